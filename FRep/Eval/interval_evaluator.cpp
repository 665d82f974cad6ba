// Interval rules. Every slot carries an enclosure of its non-NaN values over the box and a flag
// saying it may be NaN somewhere; a NaN-capable output is reported as the whole line.
//
// Soundness is about the values the point evaluator computes, not the real functions:
// - correctly rounded operations (+ - * / sqrt) are monotone after rounding, so rounded
//   endpoint values already enclose; one ulp outward is kept as a margin;
// - libm functions are only accurate to an ulp or two and need not be monotone after
//   rounding, so their endpoint values are widened by a few ulps relative to the value;
// - formulas with cancellation (the R-functions) get an absolute margin scaled by the operand
//   magnitudes (see r_function()).
#include "Eval/interval_evaluator.h"

#include "Eval/detail/batch_program.h"
#include "Semantics/detail/op_semantics.h"
#include "Compiler/detail/tape_check.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace frep
{

namespace
{

namespace hf = frep::semantics;

// The rules of the common operations are inlined into the evaluation loop: called, each returned
// its Range through memory and the loop waited on it (19 -> 11 ns per instruction on Prospero's
// tape, Benchmarks/frep_interval_benchmark).
#define HOT_RULE [[gnu::always_inline]] inline

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;

/// An enclosure of the non-NaN values of a slot plus whether NaN is possible.
struct Range
{
  Interval v;
  bool nan = false;
};

/// std::nextafter(x, +inf) without the library call (it was 6% of meshing a long tape): the next
/// double up is one unit more in the bit pattern for positives, one less for negatives.
HOT_RULE double up(double x)
{
  if (!(x < kInf))
  {
    return x; // +inf, NaN
  }
  if (x == 0.0)
  {
    return std::numeric_limits<double>::denorm_min();
  }
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0.0 ? bits + 1 : bits - 1);
}
HOT_RULE double down(double x)
{
  return -up(-x);
}

HOT_RULE Range whole(bool nan = true)
{
  return { Interval::everything(), nan };
}

HOT_RULE bool has_inf(const Interval& i)
{
  return std::isinf(i.lo) || std::isinf(i.hi);
}
HOT_RULE bool has_zero(const Interval& i)
{
  return i.lo <= 0 && 0 <= i.hi;
}

/// [lo, hi] of a correctly rounded operation, one ulp outward; NaN bounds mean "unknown".
HOT_RULE Range rounded(double lo, double hi, bool nan)
{
  if (std::isnan(lo) || std::isnan(hi))
  {
    return whole(true);
  }
  // An endpoint that is exactly zero stays zero: the operations rounded here are correctly
  // rounded and monotone, so the computed endpoint already bounds every computed value, and the
  // ulp of margin would otherwise make a sum of squares possibly negative (sqrt(x^2 + y^2) over
  // a box touching an axis became the whole line, and frep::mesh::find_solid_bounds found
  // hfTorusZ unbounded).
  return { { lo == 0.0 ? lo : down(lo), hi == 0.0 ? hi : up(hi) }, nan };
}

/// [lo, hi] of a libm result: relative margin of 4 DBL_EPSILON (several ulps) plus one ulp.
double libm_down(double x)
{
  return std::isinf(x) ? x : down(x - std::fabs(x) * 4 * DBL_EPSILON);
}
double libm_up(double x)
{
  return std::isinf(x) ? x : up(x + std::fabs(x) * 4 * DBL_EPSILON);
}
Range libm(double lo, double hi, bool nan)
{
  if (std::isnan(lo) || std::isnan(hi))
  {
    return whole(true);
  }
  return { { libm_down(lo), libm_up(hi) }, nan };
}

Range exact(double lo, double hi, bool nan)
{
  if (std::isnan(lo) || std::isnan(hi))
  {
    return whole(true);
  }
  return { { lo, hi }, nan };
}

HOT_RULE Range hull(const Range& a, const Range& b)
{
  return { { std::min(a.v.lo, b.v.lo), std::max(a.v.hi, b.v.hi) }, a.nan || b.nan };
}

Range clamp(Range r, double lo, double hi)
{
  r.v.lo = std::clamp(r.v.lo, lo, hi);
  r.v.hi = std::clamp(r.v.hi, lo, hi);
  return r;
}

/// Min and max of the non-NaN values among candidates (corners of a monotone/bilinear op).
template<std::size_t N>
HOT_RULE Range corners(const double (&c)[N], bool nan, bool libm_margin)
{
  double lo = kInf;
  double hi = -kInf;
  bool any = false;
  for (double v : c)
  {
    if (std::isnan(v))
    {
      nan = true;
      continue;
    }
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    any = true;
  }
  if (!any)
  {
    return whole(true);
  }
  return libm_margin ? libm(lo, hi, nan) : rounded(lo, hi, nan);
}

HOT_RULE Range add(const Range& a, const Range& b)
{
  const bool nan =
    a.nan || b.nan || (a.v.hi == kInf && b.v.lo == -kInf) || (a.v.lo == -kInf && b.v.hi == kInf);
  return rounded(a.v.lo + b.v.lo, a.v.hi + b.v.hi, nan);
}

HOT_RULE Range sub(const Range& a, const Range& b)
{
  const bool nan =
    a.nan || b.nan || (a.v.hi == kInf && b.v.hi == kInf) || (a.v.lo == -kInf && b.v.lo == -kInf);
  return rounded(a.v.lo - b.v.hi, a.v.hi - b.v.lo, nan);
}

HOT_RULE Range mul(const Range& a, const Range& b)
{
  const bool nan =
    a.nan || b.nan || (has_zero(a.v) && has_inf(b.v)) || (has_zero(b.v) && has_inf(a.v));
  const double c[] = { a.v.lo * b.v.lo, a.v.lo * b.v.hi, a.v.hi * b.v.lo, a.v.hi * b.v.hi };
  return corners(c, nan, false);
}

Range div(const Range& a, const Range& b)
{
  if (has_zero(b.v))
  {
    // x/±0 is ±inf (by the zero's sign) and 0/0 is NaN: nothing useful remains.
    return whole(a.nan || b.nan || has_zero(a.v) || (has_inf(a.v) && has_inf(b.v)));
  }
  const bool nan = a.nan || b.nan || (has_inf(a.v) && has_inf(b.v));
  const double c[] = { a.v.lo / b.v.lo, a.v.lo / b.v.hi, a.v.hi / b.v.lo, a.v.hi / b.v.hi };
  return corners(c, nan, false);
}

HOT_RULE Range square(const Range& a)
{
  const double l = a.v.lo * a.v.lo;
  const double h = a.v.hi * a.v.hi;
  if (has_zero(a.v))
  {
    return { { 0.0, up(std::max(l, h)) }, a.nan };
  }
  return rounded(std::min(l, h), std::max(l, h), a.nan);
}

Range absolute(const Range& a)
{
  if (has_zero(a.v))
  {
    return { { 0.0, std::max(-a.v.lo, a.v.hi) }, a.nan };
  }
  const double l = std::fabs(a.v.lo);
  const double h = std::fabs(a.v.hi);
  return { { std::min(l, h), std::max(l, h) }, a.nan };
}

/// An increasing libm function on [lo, hi] ∩ [dom_lo, dom_hi]; outside the domain is NaN.
template<class F>
Range increasing(const Range& a, F f, double dom_lo = -kInf, double dom_hi = kInf)
{
  const bool outside = a.v.lo < dom_lo || a.v.hi > dom_hi;
  const double lo = std::max(a.v.lo, dom_lo);
  const double hi = std::min(a.v.hi, dom_hi);
  if (lo > hi)
  {
    return whole(true);
  }
  return libm(f(lo), f(hi), a.nan || outside);
}

template<class F>
Range decreasing(const Range& a, F f, double dom_lo = -kInf, double dom_hi = kInf)
{
  const bool outside = a.v.lo < dom_lo || a.v.hi > dom_hi;
  const double lo = std::max(a.v.lo, dom_lo);
  const double hi = std::min(a.v.hi, dom_hi);
  if (lo > hi)
  {
    return whole(true);
  }
  return libm(f(hi), f(lo), a.nan || outside);
}

/// Whether some offset + k * period lies in [lo, hi] (k integer), erring towards "yes": the
/// quotients carry rounding errors, and a false "yes" only loosens the bound.
bool may_contain_periodic(double lo, double hi, double offset, double period)
{
  const double t_lo = (lo - offset) / period;
  const double t_hi = (hi - offset) / period;
  const double slack_lo = 1e-9 * (1 + std::fabs(t_lo));
  const double slack_hi = 1e-9 * (1 + std::fabs(t_hi));
  return std::floor(t_hi + slack_hi) >= t_lo - slack_lo;
}

// Beyond this magnitude the argument reduction of our extremum test is not trusted.
constexpr double kTrigLimit = 1e8;

/// sin or cos: monotone between extrema; the extrema are where the derivative vanishes.
template<class F>
Range trig(const Range& a, F f, double max_at, double min_at)
{
  if (has_inf(a.v))
  {
    return { { -1, 1 }, true }; // sin(±inf) is NaN
  }
  if (a.v.hi - a.v.lo >= 2 * kPi || std::fabs(a.v.lo) > kTrigLimit ||
      std::fabs(a.v.hi) > kTrigLimit)
  {
    return { { -1, 1 }, a.nan };
  }
  const double fl = f(a.v.lo);
  const double fh = f(a.v.hi);
  Range r = libm(std::min(fl, fh), std::max(fl, fh), a.nan);
  if (may_contain_periodic(a.v.lo, a.v.hi, max_at, 2 * kPi))
  {
    r.v.hi = 1;
  }
  if (may_contain_periodic(a.v.lo, a.v.hi, min_at, 2 * kPi))
  {
    r.v.lo = -1;
  }
  return clamp(r, -1, 1);
}

Range tangent(const Range& a)
{
  if (has_inf(a.v))
  {
    return whole(true);
  }
  if (a.v.hi - a.v.lo >= kPi || std::fabs(a.v.lo) > kTrigLimit || std::fabs(a.v.hi) > kTrigLimit ||
      may_contain_periodic(a.v.lo, a.v.hi, kPi / 2, kPi))
  {
    return whole(a.nan);
  }
  return libm(std::tan(a.v.lo), std::tan(a.v.hi), a.nan);
}

Range hyperbolic_cosine(const Range& a)
{
  const double l = std::cosh(a.v.lo);
  const double h = std::cosh(a.v.hi);
  Range r =
    has_zero(a.v) ? libm(1, std::max(l, h), a.nan) : libm(std::min(l, h), std::max(l, h), a.nan);
  r.v.lo = std::max(r.v.lo, 1.0);
  return r;
}

/// Rounding ops (floor, ceil, trunc) are exact and non-decreasing.
template<class F>
Range step(const Range& a, F f)
{
  return exact(f(a.v.lo), f(a.v.hi), a.nan);
}

Range fractional(const Range& a)
{
  const Interval& v = a.v;
  if (v.lo >= 0 && std::isfinite(v.hi) && std::floor(v.lo) == std::floor(v.hi))
  {
    const double k = std::floor(v.lo); // x - k is exact for x in [k, k+1)
    return { { v.lo - k, v.hi - k }, a.nan };
  }
  if (v.hi <= 0 && std::isfinite(v.lo) && std::ceil(v.lo) == std::ceil(v.hi))
  {
    const double k = std::ceil(v.hi);
    return { { v.lo - k, v.hi - k }, a.nan };
  }
  return { { v.lo >= 0 ? 0.0 : -1.0, v.hi <= 0 ? 0.0 : 1.0 }, a.nan };
}

/// fmod(a, b): NaN for b = 0 or infinite a; |r| <= |a|, |r| < |b|, sign of a; exact.
Range remainder(const Range& a, const Range& b)
{
  const bool nan = a.nan || b.nan || has_zero(b.v) || has_inf(a.v);
  const double b_max = std::max(std::fabs(b.v.lo), std::fabs(b.v.hi));
  const double b_min = has_zero(b.v) ? 0.0 : std::min(std::fabs(b.v.lo), std::fabs(b.v.hi));
  const double a_max = std::max(std::fabs(a.v.lo), std::fabs(a.v.hi));
  if (a_max < b_min)
  {
    return { a.v, nan }; // fmod(x, y) = x exactly when |x| < |y|
  }
  const double lo = a.v.lo >= 0 ? 0.0 : -std::min(-a.v.lo, b_max);
  const double hi = a.v.hi <= 0 ? 0.0 : std::min(a.v.hi, b_max);
  return { { lo, hi }, nan };
}

/// HF_round as a double: non-decreasing within the int range; NaN and out-of-range values
/// give INT_MIN (never NaN).
Range hf_round_range(const Range& a)
{
  const double int_min = static_cast<double>(INT_MIN);
  const double int_max = static_cast<double>(INT_MAX);
  Range r;
  if (a.v.lo >= int_min && a.v.hi < 2147483648.0)
  {
    r = { { static_cast<double>(hf::hf_round(a.v.lo)), static_cast<double>(hf::hf_round(a.v.hi)) },
      false };
  }
  else
  {
    r = { { int_min, int_max }, false };
  }
  if (a.nan)
  {
    r.v.lo = int_min;
  }
  return r;
}

/// hf_pow_int(a, n) (also hf_pow's integral branch). |a| < EPS gives 0; elsewhere repeated
/// multiplication is, after rounding, monotone in |a| with a sign of a^n, so the exact values
/// at the ends of each sign part enclose it with no margin.
Range pow_int(const Range& a, int n, bool negative)
{
  const auto f = [&](double x) { return hf::hf_pow_repeated(x, n, negative); };
  Range r{ { kInf, -kInf }, false };
  bool any = false;
  const auto include = [&](double x, double y)
  {
    const double fx = f(x);
    const double fy = f(y);
    if (std::isnan(fx) || std::isnan(fy))
    {
      r.nan = true;
      return;
    }
    r.v.lo = std::min({ r.v.lo, fx, fy });
    r.v.hi = std::max({ r.v.hi, fx, fy });
    any = true;
  };
  if (a.v.lo <= -hf::kEps)
  {
    include(a.v.lo, std::min(a.v.hi, -hf::kEps));
  }
  if (a.v.hi >= hf::kEps)
  {
    include(std::max(a.v.lo, hf::kEps), a.v.hi);
  }
  if (a.v.lo < hf::kEps && a.v.hi > -hf::kEps)
  {
    r.v.lo = std::min(r.v.lo, 0.0);
    r.v.hi = std::max(r.v.hi, 0.0);
    any = true;
  }
  if (a.nan)
  {
    // NaN ^ 0 is 1.0 (the loop runs zero times); otherwise NaN stays NaN.
    if (n == 0)
    {
      r.v.lo = std::min(r.v.lo, 1.0);
      r.v.hi = std::max(r.v.hi, 1.0);
      any = true;
    }
    else
    {
      r.nan = true;
    }
  }
  if (!any)
  {
    return whole(true);
  }
  return r;
}

Range hf_pow_int_op(const Range& a, int n)
{
  return pow_int(a, n < 0 ? -n : n, n < 0);
}

/// hf_pow(a, b), the value part. Tight for a constant exponent and for bases >= EPS.
Range hf_pow_range(const Range& a, const Range& b)
{
  if (b.nan || has_inf(b.v))
  {
    return whole(true);
  }
  if (b.v.lo == b.v.hi)
  {
    const double e = b.v.lo;
    if ((e - std::floor(e)) < hf::kEps)
    {
      return pow_int(a, hf::hf_round(std::fabs(e)), e < 0.0);
    }
    // exp(e * log(a)): monotone in a >= EPS; NaN for a <= -EPS; 0 for |a| < EPS.
    Range r{ { kInf, -kInf }, a.nan || a.v.lo <= -hf::kEps };
    bool any = false;
    if (a.v.lo < hf::kEps && a.v.hi > -hf::kEps)
    {
      r.v = { 0.0, 0.0 };
      any = true;
    }
    if (a.v.hi >= hf::kEps)
    {
      const double lo = std::max(a.v.lo, hf::kEps);
      const double y1 = e * std::log(lo);
      const double y2 = e * std::log(a.v.hi);
      const double f1 = std::exp(y1);
      const double f2 = std::exp(y2);
      if (std::isnan(f1) || std::isnan(f2))
      {
        return whole(true);
      }
      // exp amplifies the rounding error of its argument by |y| (an infinite y gives an exact
      // 0 or inf, which needs no margin).
      const auto finite_abs = [](double y) { return std::isfinite(y) ? std::fabs(y) : 0.0; };
      const double rel = (std::max(finite_abs(y1), finite_abs(y2)) * 2 + 8) * DBL_EPSILON;
      const auto widen = [&](double f, double sign)
      { return (f == 0 || std::isinf(f)) ? f : f * (1 + sign * rel); };
      r.v.lo = std::min(r.v.lo, widen(std::min(f1, f2), -1));
      r.v.hi = std::max(r.v.hi, widen(std::max(f1, f2), 1));
      r.v = { down(r.v.lo), up(r.v.hi) };
      any = true;
    }
    return any ? r : whole(true);
  }
  if (a.nan || a.v.lo < hf::kEps || has_inf(a.v))
  {
    return whole(true);
  }
  // Positive base, varying exponent: the value is a^e' with e' in [b.lo - EPS, b.hi] (the
  // integral branch uses floor(e) >= e - EPS), bilinear in (e', log a): extrema at corners.
  const double e_lo = b.v.lo - hf::kEps;
  const double c[] = { std::pow(a.v.lo, e_lo),
    std::pow(a.v.lo, b.v.hi),
    std::pow(a.v.hi, e_lo),
    std::pow(a.v.hi, b.v.hi) };
  const double y_max = std::max(std::fabs(b.v.lo) + 1, std::fabs(b.v.hi)) *
                       std::max(std::fabs(std::log(a.v.lo)), std::fabs(std::log(a.v.hi)));
  const double n_max = std::max(std::fabs(b.v.lo), std::fabs(b.v.hi)) + 1;
  const double rel = (2 * y_max + n_max + 8) * DBL_EPSILON;
  Range r = corners(c, false, true);
  if (r.nan || !std::isfinite(rel))
  {
    return whole(true);
  }
  // An overflowing corner is inf: widen only finite bounds (inf - inf*rel would be NaN), and
  // let an infinite lower bound come down to the largest double (values near it round to inf).
  r.v.lo = std::isfinite(r.v.lo) ? down(r.v.lo - std::fabs(r.v.lo) * rel)
                                 : std::min(r.v.lo, std::numeric_limits<double>::max());
  r.v.hi = std::isfinite(r.v.hi) ? up(r.v.hi + std::fabs(r.v.hi) * rel) : r.v.hi;
  r.v.lo = std::max(r.v.lo, 0.0);
  return r;
}

/// C pow: tight only for a positive finite base and a finite exponent (corners of the
/// bilinear b * log a); anything else may be NaN or change sign.
Range c_pow(const Range& a, const Range& b)
{
  if (a.nan || b.nan || !(a.v.lo > 0) || has_inf(a.v) || has_inf(b.v))
  {
    return whole(true);
  }
  const double c[] = { std::pow(a.v.lo, b.v.lo),
    std::pow(a.v.lo, b.v.hi),
    std::pow(a.v.hi, b.v.lo),
    std::pow(a.v.hi, b.v.hi) };
  Range r = corners(c, false, true);
  r.v.lo = std::max(r.v.lo, 0.0);
  return r;
}

/// max/min as (a > b) ? a : b and (a < b) ? a : b: a NaN operand a yields b, a NaN b yields NaN.
HOT_RULE Range max_min(const Range& a, const Range& b, bool is_max)
{
  Range r = is_max ? Range{ { std::max(a.v.lo, b.v.lo), std::max(a.v.hi, b.v.hi) }, false }
                   : Range{ { std::min(a.v.lo, b.v.lo), std::min(a.v.hi, b.v.hi) }, false };
  if (a.nan)
  {
    r = hull(r, Range{ b.v, false });
  }
  r.nan = b.nan;
  return r;
}

/// Union / Intersect: l + r ± sqrt(l² + r²) is non-decreasing in each argument, so the values
/// at the interval ends enclose it. Rounding can break exact monotonicity by a few ulps of
/// the operands' magnitude (cancellation), so the margin is absolute: 8 DBL_EPSILON (|l|+|r|),
/// plus 2^-500 for squares that underflow. Huge operands overflow l² (and infinite ones give
/// NaN through the 0*r*l term), so they get no rule.
template<bool is_union, bool plain>
HOT_RULE Range r_function(const Range& a, const Range& b)
{
  const double kHuge = 0x1p500;
  const double m =
    std::max(std::fabs(a.v.lo), std::fabs(a.v.hi)) + std::max(std::fabs(b.v.lo), std::fabs(b.v.hi));
  if (!(m < kHuge))
  {
    return whole(true);
  }
  // The plain forms (hfBlendUni/Int's) are the same functions for finite operands, the only
  // ones that get this rule.
  // (Chosen at compile time: through a function pointer the rules were calls, a tenth of
  // ray casting the Homotopic Fun model.)
  const auto f = [](double l, double r)
  {
    if constexpr (plain)
    {
      return is_union ? hf::unite_plain(l, r) : hf::intersect_plain(l, r);
    }
    else
    {
      return is_union ? hf::unite(l, r) : hf::intersect(l, r);
    }
  };
  const double pad = 8 * DBL_EPSILON * m + 0x1p-500;
  return { { down(f(a.v.lo, b.v.lo) - pad), up(f(a.v.hi, b.v.hi) + pad) }, a.nan || b.nan };
}

HOT_RULE Range boolean(bool can_true, bool can_false)
{
  return { { can_true && !can_false ? 1.0 : 0.0, can_false && !can_true ? 0.0 : 1.0 }, false };
}

bool may_be_truthy(const Range& a)
{
  return a.v.hi >= hf::kEps || a.v.lo <= -hf::kEps;
}
bool may_be_falsy(const Range& a)
{
  return a.nan || (a.v.lo < hf::kEps && a.v.hi > -hf::kEps);
}
bool may_be_nonzero(const Range& a)
{
  return a.nan || a.v.lo < 0 || a.v.hi > 0;
}
bool may_be_zero(const Range& a)
{
  return a.v.lo <= 0 && a.v.hi >= 0;
}

// Choices (tape_simplifier.h). The interval of a slot encloses the values the point evaluator
// computes, so a comparison decided on the ranges is decided at every point. With a NaN a, a > b
// and a < b are false (the result is b); with a NaN b they are false too (the result is b, NaN).

/// max(a, b) = (a > b) ? a : b
HOT_RULE Choice max_choice(const Range& a, const Range& b)
{
  if (a.v.hi <= b.v.lo)
  {
    return Choice::TakeB; // a > b is false for every non-NaN a, and for NaN a or b
  }
  if (!a.nan && !b.nan && a.v.lo > b.v.hi)
  {
    return Choice::TakeA;
  }
  return Choice::Keep;
}

/// min(a, b) = (a < b) ? a : b
HOT_RULE Choice min_choice(const Range& a, const Range& b)
{
  if (a.v.lo >= b.v.hi)
  {
    return Choice::TakeB;
  }
  if (!a.nan && !b.nan && a.v.hi < b.v.lo)
  {
    return Choice::TakeA;
  }
  return Choice::Keep;
}

/// The enclosure of a logical operation's result on truth values (0 or 1 where decided).
HOT_RULE Range enclose_logic(Opcode op, const Range& a, const Range& b)
{
  switch (op)
  {
    case Opcode::Truthy:
      return boolean(may_be_truthy(a), may_be_falsy(a));
    case Opcode::Not:
      return boolean(may_be_falsy(a), may_be_truthy(a));
    case Opcode::And:
      return boolean(may_be_truthy(a) && may_be_truthy(b), may_be_falsy(a) || may_be_falsy(b));
    case Opcode::Or:
      return boolean(may_be_truthy(a) || may_be_truthy(b), may_be_falsy(a) && may_be_falsy(b));
    default:
      return whole(true); // not a logical operation: never called so
  }
}

/// The enclosure of a C or HyperFun library function's result (exp .. tanh, atan2, pow, the
/// rounding functions, the hf* operators).
HOT_RULE Range enclose_library(const Instruction& ins, const Range& a, const Range& b)
{
  Range r;
  switch (ins.op)
  {
    case Opcode::Exp:
      r = increasing(a, [](double x) { return std::exp(x); });
      r.v.lo = std::max(r.v.lo, 0.0);
      return r;
    case Opcode::Log:
      return increasing(a, [](double x) { return std::log(x); }, 0.0);
    case Opcode::Log10:
      return increasing(a, [](double x) { return std::log10(x); }, 0.0);
    case Opcode::Sin:
      return trig(a, [](double x) { return std::sin(x); }, kPi / 2, -kPi / 2);
    case Opcode::Cos:
      return trig(a, [](double x) { return std::cos(x); }, 0.0, kPi);
    case Opcode::Tan:
      return tangent(a);
    case Opcode::Asin:
      return increasing(a, [](double x) { return std::asin(x); }, -1.0, 1.0);
    case Opcode::Acos:
      r = decreasing(a, [](double x) { return std::acos(x); }, -1.0, 1.0);
      r.v.lo = std::max(r.v.lo, 0.0);
      return r;
    case Opcode::Atan:
      return increasing(a, [](double x) { return std::atan(x); });
    case Opcode::Sinh:
      return increasing(a, [](double x) { return std::sinh(x); });
    case Opcode::Cosh:
      return hyperbolic_cosine(a);
    case Opcode::Tanh:
      return clamp(increasing(a, [](double x) { return std::tanh(x); }), -1, 1);
    case Opcode::Atan2:
      return { { down(-kPi), up(kPi) }, a.nan || b.nan };
    case Opcode::Pow:
      return c_pow(a, b);
    case Opcode::Floor:
      return step(a, [](double x) { return std::floor(x); });
    case Opcode::Ceil:
      return step(a, [](double x) { return std::ceil(x); });
    case Opcode::Trunc:
      return step(a, [](double x) { return std::trunc(x); });
    case Opcode::Frac:
      return fractional(a);
    case Opcode::Fmod:
      return remainder(a, b);
    case Opcode::HfPow:
      return hf_pow_range(a, b);
    case Opcode::HfPowInt:
      return hf_pow_int_op(a, ins.index);
    case Opcode::HfMod:
      return remainder(hf_round_range(a), hf_round_range(b));
    case Opcode::HfRound:
      return hf_round_range(a);
    default:
      return whole(true); // not a library function: never called so
  }
}

/// The enclosure `r` of one instruction's result from its operands' (`get` reads Select's
/// third), and what the box decides for max, min and Select (`choice`, when not null; the
/// simplifier's, tape_simplifier.h). Input, ErrorIf and Call are the evaluation loop's own.
/// Inlined (HOT_RULE), with the common operations in this one switch: written in the loop, as
/// before, it measured the same (Benchmarks/README.md, "Long functions split").
template<class Get>
HOT_RULE void enclose_operation(const Instruction& ins, const Range& a, const Range& b,
  const Get& get, Choice* choice, Range& r)
{
  switch (ins.op)
  {
    case Opcode::Const:
      r = std::isnan(ins.imm) ? whole(true) : Range{ Interval::point(ins.imm), false };
      break;
    case Opcode::Add:
      r = add(a, b);
      break;
    case Opcode::Sub:
      r = sub(a, b);
      break;
    case Opcode::Mul:
      r = mul(a, b);
      break;
    case Opcode::Div:
      r = div(a, b);
      break;
    case Opcode::Neg:
      r = { { -a.v.hi, -a.v.lo }, a.nan };
      break;
    case Opcode::Square:
      r = square(a);
      break;
    case Opcode::Abs:
      r = absolute(a);
      break;
    case Opcode::Sqrt:
      if (a.v.hi < 0)
      {
        r = whole(true);
        break;
      }
      r = rounded(std::sqrt(std::max(a.v.lo, 0.0)), std::sqrt(a.v.hi), a.nan || a.v.lo < 0);
      r.v.lo = std::max(r.v.lo, 0.0);
      break;
    case Opcode::Max:
      r = max_min(a, b, true);
      if (choice)
      {
        *choice = max_choice(a, b);
      }
      break;
    case Opcode::Min:
      r = max_min(a, b, false);
      if (choice)
      {
        *choice = min_choice(a, b);
      }
      break;
    case Opcode::Union:
      r = r_function<true, false>(a, b);
      break;
    case Opcode::Intersect:
      r = r_function<false, false>(a, b);
      break;
    case Opcode::UnionPlain:
      r = r_function<true, true>(a, b);
      break;
    case Opcode::IntersectPlain:
      r = r_function<false, true>(a, b);
      break;
    case Opcode::Eq:
    case Opcode::Ne:
    {
      // The point computes fabs(a - b): enclose the rounded difference, then decide.
      const Range d = sub(a, b);
      // NaN differences make both |d| < EPS and |d| >= EPS false.
      const bool small = d.v.lo < hf::kEps && d.v.hi > -hf::kEps;
      const bool large = d.v.hi >= hf::kEps || d.v.lo <= -hf::kEps;
      r = ins.op == Opcode::Eq ? boolean(small, large || d.nan) : boolean(large, small || d.nan);
      break;
    }
    case Opcode::Lt:
      r = boolean(a.v.lo < b.v.hi, a.nan || b.nan || a.v.hi >= b.v.lo);
      break;
    case Opcode::Le:
      r = boolean(a.v.lo <= b.v.hi, a.nan || b.nan || a.v.hi > b.v.lo);
      break;
    case Opcode::Gt:
      r = boolean(a.v.hi > b.v.lo, a.nan || b.nan || a.v.lo <= b.v.hi);
      break;
    case Opcode::Ge:
      r = boolean(a.v.hi >= b.v.lo, a.nan || b.nan || a.v.lo < b.v.hi);
      break;
    case Opcode::Truthy:
    case Opcode::Not:
    case Opcode::And:
    case Opcode::Or:
      r = enclose_logic(ins.op, a, b);
      break;
    case Opcode::Select:
    {
      const Range c = get(ins.c);
      const bool take_b = may_be_nonzero(a);
      const bool take_c = may_be_zero(a);
      r = take_b && take_c ? hull(b, c) : (take_b ? b : c);
      if (choice && take_b != take_c)
      {
        *choice = take_b ? Choice::TakeB : Choice::TakeC;
      }
      break;
    }
    case Opcode::Input:
    case Opcode::ErrorIf:
    case Opcode::Call:
      break; // the loop's own
    default:
      r = enclose_library(ins, a, b);
      break;
  }
}

/// An opaque call with an enclosure form of its own (a user function's): its outputs over the
/// box of its inputs' ranges. False (the caller takes the whole line) when it has none, or an
/// input may be NaN (what the function makes of NaN is unknown).
template<class Get, class Put>
bool enclose_call(const CallSite& site, const Get& get, const Put& put, bool& may_fail)
{
  constexpr std::size_t kMax = 64;
  const std::size_t n_in = site.inputs.size();
  const std::size_t n_out = site.outputs.size();
  if (n_in > kMax || n_out > kMax)
  {
    return false;
  }
  std::array<double, kMax> lo{};
  std::array<double, kMax> hi{};
  for (std::size_t k = 0; k < n_in; ++k)
  {
    const Range r = get(site.inputs[k]);
    if (r.nan)
    {
      return false;
    }
    lo[k] = r.v.lo;
    hi[k] = r.v.hi;
  }
  std::array<double, kMax> out_lo{};
  std::array<double, kMax> out_hi{};
  bool fails = false;
  if (!site.function->enclose(std::span<const double>(lo.data(), n_in),
        std::span<const double>(hi.data(), n_in), std::span<double>(out_lo.data(), n_out),
        std::span<double>(out_hi.data(), n_out), fails))
  {
    return false;
  }
  for (std::size_t j = 0; j < n_out; ++j)
  {
    put(site.outputs[j], Range{ Interval{ out_lo[j], out_hi[j] }, false });
  }
  may_fail = may_fail || fails;
  return true;
}

} // namespace

