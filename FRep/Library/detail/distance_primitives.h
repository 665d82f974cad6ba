// The closed-form members of the SARDF (signed approximate real distance) family, LIBRARY.md
// section 3, generic over the scalar type: hfDConeX/Y/Z, hfDCylinder, hfDTorusX/Y/Z and the
// distance blends hfDBlendUni/Int. (hfDEllipsoid and hfDUni/DInt/DSub need iteration or a
// quartic solver and are double-only: distance_ellipsoid.cpp, sardf_operations.cpp.)
#pragma once

#include "Library/detail/array_access.h"
#include "Library/library.h"
#include "Library/detail/scalar_ops.h"

#include <span>

namespace frep::library
{

// hfDConeX/Y/Z(x, center, R): -(radial * cos(atan R) - |axial| * sin(atan R)).
template<int Axis, class T, class Ctx>
T distance_cone(std::span<Arg<T>> args, Ctx&)
{
  auto x = args[0].array;
  auto c = args[1].array;
  if (x.size() != 3)
  {
    return T(kWrongDimensionCone);
  }
  T t = atan(args[2].real);
  T xx = x[0] - at(c, 0);
  T y = x[1] - at(c, 1);
  T z = x[2] - at(c, 2);
  T distance;
  if constexpr (Axis == 0)
  {
    distance = sqrt(z * z + y * y) * cos(t) - fabs(xx) * sin(t);
  }
  else if constexpr (Axis == 1)
  {
    distance = sqrt(z * z + xx * xx) * cos(t) - fabs(y) * sin(t);
  }
  else
  {
    distance = sqrt(xx * xx + y * y) * cos(t) - fabs(z) * sin(t);
  }
  return -distance;
}

// hfDCylinder(x, center, u, R): R minus the distance to the line through center along u,
// computed as the original does (through the second point center + u).
template<class T, class Ctx>
T distance_cylinder(std::span<Arg<T>> args, Ctx&)
{
  auto x = args[0].array;
  auto center = args[1].array;
  auto u = args[2].array;
  if (x.size() != 3)
  {
    return T(kWrongDimensionCylinder);
  }
  T x21[3];
  T x10[3];
  for (int i = 0; i < 3; ++i)
  {
    T x1 = at(center, i);
    T x2 = at(center, i) + at(u, i);
    x21[i] = x2 - x1;
    x10[i] = x1 - x[i];
  }
  T cp0 = x21[1] * x10[2] - x10[1] * x21[2];
  T cp1 = x21[2] * x10[0] - x21[0] * x10[2];
  T cp2 = x21[0] * x10[1] - x21[1] * x10[0];
  T d1 = cp0 * cp0 + cp1 * cp1 + cp2 * cp2;
  T d2 = x21[0] * x21[0] + x21[1] * x21[1] + x21[2] * x21[2];
  T d = sqrt(d1 / d2);
  return args[3].real - d;
}

// hfDTorusX/Y/Z(x, center, R, r0): r0 - |(ring distance - R, axial offset)|.
template<int Axis, class T, class Ctx>
T distance_torus(std::span<Arg<T>> args, Ctx&)
{
  auto x = args[0].array;
  auto c = args[1].array;
  if (x.size() != 3)
  {
    return T(kWrongDimension);
  }
  const T& big_r = args[2].real;
  const T& r0 = args[3].real;
  T xx = x[0] - at(c, 0);
  T y = x[1] - at(c, 1);
  T z = x[2] - at(c, 2);
  T ring;
  T axial;
  if constexpr (Axis == 0)
  {
    ring = sqrt(y * y + z * z);
    axial = xx;
  }
  else if constexpr (Axis == 1)
  {
    ring = sqrt(xx * xx + z * z);
    axial = y;
  }
  else
  {
    ring = sqrt(xx * xx + y * y);
    axial = z;
  }
  ring = ring - big_r;
  T d = sqrt(ring * ring + axial * axial);
  d = d - r0;
  return -d;
}

// hfDBlendUni / hfDBlendInt(f1, f2, r): inside the band |f2 - f1| <= r the root of a quadratic
// (0 when its discriminant is negative), outside it max (union) or min (intersection); NaN
// input falls through every test of the original and gives 0.
template<bool Union, class T, class Ctx>
T distance_blend(std::span<Arg<T>> args, Ctx&)
{
  const T& xt = args[0].real;
  const T& yt = args[1].real;
  const T& r = args[2].real;
  constexpr double aa = 2.0;
  T b;
  T c;
  if constexpr (Union)
  {
    b = -2.0 * xt - 4.0 * r - 2.0 * yt;
    c = xt * xt + yt * yt + r * r + 2.0 * xt * r + 2.0 * yt * r;
  }
  else
  {
    b = -2.0 * xt + 4.0 * r - 2.0 * yt;
    c = xt * xt + yt * yt + r * r - 2.0 * xt * r - 2.0 * yt * r;
  }
  T ds = b * b - 4.0 * aa * c;
  T root;
  if constexpr (Union)
  {
    root = (-b - sqrt(ds)) / (2.0 * aa);
  }
  else
  {
    root = (-b + sqrt(ds)) / (2.0 * aa);
  }
  T upper = xt + r;
  T lower = xt - r;
  auto in_band = logical_and(yt <= upper, yt >= lower);
  T band = select(ds >= T(0.0), root, T(0.0));
  // Outside: "if (yt < xt - r) d = ...; if (yt > xt + r) d = ...;" -- the second wins.
  T below = Union ? xt : yt;
  T above = Union ? yt : xt;
  T outside = select(yt > upper, above, select(yt < lower, below, T(0.0)));
  return select(in_band, band, outside);
}

} // namespace frep::library
