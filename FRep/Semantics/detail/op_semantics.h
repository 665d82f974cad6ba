// The exact double semantics of the HyperFun-specific opcodes, shared by everything that must
// agree bit for bit: the reference interpreter, constant folding in the compiler, and the point
// and batch evaluators. Each function performs the same floating-point operations in the same
// order as the original interpreter (int_calc.c), so results are identical to the last bit.
#pragma once

#include <climits>
#include <cmath>

namespace frep::semantics
{

/// EPS of the original (double EPS = 0.1e-5).
inline constexpr double kEps = 1e-6;

/// The original's HF_round: round half up, via ceil, then a C cast to int. Out-of-range values
/// (and NaN) convert as x86-64's cvttsd2si does: to INT_MIN (undefined behaviour in C; this is
/// what the reference build computed).
inline int hf_round(double d)
{
  const double c = std::ceil(d);
  const double r = (c - d > 0.5) ? (c - 1) : c;
  if (!(r >= static_cast<double>(INT_MIN) && r < 2147483648.0))
  {
    return INT_MIN;
  }
  return static_cast<int>(r);
}

/// Truthiness of a value in conditions, and/or/not: |v| >= EPS.
inline bool truthy(double v)
{
  return std::fabs(v) >= kEps;
}

/// lhs & rhs (and @): (1/(1+ALPHA)) * (l + r - sqrt(fabs(l*l + r*r - 2*ALPHA*r*l))), ALPHA = 0.
/// The 0*r*l term is kept: it turns an infinite operand into NaN, as in the original.
inline double intersect(double l, double r)
{
  return 1.0 * (l + r - std::sqrt(std::fabs(l * l + r * r - 0.0 * r * l)));
}

/// lhs | rhs.
inline double unite(double l, double r)
{
  return 1.0 * (l + r + std::sqrt(std::fabs(l * l + r * r - 0.0 * r * l)));
}

/// The union part of hfBlendUni, (l + r) + sqrt(l*l + r*r), exactly as the library writes it
/// (no fabs, no 0*r*l term): equal to unite() bit for bit for finite operands.
inline double unite_plain(double l, double r)
{
  return (l + r) + std::sqrt(l * l + r * r);
}

/// The intersection part of hfBlendInt, (l + r) - sqrt(l*l + r*r).
inline double intersect_plain(double l, double r)
{
  return (l + r) - std::sqrt(l * l + r * r);
}

/// Error cases of b ^ e (value part in hf_pow).
enum class PowError
{
  None,
  ZeroBase,    ///< "Zero value in negative or zero power": |b| < EPS and e <= EPS
  NegativeBase ///< "Negative value for power": non-integral e and b < 0
};

inline PowError hf_pow_error(double b, double e)
{
  if (std::fabs(b) < kEps)
  {
    return e <= kEps ? PowError::ZeroBase : PowError::None;
  }
  if ((e - std::floor(e)) < kEps)
  {
    return PowError::None;
  }
  return b < 0.0 ? PowError::NegativeBase : PowError::None;
}

/// Integer power by repeated multiplication (the original's loop): 1.0 * b * b ... n times,
/// reciprocal when the exponent is negative.
inline double hf_pow_repeated(double b, int n, bool negative)
{
  double v = 1.0;
  for (int i = 0; i < n; ++i)
  {
    v *= b;
    // Once v is 0, inf or NaN, or when |b| = 1, every further multiplication keeps |v| and only
    // flips the sign when b < 0 (a NaN keeps its bits): finish by parity instead of looping up
    // to 2^31 times. Bit-identical to the full loop.
    if (v == 0.0 || std::isinf(v) || std::isnan(v) || std::fabs(b) == 1.0)
    {
      const int remaining = n - 1 - i;
      if (!std::isnan(v) && std::signbit(b) && remaining % 2 == 1)
      {
        v = -v;
      }
      break;
    }
  }
  return negative ? 1 / v : v;
}

/// Value of b ^ e when hf_pow_error(b, e) == None (otherwise meaningless but finite-safe).
inline double hf_pow(double b, double e)
{
  if (std::fabs(b) < kEps)
  {
    return 0.0;
  }
  if ((e - std::floor(e)) < kEps)
  {
    return hf_pow_repeated(b, hf_round(std::fabs(e)), e < 0.0);
  }
  return std::exp(e * std::log(b));
}

/// b ^ n for a constant integral exponent n (the compiler's specialisation of hf_pow; n is the
/// HF_round of |e| with the sign of e, and e was integral within EPS).
inline double hf_pow_int(double b, int n)
{
  if (std::fabs(b) < kEps)
  {
    return 0.0; // the compiler emits the ZeroBase error check separately when n <= 0
  }
  return hf_pow_repeated(b, n < 0 ? -n : n, n < 0);
}

/// mod(a, b) = fmod(HF_round(a), HF_round(b)) (2018+ builds).
inline double hf_mod(double a, double b)
{
  return std::fmod(static_cast<double>(hf_round(a)), static_cast<double>(hf_round(b)));
}

/// max/min as the builtins compute them (NaN handling follows the comparison).
inline double hf_max(double a, double b)
{
  return (a > b) ? a : b;
}
inline double hf_min(double a, double b)
{
  return (a < b) ? a : b;
}

} // namespace frep::semantics