IntervalEvaluator::IntervalEvaluator(std::shared_ptr<const Tape> tape)
  : tape_(std::move(tape))
{
  if (!tape_)
  {
    throw std::invalid_argument("IntervalEvaluator: null tape");
  }
  eval::check_tape(*tape_, "IntervalEvaluator");
  prepare(true);
}

void IntervalEvaluator::prepare(bool fold)
{
  slots_.assign(tape_->slot_count, Interval::everything());
  may_nan_.assign(tape_->slot_count, 1);
  folded_ = fold;
  if (!fold)
  {
    code_.clear();
    immediate_.clear();
    origin_.clear();
    position_.clear();
    return;
  }
  eval::BatchProgram program = eval::make_batch_program(*tape_);
  code_ = std::move(program.code);
  origin_ = std::move(program.origin);
  position_.assign(tape_->code.size(), kNotInCode);
  for (std::size_t j = 0; j < origin_.size(); ++j)
  {
    position_[origin_[j]] = j;
  }
  immediate_.resize(program.immediate.size());
  std::transform(program.immediate.begin(), program.immediate.end(), immediate_.begin(),
    [](eval::Immediate i) { return static_cast<std::uint8_t>(i); });
}

void IntervalEvaluator::rebind(std::shared_ptr<const Tape> tape, bool trusted)
{
  if (!tape)
  {
    throw std::invalid_argument("IntervalEvaluator: null tape");
  }
  if (tape == tape_)
  {
    return;
  }
  if (!trusted)
  {
    eval::check_tape(*tape, "IntervalEvaluator");
  }
  tape_ = std::move(tape);
  prepare(false);
  producers_.clear();
}

