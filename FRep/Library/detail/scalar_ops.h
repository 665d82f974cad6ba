// The scalar vocabulary the generic library templates are written in. For T = double these
// are the C library functions and plain control flow; a symbolic scalar type (the compiler's
// Expr) provides the same names in its own namespace, found by argument-dependent lookup.
//
// Rules for generic code: never branch on a T value with `if`/`?:`/loops (use select and the
// logical_* helpers; keep `auto` for conditions, they are bool for double and Expr otherwise);
// branch freely on array sizes and other compile-time facts; no value-dependent loop counts.
#pragma once

#include <cmath>

namespace frep::library
{

using std::acos;
using std::asin;
using std::atan;
using std::atan2;
using std::ceil;
using std::cos;
using std::cosh;
using std::exp;
using std::fabs;
using std::floor;
using std::fmod;
using std::log;
using std::log10;
using std::pow;
using std::sin;
using std::sinh;
using std::sqrt;
using std::tan;
using std::tanh;
using std::trunc;

/// c ? a : b. Both operands are evaluated (they are pure), which is why this is only for values.
inline double select(bool c, double a, double b)
{
  return c ? a : b;
}
inline bool logical_and(bool a, bool b)
{
  return a && b;
}
inline bool logical_or(bool a, bool b)
{
  return a || b;
}
inline bool logical_not(bool a)
{
  return !a;
}

} // namespace frep::library
