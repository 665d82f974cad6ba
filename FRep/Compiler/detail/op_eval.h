// The value of one pure tape opcode on doubles, exactly as the tape contract (tape.h) defines it.
// The compiler folds constants with this function, so a folded constant is the very double an
// evaluator would have computed at run time; evaluators may use it as their scalar reference.
#pragma once

#include "Semantics/detail/op_semantics.h"
#include "Compiler/tape.h"

#include <cmath>

namespace frep::semantics
{

/// Result of a pure opcode (not Const, Input, ErrorIf or Call) on operand values a, b, c;
/// `index` is the HfPowInt exponent.
[[gnu::always_inline]] inline double evaluate_op(Opcode op, double a, double b, double c, int index)
{
  switch (op)
  {
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
    {
      double integral = 0;
      return std::modf(a, &integral);
    }
    case Opcode::Fmod:
      return std::fmod(a, b);
    case Opcode::HfPow:
      return hf_pow(a, b);
    case Opcode::HfPowInt:
      return hf_pow_int(a, index);
    case Opcode::HfMod:
      return hf_mod(a, b);
    case Opcode::HfRound:
      return static_cast<double>(hf_round(a));
    case Opcode::Max:
      return hf_max(a, b);
    case Opcode::Min:
      return hf_min(a, b);
    case Opcode::Union:
      return unite(a, b);
    case Opcode::Intersect:
      return intersect(a, b);
    case Opcode::UnionPlain:
      return unite_plain(a, b);
    case Opcode::IntersectPlain:
      return intersect_plain(a, b);
    case Opcode::Eq:
      return std::fabs(a - b) < kEps ? 1.0 : 0.0;
    case Opcode::Ne:
      return std::fabs(a - b) >= kEps ? 1.0 : 0.0;
    case Opcode::Lt:
      return a < b ? 1.0 : 0.0;
    case Opcode::Le:
      return a <= b ? 1.0 : 0.0;
    case Opcode::Gt:
      return a > b ? 1.0 : 0.0;
    case Opcode::Ge:
      return a >= b ? 1.0 : 0.0;
    case Opcode::Truthy:
      return truthy(a) ? 1.0 : 0.0;
    case Opcode::And:
      return truthy(a) && truthy(b) ? 1.0 : 0.0;
    case Opcode::Or:
      return truthy(a) || truthy(b) ? 1.0 : 0.0;
    case Opcode::Not:
      return truthy(a) ? 0.0 : 1.0;
    case Opcode::Select:
      return a != 0 ? b : c;
    default:
      return 0.0; // not a pure value opcode
  }
}

} // namespace frep::semantics