IntervalResult IntervalEvaluator::evaluate(std::span<const Interval> box)
{
  return run(box, nullptr);
}

IntervalResult IntervalEvaluator::evaluate(std::span<const Interval> box, std::span<Choice> choices)
{
  if (choices.size() != tape_->code.size())
  {
    throw std::invalid_argument("IntervalEvaluator::evaluate: one choice per instruction expected");
  }
  std::fill(choices.begin(), choices.end(), Choice::Keep);
  return run(box, choices.data());
}

IntervalResult IntervalEvaluator::evaluate(std::span<const Interval> box,
  std::span<Choice> choices, const IntervalFreeze* outer, IntervalFreeze* inner)
{
  const std::size_t n = tape_->code.size();
  if (!choices.empty() && choices.size() != n)
  {
    throw std::invalid_argument("IntervalEvaluator::evaluate: one choice per instruction expected");
  }
  if (outer && outer->action.size() != n)
  {
    throw std::invalid_argument("IntervalEvaluator::evaluate: the freeze is of another tape");
  }
  std::fill(choices.begin(), choices.end(), Choice::Keep);
  if (inner)
  {
    inner->value.resize(n);
    inner->nan.resize(n);
  }
  return run(box, choices.empty() ? nullptr : choices.data(), outer, inner);
}

