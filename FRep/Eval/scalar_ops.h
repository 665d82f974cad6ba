// The value of one pure tape instruction at one point: the single definition the point, batch
// (for the lanes it does not vectorise) and gradient evaluators share, so that they cannot
// drift apart. Everything HyperFun-specific is delegated to Compiler/op_semantics.h, which
// the compiler's constant folding also uses.
#pragma once

#include "Compiler/op_semantics.h"
#include "Compiler/tape.h"

#include <cmath>

namespace frep::eval
{

/// 1.0 / 0.0 for a C++ bool (the tape's booleans).
inline double boolean(bool v)
{
  return v ? 1.0 : 0.0;
}

/// Frac: the fractional part exactly as C modf computes it (sign kept, 0 for infinities).
inline double frac(double a)
{
  double integral = 0;
  return std::modf(a, &integral);
}

/// The result of a pure opcode (everything but Input, ErrorIf and Call) on operand values
/// a, b, c; `ins` supplies the immediate and the integer index.
[[gnu::always_inline]] inline double apply(const Instruction& ins, double a, double b, double c)
{
  namespace hf = frep::semantics;
  switch (ins.op)
  {
    case Opcode::Const:
      return ins.imm;
    case Opcode::Add:
      return a + b;
    case Opcode::Sub:
      return a - b;
    case Opcode::Mul:
      return a * b;
    case Opcode::Div:
      return a / b;
    case Opcode::Neg:
      return -a;
    case Opcode::Square:
      return a * a;
    case Opcode::Abs:
      return std::fabs(a);
    case Opcode::Sqrt:
      return std::sqrt(a);
    case Opcode::Exp:
      return std::exp(a);
    case Opcode::Log:
      return std::log(a);
    case Opcode::Log10:
      return std::log10(a);
    case Opcode::Sin:
      return std::sin(a);
    case Opcode::Cos:
      return std::cos(a);
    case Opcode::Tan:
      return std::tan(a);
    case Opcode::Asin:
      return std::asin(a);
    case Opcode::Acos:
      return std::acos(a);
    case Opcode::Atan:
      return std::atan(a);
    case Opcode::Sinh:
      return std::sinh(a);
    case Opcode::Cosh:
      return std::cosh(a);
    case Opcode::Tanh:
      return std::tanh(a);
    case Opcode::Atan2:
      return std::atan2(a, b);
    case Opcode::Pow:
      return std::pow(a, b);
    case Opcode::Floor:
      return std::floor(a);
    case Opcode::Ceil:
      return std::ceil(a);
    case Opcode::Trunc:
      return std::trunc(a);
    case Opcode::Frac:
      return frac(a);
    case Opcode::Fmod:
      return std::fmod(a, b);
    case Opcode::HfPow:
      return hf::hf_pow(a, b);
    case Opcode::HfPowInt:
      return hf::hf_pow_int(a, ins.index);
    case Opcode::HfMod:
      return hf::hf_mod(a, b);
    case Opcode::HfRound:
      return static_cast<double>(hf::hf_round(a));
    case Opcode::Max:
      return hf::hf_max(a, b);
    case Opcode::Min:
      return hf::hf_min(a, b);
    case Opcode::Union:
      return hf::unite(a, b);
    case Opcode::Intersect:
      return hf::intersect(a, b);
    case Opcode::Eq:
      return boolean(std::fabs(a - b) < hf::kEps);
    case Opcode::Ne:
      return boolean(std::fabs(a - b) >= hf::kEps);
    case Opcode::Lt:
      return boolean(a < b);
    case Opcode::Le:
      return boolean(a <= b);
    case Opcode::Gt:
      return boolean(a > b);
    case Opcode::Ge:
      return boolean(a >= b);
    case Opcode::Truthy:
      return boolean(hf::truthy(a));
    case Opcode::And:
      return boolean(hf::truthy(a) && hf::truthy(b));
    case Opcode::Or:
      return boolean(hf::truthy(a) || hf::truthy(b));
    case Opcode::Not:
      return boolean(!hf::truthy(a));
    case Opcode::Select:
      return a != 0.0 ? b : c;
    case Opcode::Input:
    case Opcode::ErrorIf:
    case Opcode::Call:
      break; // not pure: handled by each evaluator
  }
  return std::nan("");
}

} // namespace frep::eval
