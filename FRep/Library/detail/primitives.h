// Closed-form primitives of LIBRARY.md section 1, generic over the scalar type.
//
// Each template repeats the original C expression operation for operation (same grouping,
// same constants), so that T = double is bit-identical to hflibrary. Arguments arrive in
// declaration order (args[0] is the first HyperFun argument). The dimension check of the
// original applies to the *last array fetched*, which for these functions is the point array;
// it is a size test, hence a plain `if`. Value tests become select().
#pragma once

#include "Library/detail/array_access.h"
#include "Library/library.h"
#include "Library/detail/scalar_ops.h"

#include <span>

namespace frep::library
{

namespace detail
{
/// X, Y, Z = x - c (c read bounds-safely: the original does not check its size).
template<class T>
struct Offset
{
  T x, y, z;
};

template<class T>
Offset<T> offset(std::span<T> x, std::span<T> c)
{
  return { x[0] - at(c, 0), x[1] - at(c, 1), x[2] - at(c, 2) };
}

/// |v| < EPS, the original's parameter test.
template<class T>
auto tiny(const T& v)
{
  return fabs(v) < T(kEps);
}
} // namespace detail

// hfSphere(x, center, R)
template<class T, class Ctx>
T sphere(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto [xt, yt, zt] = detail::offset(args[0].array, args[1].array);
  const T& r = args[2].real;
  return r * r - xt * xt - yt * yt - zt * zt;
}

// hfEllipsoid(x, center, a, b, c)
template<class T, class Ctx>
T ellipsoid(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  const T& a = args[2].real;
  const T& b = args[3].real;
  const T& c = args[4].real;
  auto [x, y, z] = detail::offset(args[0].array, args[1].array);
  T xt = x / a;
  T yt = y / b;
  T zt = z / c;
  T f = 1.0 - xt * xt - yt * yt - zt * zt;
  auto bad = logical_or(logical_or(detail::tiny(a), detail::tiny(b)), detail::tiny(c));
  return select(bad, T(kWrongDimension), f);
}

// hfTorusX/Y/Z(x, center, R, r0): axis selects which two offsets form the ring distance.
template<int Axis, class T, class Ctx>
T torus(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto [xt, yt, zt] = detail::offset(args[0].array, args[1].array);
  const T& big_r = args[2].real;
  const T& r0 = args[3].real;
  if constexpr (Axis == 0)
  {
    T z2 = zt * zt;
    T y2 = yt * yt;
    return r0 * r0 - xt * xt - y2 - z2 - big_r * big_r + 2.0 * big_r * sqrt(z2 + y2);
  }
  else if constexpr (Axis == 1)
  {
    T z2 = zt * zt;
    T x2 = xt * xt;
    return r0 * r0 - x2 - yt * yt - z2 - big_r * big_r + 2.0 * big_r * sqrt(z2 + x2);
  }
  else
  {
    T x2 = xt * xt;
    T y2 = yt * yt;
    return r0 * r0 - x2 - y2 - zt * zt - big_r * big_r + 2.0 * big_r * sqrt(x2 + y2);
  }
}

// hfEllCylX/Y/Z(x, center, a, b): the two offsets across the axis, divided by a and b.
template<int Axis, class T, class Ctx>
T ell_cylinder(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto [x, y, z] = detail::offset(args[0].array, args[1].array);
  const T& a = args[2].real;
  const T& b = args[3].real;
  T u = (Axis == 0) ? y / a : x / a;
  T v = (Axis == 2) ? y / b : z / b;
  T f = 1.0 - u * u - v * v;
  return select(logical_or(detail::tiny(a), detail::tiny(b)), T(kWrongDimension), f);
}

// hfCylinderX/Y/Z(x, center, R)
template<int Axis, class T, class Ctx>
T cylinder(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto [x, y, z] = detail::offset(args[0].array, args[1].array);
  const T& r = args[2].real;
  const T& u = (Axis == 0) ? y : x;
  const T& v = (Axis == 2) ? y : z;
  return r * r - u * u - v * v;
}

// hfBlock(x, vertex, dx, dy, dz): R-intersection of three slabs with the original's ALPHA = 0
// term kept literally (2*ALPHA*u*v), which only matters when u*v overflows to inf (-> NaN).
template<class T, class Ctx>
T block(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto x = args[0].array;
  auto v = args[1].array;
  const T& dx = args[2].real;
  const T& dy = args[3].real;
  const T& dz = args[4].real;
  constexpr double kTwoAlpha = 2.0 * 0.0;
  T xt = (x[0] - at(v, 0)) * (at(v, 0) + dx - x[0]);
  T yt = (x[1] - at(v, 1)) * (at(v, 1) + dy - x[1]);
  T zt = (x[2] - at(v, 2)) * (at(v, 2) + dz - x[2]);
  T f = xt + yt - sqrt(xt * xt + yt * yt - kTwoAlpha * xt * yt);
  f = f + zt - sqrt(f * f + zt * zt - kTwoAlpha * f * zt);
  auto bad = logical_or(logical_or(dx < T(0.0), dy < T(0.0)), dz < T(0.0));
  return select(bad, T(kWrongDimension), f);
}

// hfConeX/Y/Z(x, center, R): squared offset along the axis minus the scaled cross offsets.
template<int Axis, class T, class Ctx>
T cone(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto [x, y, z] = detail::offset(args[0].array, args[1].array);
  const T& r = args[2].real;
  if constexpr (Axis == 0)
  {
    T yt = y / r;
    T zt = z / r;
    return x * x - yt * yt - zt * zt;
  }
  else if constexpr (Axis == 1)
  {
    T xt = x / r;
    T zt = z / r;
    return y * y - xt * xt - zt * zt;
  }
  else
  {
    T xt = x / r;
    T yt = y / r;
    return z * z - xt * xt - yt * yt;
  }
}

// hfEllConeX/Y/Z(x, center, a, b)
template<int Axis, class T, class Ctx>
T ell_cone(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto [x, y, z] = detail::offset(args[0].array, args[1].array);
  const T& a = args[2].real;
  const T& b = args[3].real;
  if constexpr (Axis == 0)
  {
    T yt = y / a;
    T zt = z / b;
    return x * x - yt * yt - zt * zt;
  }
  else if constexpr (Axis == 1)
  {
    T xt = x / a;
    T zt = z / b;
    return y * y - xt * xt - zt * zt;
  }
  else
  {
    T xt = x / a;
    T yt = y / b;
    return z * z - xt * xt - yt * yt;
  }
}

// hfSuperell(x, center, a, b, c, s1, s2)
template<class T, class Ctx>
T superellipsoid(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto [x, y, z] = detail::offset(args[0].array, args[1].array);
  const T& a = args[2].real;
  const T& b = args[3].real;
  const T& c = args[4].real;
  const T& s1 = args[5].real;
  const T& s2 = args[6].real;
  T xt = x / a;
  T yt = y / b;
  T zt = z / c;
  T p = 2.0 / s2;
  T xp = pow(fabs(xt), p);
  T yp = pow(fabs(yt), p);
  T zp = pow(fabs(zt), 2.0 / s1);
  T xyp = pow(xp + yp, s2 / s1);
  T f = 1.0 - xyp - zp;
  auto bad = logical_or(logical_or(logical_or(detail::tiny(a), detail::tiny(b)),
                          logical_or(detail::tiny(c), detail::tiny(s1))),
    detail::tiny(s2));
  return select(bad, T(kWrongDimension), f);
}

// hfBlobby(x, x0, y0, z0, a, b, T): N = size of x0 (the last array the original fetches
// before x, whose size it never checks).
template<class T, class Ctx>
T blobby(std::span<Arg<T>> args, Ctx&)
{
  auto x = args[0].array;
  auto x0 = args[1].array;
  auto y0 = args[2].array;
  auto z0 = args[3].array;
  auto a = args[4].array;
  auto b = args[5].array;
  const T& threshold = args[6].real;
  const std::int64_t num = size_of(x0);
  if (num <= 0)
  {
    return T(kWrongDimension);
  }
  T sum = T(0.0);
  for (std::int64_t i = 0; i < num; ++i)
  {
    T xt = at(x, 0) - x0[i];
    T yt = at(x, 1) - at(y0, i);
    T zt = at(x, 2) - at(z0, i);
    sum = sum + at(b, i) * exp(-at(a, i) * (xt * xt + yt * yt + zt * zt));
  }
  return sum - threshold;
}

// hfMetaBall(x, x0, y0, z0, b, d, T): centres with d <= 0 contribute nothing.
template<class T, class Ctx>
T metaball(std::span<Arg<T>> args, Ctx&)
{
  auto x = args[0].array;
  auto x0 = args[1].array;
  auto y0 = args[2].array;
  auto z0 = args[3].array;
  auto b = args[4].array;
  auto d = args[5].array;
  const T& threshold = args[6].real;
  const std::int64_t num = size_of(x0);
  if (num <= 0)
  {
    return T(kWrongDimension);
  }
  T mb = T(0.0);
  for (std::int64_t i = 0; i < num; ++i)
  {
    T di = at(d, i);
    T bi = at(b, i);
    T xt = at(x, 0) - x0[i];
    T yt = at(x, 1) - at(y0, i);
    T zt = at(x, 2) - at(z0, i);
    T r2 = xt * xt + yt * yt + zt * zt;
    T r = sqrt(r2);
    T rd = r / di;
    T near = mb + bi * (1.0 - 3.0 * rd * rd);
    T far = mb + 1.5 * bi * (1.0 - rd) * (1.0 - rd);
    T inside = select(r <= di / 3.0, near, select(r < di, far, mb));
    mb = select(di > T(0.0), inside, mb);
  }
  return mb - threshold;
}

// hfSoft(x, x0, y0, z0, d, T): Wyvill's soft objects.
template<class T, class Ctx>
T soft(std::span<Arg<T>> args, Ctx&)
{
  auto x = args[0].array;
  auto x0 = args[1].array;
  auto y0 = args[2].array;
  auto z0 = args[3].array;
  auto d = args[4].array;
  const T& threshold = args[5].real;
  const std::int64_t num = size_of(x0);
  if (num <= 0)
  {
    return T(kWrongDimension);
  }
  T sum = T(0.0);
  for (std::int64_t i = 0; i < num; ++i)
  {
    T di = at(d, i);
    T xt = at(x, 0) - x0[i];
    T yt = at(x, 1) - at(y0, i);
    T zt = at(x, 2) - at(z0, i);
    T r2 = xt * xt + yt * yt + zt * zt;
    T r4 = r2 * r2;
    T d2 = di * di;
    T d4 = d2 * d2;
    T added =
      sum + 1.0 - 22.0 * r2 / (9.0 * d2) + 17.0 * r4 / (9.0 * d4) - 4.0 * r4 * r2 / (9.0 * d4 * d2);
    sum = select(sqrt(r2) <= di, added, sum);
  }
  return sum - threshold;
}

// hfNoiseG(x, amp, freq, phase): Gardner series.
template<class T, class Ctx>
T noise_g(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto x = args[0].array;
  const T& a1 = args[1].real;
  const T& a2 = args[2].real;
  const T& phase = args[3].real;
  T a2x = a2 * x[0];
  T a2y = a2 * x[1];
  T a2z = a2 * x[2];
  T sx = sin(a2x);
  T sy = sin(a2y);
  T sz = sin(a2z);
  T a1d = a1 / 1.17;
  T sx2 = a1d * sin(a2x / 1.35 + phase * sz);
  T sy2 = a1d * sin(a2y / 1.35 + phase * sx);
  T sz2 = a1d * sin(a2z / 1.35 + phase * sy);
  T serx = a1 * sx + sx2;
  T sery = a1 * sy + sy2;
  T serz = a1 * sz + sz2;
  return serx * sery * serz;
}

// hfConvPoint(x, vect, S, T): Cauchy kernel summed over N = size(S) points.
template<class T, class Ctx>
T conv_point(std::span<Arg<T>> args, Ctx&)
{
  if (args[0].array.size() != 3)
  {
    return T(kWrongDimension);
  }
  auto x = args[0].array;
  auto vect = args[1].array;
  auto s = args[2].array;
  const T& threshold = args[3].real;
  T f = T(0.0);
  for (std::int64_t n = 0; n < size_of(s); ++n)
  {
    T dx = at(vect, 3 * n) - x[0];
    T dy = at(vect, 3 * n + 1) - x[1];
    T dz = at(vect, 3 * n + 2) - x[2];
    T r2 = dx * dx + dy * dy + dz * dz;
    T k = 1.0 + s[n] * s[n] * r2;
    f = f + 1.0 / (k * k);
  }
  return f - threshold;
}

} // namespace frep::library
