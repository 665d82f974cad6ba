// hfDUni, hfDInt, hfDSub: the SARDF set operations (Fayolle's uni_sardef_1 / int_sardef_1):
// an unbounded angle-based blend in one quadrant of the (f1, f2) plane and a bounded one
// (radius R, a quartic root near the axes, a circular arc in the strip) in the opposite one.
// Double-only: many value-dependent branches and a quartic solver. The control flow, including
// every fall-through that returns 0, follows the original.
#include "Library/detail/library_double.h"
#include "Library/detail/quartic.h"

#include <cmath>

namespace frep::library
{
namespace
{

constexpr double kZero = 1.0e-7;

double uni_sardef(double xt, double yt, double r, double alpha)
{
  double d = 0;
  if (std::fabs(xt) < kZero && std::fabs(yt) < kZero)
  {
    return 0.0;
  }
  if (std::fabs(xt) < kZero && yt > 0)
  {
    return yt;
  }
  if (std::fabs(xt) < kZero && yt < 0)
  {
    return 0.0;
  }
  if (std::fabs(yt) < kZero && xt > 0)
  {
    return xt;
  }
  if (std::fabs(yt) < kZero && xt < 0)
  {
    return 0.0;
  }
  if ((std::fabs(yt) > kZero) && (std::fabs(xt) > kZero))
  {
    if (yt > 0 && xt < 0)
    {
      return yt; // II quadrant
    }
    if (xt > 0 && yt < 0)
    {
      return xt; // IV quadrant
    }
    if ((xt > 0) && (yt > 0))
    {
      // I quadrant: unbounded blend inside the angle (atan(alpha) .. pi/2 - alpha)
      const double g = 1.0 / (std::tan(alpha));
      const double g2 = std::tan(alpha);
      const double gt = xt / yt;
      if ((gt < g) && (gt > g2))
      {
        const double t = std::tan(alpha);
        const double aa = t * t + 2.0 * t - 1.0;
        const double b = -2.0 * t * (xt + yt);
        const double c = xt * xt + yt * yt;
        double d1 = -b - std::sqrt(b * b - 4.0 * aa * c);
        d1 = d1 / (2.0 * aa);
        return d1;
      }
      if (gt >= g)
      {
        return xt;
      }
      if (gt <= g2)
      {
        return yt;
      }
    }
    const double lim2 = ((xt + 2 * r) * (xt + 2 * r)) + ((yt + 2 * r) * (yt + 2 * r));
    if ((xt < 0) && (yt < 0))
    {
      // III quadrant: bounded blend
      if ((xt >= -r) || (yt >= -r) || ((xt >= -2 * r) && (yt >= -2 * r) && (lim2 >= r * r)))
      {
        double xx = xt * xt;
        double yy = yt * yt;
        xx = -xx / (4.0 * r);
        yy = -yy / (4.0 * r);
        if ((xt <= yy) && (yt <= xx))
        {
          const double c0 = -(xt * xt + yt * yt);
          const double c1 = -4.0 * std::sqrt(r) * (xt + yt);
          const double c2 = -4.0 * r;
          const double c3 = -4.0 * std::sqrt(r);
          const double c4 = 1.0;
          const Roots sol = quartic_roots(c4, c3, c2, c1, c0);
          double m = sol.value[1];
          m = -m * m;
          return m;
        }
        if (yt > xx)
        {
          return yt;
        }
        if (yy < xt)
        {
          return xt;
        }
      }
      else
      {
        if ((yt <= xt + r) && (yt >= xt - r))
        {
          const double aa = 2;
          const double b = -2 * xt - 4 * r - 2 * yt;
          const double c = xt * xt + yt * yt + r * r + 2 * xt * r + 2 * yt * r;
          const double ds = b * b - 4 * aa * c;
          if (ds >= 0)
          {
            d = (-b - std::sqrt(ds)) / (2 * aa);
            return d;
          }
        }
        else
        {
          if (yt < xt - r)
          {
            return xt;
          }
          if (yt > xt + r)
          {
            return yt;
          }
        }
      }
    }
  }
  return d;
}

double int_sardef(double xt, double yt, double r, double alpha)
{
  double d = 0;
  if (std::fabs(xt) < 1e-07 && std::fabs(yt) < 1e-07)
  {
    return 0.0;
  }
  if (std::fabs(yt) < 1e-7 && xt > 0)
  {
    return 0.0;
  }
  if (std::fabs(yt) < 1e-7 && xt < 0)
  {
    return xt;
  }
  if (std::fabs(xt) < 1e-7 && yt > 0)
  {
    return 0.0;
  }
  if (std::fabs(xt) < 1e-7 && yt < 0)
  {
    return yt;
  }
  if ((std::fabs(yt) > 1e-7) && (std::fabs(xt) > 1e-7))
  {
    if (xt < 0 && yt > 0)
    {
      return xt; // II quadrant
    }
    if (yt < 0 && xt > 0)
    {
      return yt; // IV quadrant
    }
    if ((xt > 0) && (yt > 0))
    {
      // I quadrant: bounded blend; the circle centred at (2R, 2R) separates the two regimes
      const double lim = ((xt - 2 * r) * (xt - 2 * r)) + ((yt - 2 * r) * (yt - 2 * r));
      if ((xt <= r) || (yt <= r) || ((xt <= 2 * r) && (yt <= 2 * r) && (lim >= r * r)))
      {
        double xx = xt * xt;
        double yy = yt * yt;
        xx = xx / (4.0 * r);
        yy = yy / (4.0 * r);
        if ((xx <= yt) && (yy <= xt))
        {
          const double c0 = -(xt * xt + yt * yt);
          const double c1 = 4.0 * (xt + yt) * std::sqrt(r);
          const double c2 = -4.0 * r;
          const double c3 = -4.0 * std::sqrt(r);
          const double c4 = 1.0;
          const Roots sol = quartic_roots(c4, c3, c2, c1, c0);
          double m = sol.value[1];
          m = m * m;
          return m;
        }
        if (xx > yt)
        {
          return yt;
        }
        if (yy > xt)
        {
          return xt;
        }
      }
      else
      {
        if ((yt <= xt + r) && (yt >= xt - r))
        {
          const double aa = 2;
          const double b = -2 * xt + 4 * r - 2 * yt;
          const double c = xt * xt + yt * yt + r * r - 2 * xt * r - 2 * yt * r;
          const double ds = b * b - 4 * aa * c;
          if (ds >= 0)
          {
            d = (-b + std::sqrt(ds)) / (2 * aa);
            return d;
          }
        }
        else
        {
          if (yt < xt - r)
          {
            return yt;
          }
          if (yt > xt + r)
          {
            return xt;
          }
        }
      }
    }
    if ((xt < 0) && (yt < 0))
    {
      // III quadrant: unbounded angle blend (alpha = 0 makes g infinite: always inside)
      const double g = 1.0 / (std::tan(alpha));
      const double g2 = std::tan(alpha);
      const double gt = xt / yt;
      if ((gt < g) && (gt > g2))
      {
        const double t = std::tan(alpha);
        const double aa = 1.0 - t * t - 2.0 * t;
        const double b = 2.0 * t * (xt + yt);
        const double c = -xt * xt - yt * yt;
        const double ds = b * b - 4.0 * aa * c;
        return (-b - std::sqrt(ds)) / (2.0 * aa);
      }
      if (gt >= g)
      {
        return xt;
      }
      if (gt <= g2)
      {
        return yt;
      }
    }
  }
  return d;
}

} // namespace

// hfDUni(f1, f2, r, alpha)
double distance_union(DoubleArgs args, DoubleContext&)
{
  return uni_sardef(args[0].real, args[1].real, args[2].real, args[3].real);
}

// hfDInt(f1, f2, r, alpha)
double distance_intersection(DoubleArgs args, DoubleContext&)
{
  return int_sardef(args[0].real, args[1].real, args[2].real, args[3].real);
}

// hfDSub(f1, f2, r, alpha) = hfDInt(f1, -f2, r, alpha)
double distance_subtraction(DoubleArgs args, DoubleContext&)
{
  return int_sardef(args[0].real, -args[1].real, args[2].real, args[3].real);
}

} // namespace frep::library
