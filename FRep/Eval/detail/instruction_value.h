// The value of one pure tape instruction at one point: the single definition the point, batch
// (for the lanes it does not vectorise) and gradient evaluators share, so that they cannot
// drift apart. Everything HyperFun-specific is delegated to Semantics/detail/op_semantics.h, which
// the compiler's constant folding also uses.
#pragma once

#include "Compiler/detail/op_eval.h"
#include "Semantics/detail/op_semantics.h"
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
/// a, b, c; `ins` supplies the immediate and the integer index. The semantics live in one place,
/// Compiler/detail/op_eval.h, which the compiler's constant folding uses too.
[[gnu::always_inline]] inline double apply(const Instruction& ins, double a, double b, double c)
{
  if (ins.op == Opcode::Const)
  {
    return ins.imm;
  }
  return semantics::evaluate_op(ins.op, a, b, c, ins.index);
}

} // namespace frep::eval
