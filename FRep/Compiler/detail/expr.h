// Expr: the symbolic scalar the compiler runs HyperFun (and the generic library templates) on.
// It is either a pending double constant (so `Expr e = 2.0;` needs no DAG) or a node of a Dag.
// The free functions below are the scalar_ops.h vocabulary for Expr, found by argument-dependent
// lookup, so library::call_generic<Expr, ...> expands a library call into DAG nodes. Operations
// on two constants are computed at once with the evaluators' double code (bit-exact folding).
// Conditions are Exprs too, valued 1.0 / 0.0.
#pragma once

#include "Compiler/detail/dag.h"
#include "Compiler/detail/op_eval.h"

namespace frep::compiler
{

class Expr
{
public:
  Expr(double value = 0.0) // NOLINT: implicit on purpose (generic code writes T(0.0), 2.0 * x)
    : value_(value)
  {
  }
  Expr(Dag* dag, NodeId id)
    : dag_(dag)
    , id_(id)
  {
    if (dag_->is_constant(id_))
    {
      value_ = dag_->constant_value(id_);
      dag_ = nullptr;
    }
  }

  bool is_constant() const { return dag_ == nullptr; }
  double constant() const { return value_; }
  Dag* dag() const { return dag_; }
  /// The node of this value in `dag` (constants are interned on demand).
  NodeId node(Dag& dag) const { return dag_ ? id_ : dag.constant(value_); }

private:
  Dag* dag_ = nullptr;
  NodeId id_ = 0;
  double value_ = 0.0;
};

namespace detail
{
inline Dag* dag_of(const Expr& a, const Expr& b, const Expr& c = Expr())
{
  return a.dag() ? a.dag() : (b.dag() ? b.dag() : c.dag());
}
} // namespace detail

inline Expr apply(Opcode op, const Expr& a)
{
  if (a.is_constant())
  {
    return Expr(semantics::evaluate_op(op, a.constant(), 0.0, 0.0, 0));
  }
  Dag* d = a.dag();
  return Expr(d, d->unary(op, a.node(*d)));
}

inline Expr apply(Opcode op, const Expr& a, const Expr& b)
{
  Dag* d = detail::dag_of(a, b);
  if (!d)
  {
    return Expr(semantics::evaluate_op(op, a.constant(), b.constant(), 0.0, 0));
  }
  return Expr(d, d->binary(op, a.node(*d), b.node(*d)));
}

inline Expr select(const Expr& c, const Expr& a, const Expr& b)
{
  if (c.is_constant())
  {
    return c.constant() != 0 ? a : b;
  }
  Dag* d = c.dag();
  return Expr(d, d->select(c.node(*d), a.node(*d), b.node(*d)));
}

inline Expr pow_int(const Expr& base, int n)
{
  if (base.is_constant())
  {
    return Expr(semantics::hf_pow_int(base.constant(), n));
  }
  Dag* d = base.dag();
  return Expr(d, d->pow_int(base.node(*d), n));
}

// Arithmetic (mixed double/Expr through the implicit conversion).
inline Expr operator+(const Expr& a, const Expr& b)
{
  return apply(Opcode::Add, a, b);
}
inline Expr operator-(const Expr& a, const Expr& b)
{
  return apply(Opcode::Sub, a, b);
}
inline Expr operator*(const Expr& a, const Expr& b)
{
  return apply(Opcode::Mul, a, b);
}
inline Expr operator/(const Expr& a, const Expr& b)
{
  return apply(Opcode::Div, a, b);
}
inline Expr operator-(const Expr& a)
{
  return apply(Opcode::Neg, a);
}
inline Expr operator+(const Expr& a)
{
  return a;
}
inline Expr& operator+=(Expr& a, const Expr& b)
{
  return a = a + b;
}
inline Expr& operator-=(Expr& a, const Expr& b)
{
  return a = a - b;
}
inline Expr& operator*=(Expr& a, const Expr& b)
{
  return a = a * b;
}
inline Expr& operator/=(Expr& a, const Expr& b)
{
  return a = a / b;
}

// C library (no domain checks, like the C functions in generic library code).
inline Expr sqrt(const Expr& a)
{
  return apply(Opcode::Sqrt, a);
}
inline Expr exp(const Expr& a)
{
  return apply(Opcode::Exp, a);
}
inline Expr log(const Expr& a)
{
  return apply(Opcode::Log, a);
}
inline Expr log10(const Expr& a)
{
  return apply(Opcode::Log10, a);
}
inline Expr sin(const Expr& a)
{
  return apply(Opcode::Sin, a);
}
inline Expr cos(const Expr& a)
{
  return apply(Opcode::Cos, a);
}
inline Expr tan(const Expr& a)
{
  return apply(Opcode::Tan, a);
}
inline Expr asin(const Expr& a)
{
  return apply(Opcode::Asin, a);
}
inline Expr acos(const Expr& a)
{
  return apply(Opcode::Acos, a);
}
inline Expr atan(const Expr& a)
{
  return apply(Opcode::Atan, a);
}
inline Expr sinh(const Expr& a)
{
  return apply(Opcode::Sinh, a);
}
inline Expr cosh(const Expr& a)
{
  return apply(Opcode::Cosh, a);
}
inline Expr tanh(const Expr& a)
{
  return apply(Opcode::Tanh, a);
}
inline Expr fabs(const Expr& a)
{
  return apply(Opcode::Abs, a);
}
inline Expr floor(const Expr& a)
{
  return apply(Opcode::Floor, a);
}
inline Expr ceil(const Expr& a)
{
  return apply(Opcode::Ceil, a);
}
inline Expr trunc(const Expr& a)
{
  return apply(Opcode::Trunc, a);
}
inline Expr atan2(const Expr& a, const Expr& b)
{
  return apply(Opcode::Atan2, a, b);
}
inline Expr pow(const Expr& a, const Expr& b)
{
  return apply(Opcode::Pow, a, b);
}
inline Expr fmod(const Expr& a, const Expr& b)
{
  return apply(Opcode::Fmod, a, b);
}

// Conditions. == and != are EXACT here (C semantics of generic code); HyperFun's tolerant
// `=` / `/=` are the Eq / Ne opcodes, which the lowering uses directly.
inline Expr operator<(const Expr& a, const Expr& b)
{
  return apply(Opcode::Lt, a, b);
}
inline Expr operator<=(const Expr& a, const Expr& b)
{
  return apply(Opcode::Le, a, b);
}
inline Expr operator>(const Expr& a, const Expr& b)
{
  return apply(Opcode::Gt, a, b);
}
inline Expr operator>=(const Expr& a, const Expr& b)
{
  return apply(Opcode::Ge, a, b);
}
inline Expr logical_and(const Expr& a, const Expr& b)
{
  return apply(Opcode::And, a, b);
}
inline Expr logical_or(const Expr& a, const Expr& b)
{
  return apply(Opcode::Or, a, b);
}
inline Expr logical_not(const Expr& a)
{
  return apply(Opcode::Not, a);
}
inline Expr operator==(const Expr& a, const Expr& b)
{
  return logical_and(a <= b, a >= b); // false for NaN, true for -0 == +0, as in C
}
inline Expr operator!=(const Expr& a, const Expr& b)
{
  return logical_not(a == b);
}

} // namespace frep::compiler