IntervalResult IntervalEvaluator::run(std::span<const Interval> box, Choice* choices,
  const IntervalFreeze* outer, IntervalFreeze* inner)
{
  const Tape& tape = *tape_;
  if (box.size() < tape.input_count)
  {
    throw std::invalid_argument("IntervalEvaluator::evaluate: box has fewer intervals than inputs");
  }
  IntervalResult result;
  // operand_count per opcode, looked up without a call per instruction (hot on long tapes).
  static const std::array<std::uint8_t, 256> operands_by_opcode = []
  {
    std::array<std::uint8_t, 256> table{};
    for (int op = 0; op <= static_cast<int>(Opcode::Call); ++op)
    {
      table[static_cast<std::size_t>(op)] =
        static_cast<std::uint8_t>(operand_count(static_cast<Opcode>(op)));
    }
    return table;
  }();
  static const std::array<bool, 256> boolean_by_opcode = []
  {
    std::array<bool, 256> table{};
    for (int op = 0; op <= static_cast<int>(Opcode::Call); ++op)
    {
      table[static_cast<std::size_t>(op)] = is_boolean_opcode(static_cast<Opcode>(op));
    }
    return table;
  }();
  const auto get = [&](std::uint32_t s) { return Range{ slots_[s], may_nan_[s] != 0 }; };
  const auto put = [&](std::uint32_t s, const Range& r)
  {
    slots_[s] = r.v;
    may_nan_[s] = r.nan ? 1 : 0;
  };
  // Each instruction's result, for make_freeze (only when asked: `inner`).
  const auto record = [&](std::size_t at, const Range& r)
  {
    if (inner)
    {
      inner->value[at] = r.v;
      inner->nan[at] = r.nan ? 1 : 0;
    }
  };
  // An immediate operand: the constant's range (a NaN constant may be anything, as a Const slot).
  const auto immediate = [](double v)
  { return std::isnan(v) ? whole(true) : Range{ Interval::point(v), false }; };
  const std::vector<Instruction>& code = folded_ ? code_ : tape.code;
  // With a freeze, only its active instructions are visited (the skipped ones cost nothing).
  const std::size_t visits = outer ? outer->active.size() : code.size();
  for (std::size_t visit = 0; visit < visits; ++visit)
  {
    std::size_t j = visit;
    if (outer)
    {
      j = outer->active[visit];
      if (folded_)
      {
        j = position_[j];
        if (j == kNotInCode)
        {
          continue; // a constant folded into its readers
        }
      }
    }
    const Instruction& ins = code[j];
    const std::size_t at = folded_ ? origin_[j] : j;
    const Opcode op = ins.op;
    if (outer && outer->action[at] != IntervalFreeze::Evaluate)
    {
      if (outer->action[at] == IntervalFreeze::Frozen)
      {
        const Range r{ outer->value[at], outer->nan[at] != 0 };
        put(ins.out, r);
        record(at, r);
      }
      continue;
    }
    if (op == Opcode::Call)
    {
      const CallSite& site = tape.calls[static_cast<std::size_t>(ins.index)];
      if (enclose_call(site, get, put, result.may_fail))
      {
        continue;
      }
      for (std::uint32_t s : site.outputs)
      {
        put(s, whole(true));
      }
      result.may_fail = true;
      continue;
    }
    if (op == Opcode::Input)
    {
      const Interval& in = box[static_cast<std::size_t>(ins.index)];
      const Range r = (in.lo <= in.hi) ? Range{ in, false } : whole(true);
      put(ins.out, r);
      record(at, r);
      continue;
    }
    const int operands = operands_by_opcode[static_cast<std::size_t>(op)];
    const auto side = folded_ ? static_cast<eval::Immediate>(immediate_[j]) : eval::Immediate::None;
    const Range a = side == eval::Immediate::A ? immediate(ins.imm)
                  : operands >= 1             ? get(ins.a)
                                              : Range{};
    const Range b = side == eval::Immediate::B ? immediate(ins.imm)
                  : operands >= 2             ? get(ins.b)
                                              : Range{};
    if (op == Opcode::ErrorIf)
    {
      const bool may_fire = may_be_nonzero(a);
      result.may_fail = result.may_fail || may_fire;
      if (choices && !may_fire)
      {
        choices[at] = Choice::Drop;
      }
      continue;
    }
    Range r;
    enclose_operation(ins, a, b, get, choices ? choices + at : nullptr, r);
    if (choices && boolean_by_opcode[static_cast<std::size_t>(op)] && r.v.lo == r.v.hi)
    {
      choices[at] = r.v.lo != 0.0 ? Choice::True : Choice::False;
    }
    put(ins.out, r);
    record(at, r);
  }
  if (!tape.outputs.empty())
  {
    const Range f = get(tape.outputs[0]);
    // A NaN bound (which no rule should produce) must never pass for an enclosure.
    const bool broken = std::isnan(f.v.lo) || std::isnan(f.v.hi);
    result.value = (f.nan || broken) ? Interval::everything() : f.v;
  }
  return result;
}

bool IntervalEvaluator::output(std::size_t i, Interval& value) const
{
  const std::uint32_t s = tape_->outputs.at(i);
  value = slots_[s];
  return may_nan_[s] == 0 && !std::isnan(value.lo) && !std::isnan(value.hi);
}

} // namespace frep
