// See quartic.h. The helpers keep the original's special cases: fdiv's LARGE_VAL on overflow,
// the c0 == 0 deflation, the trigonometric branch of the cubic.
#include "Library/detail/quartic.h"

#include <cmath>

namespace frep::library
{
namespace
{

constexpr double kLargeValue = 1e10;
constexpr double kPi = 3.1415926535897932384626433832795;

int sign(double x)
{
  return (x == 0 ? 0 : (x < 0 ? -1 : 1));
}

/// a / b, with 0/0 = 0 and LARGE_VAL (signed) where the original detects overflow.
double fdiv(double a, double b)
{
  if (b == 0)
  {
    if (a == 0)
    {
      return 0;
    }
    return kLargeValue * sign(a);
  }
  if (a == 0)
  {
    return 0;
  }
  if ((a + b) == a)
  {
    return kLargeValue * sign(a) * sign(b);
  }
  return a / b;
}

void push(Roots& r, double v)
{
  if (r.count < 5)
  {
    r.value[r.count++] = v;
  }
}

Roots linear_root(double c1, double c0)
{
  Roots r;
  if (c1 != 0)
  {
    r.count = 1;
    r.value[0] = fdiv(-c0, c1);
  }
  return r;
}

Roots quadratic_roots(double c2, double c1, double c0)
{
  if (c2 == 0)
  {
    return linear_root(c1, c0);
  }
  Roots r;
  const double d = c1 * c1 - 4 * c2 * c0;
  if (d == 0)
  {
    r.count = 1;
    r.value[0] = fdiv(-c1, 2 * c2);
  }
  else if (d > 0)
  {
    r.count = 2;
    r.value[0] = fdiv(-c1 + std::sqrt(d), 2 * c2);
    r.value[1] = fdiv(-c1 - std::sqrt(d), 2 * c2);
  }
  return r;
}

Roots cubic_roots(double c3, double c2, double c1, double c0)
{
  if (c3 == 0)
  {
    return quadratic_roots(c2, c1, c0);
  }
  Roots r;
  if (c2 == 0 && c1 == 0)
  {
    r.count = 1;
    r.value[0] = std::cbrt(fdiv(-c0, c3));
    return r;
  }
  if (c0 == 0)
  {
    r.count = 1;
    r.value[0] = 0;
    const Roots quad = quadratic_roots(c3, c2, c1);
    for (int i = 0; i < quad.count; i++)
    {
      if (quad.value[i] != 0)
      {
        push(r, quad.value[i]);
      }
    }
    return r;
  }
  double k, p, q;
  if (c2 != 0)
  {
    k = fdiv(-c2, 3 * c3);
    p = fdiv(3 * c3 * c1 - c2 * c2, -3 * c3 * c3);
    q = fdiv(2 * c2 * c2 * c2 - 9 * c3 * c2 * c1 + 27 * c3 * c3 * c0, -27 * c3 * c3 * c3);
  }
  else
  {
    k = 0;
    p = fdiv(-c1, c3);
    q = fdiv(-c0, c3);
  }
  const double p_d3_e3 = p * p / 27 * p;
  const double w = q / 4 * q - p_d3_e3;
  if (w < 0)
  {
    const double cos3a = fdiv(q, 2 * std::sqrt(p_d3_e3));
    const double a = std::acos(cos3a) / 3;
    const double t = std::sqrt(p * 1.33333333333333);
    r.count = 3;
    r.value[0] = t * std::cos(a) + k;
    double rad_120 = 2.0 * kPi;
    rad_120 = rad_120 / 3.0;
    double rad_240 = 4.0 * kPi;
    rad_240 = rad_240 / 3.0;
    r.value[1] = t * std::cos(a + rad_120) + k;
    r.value[2] = t * std::cos(a + rad_240) + k;
  }
  else if (w == 0)
  {
    r.count = 1;
    r.value[0] = 2 * std::cbrt(q / 2) + k;
  }
  else
  {
    r.count = 1;
    r.value[0] = std::cbrt(q / 2 + std::sqrt(w)) + std::cbrt(q / 2 - std::sqrt(w)) + k;
  }
  return r;
}

} // namespace

Roots quartic_roots(double c4, double c3, double c2, double c1, double c0)
{
  Roots r;
  if (c0 == 0)
  {
    r.count = 1;
    r.value[0] = 0;
    const Roots cubic = cubic_roots(c4, c3, c2, c1);
    for (int i = 0; i < cubic.count; i++)
    {
      if (cubic.value[i] != 0)
      {
        push(r, cubic.value[i]);
      }
    }
    return r;
  }
  const double a3 = fdiv(c3, c4);
  double a2 = fdiv(c2, c4);
  const double a1 = fdiv(c1, c4);
  const double a0 = fdiv(c0, c4);
  const Roots cb = cubic_roots(-8, 4 * a2, 8 * a0 - 2 * a1 * a3, a1 * a1 - a0 * (4 * a2 - a3 * a3));
  double hi_root = cb.value[0];
  if (cb.count == 2)
  {
    if (cb.value[1] > hi_root)
    {
      hi_root = cb.value[1];
    }
  }
  else if (cb.count == 3)
  {
    if (cb.value[1] > cb.value[2])
    {
      if (cb.value[1] > hi_root)
      {
        hi_root = cb.value[1];
      }
    }
    else if (cb.value[2] > hi_root)
    {
      hi_root = cb.value[2];
    }
  }
  r.count = 0;
  if ((a2 = hi_root * hi_root) > a0)
  {
    const double b = std::sqrt(a2 - a0);
    const double m = fdiv(a3 * hi_root - a1, 2 * b);
    const Roots first = quadratic_roots(1, a3 / 2 + m, hi_root + b);
    const Roots second = quadratic_roots(1, a3 / 2 - m, hi_root - b);
    for (int j = 0; j < first.count; j++)
    {
      push(r, first.value[j]);
    }
    for (int j = 0; j < second.count; j++)
    {
      push(r, second.value[j]);
    }
  }
  return r;
}

} // namespace frep::library
