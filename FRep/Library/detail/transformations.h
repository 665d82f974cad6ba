// Space transformations of LIBRARY.md section 2b, generic over the scalar type. They overwrite
// their first array argument in place and return 1, like the original. Reads and writes follow
// the original's order element by element, so an argument passed twice (hfStretch3D(x, x, ...))
// behaves the same. Elements 1..3 only; a shorter array is read as zeros and not grown.
#pragma once

#include "Library/detail/array_access.h"
#include "Library/library.h"
#include "Library/detail/scalar_ops.h"

#include <span>

namespace frep::library
{

// hfScale3D(xt, sx, sy, sz): no zero check in the original.
template<class T, class Ctx>
T scale3d(std::span<Arg<T>> args, Ctx&)
{
  auto xt = args[0].array;
  put(xt, 0, at(xt, 0) / args[1].real);
  put(xt, 1, at(xt, 1) / args[2].real);
  put(xt, 2, at(xt, 2) / args[3].real);
  return T(1.0);
}

// hfShift3D(xt, dx, dy, dz)
template<class T, class Ctx>
T shift3d(std::span<Arg<T>> args, Ctx&)
{
  auto xt = args[0].array;
  put(xt, 0, at(xt, 0) - args[1].real);
  put(xt, 1, at(xt, 1) - args[2].real);
  put(xt, 2, at(xt, 2) - args[3].real);
  return T(1.0);
}

namespace detail
{
/// The rotation every rotate/twist uses: (u, v) -> (u cos + v sin, -u sin + v cos), written
/// back to elements iu, iv.
template<class T>
void rotate_pair(std::span<T> xt, int iu, int iv, const T& theta)
{
  T ct = cos(theta);
  T st = sin(theta);
  T u = at(xt, iu);
  T v = at(xt, iv);
  T ur = u * ct + v * st;
  T vr = -u * st + v * ct;
  put(xt, iu, ur);
  put(xt, iv, vr);
}

/// Element pairs (u, v) rotated about each axis, as the original orders them:
/// x-axis (y, z), y-axis (z, x), z-axis (x, y).
constexpr int kRotU[3] = { 1, 2, 0 };
constexpr int kRotV[3] = { 2, 0, 1 };
} // namespace detail

// hfRotate3DX/Y/Z(xt, theta), theta in radians.
template<int Axis, class T, class Ctx>
T rotate3d(std::span<Arg<T>> args, Ctx&)
{
  detail::rotate_pair(args[0].array, detail::kRotU[Axis], detail::kRotV[Axis], args[1].real);
  return T(1.0);
}

// hfTwistX/Y/Z(xt, w1, w2, theta1, theta2): the angle varies linearly along the axis
// (t is not clamped).
template<int Axis, class T, class Ctx>
T twist(std::span<Arg<T>> args, Ctx&)
{
  auto xt = args[0].array;
  const T& w1 = args[1].real;
  const T& w2 = args[2].real;
  const T& theta1 = args[3].real;
  const T& theta2 = args[4].real;
  T t = (at(xt, Axis) - w1) / (w2 - w1);
  T theta = (1.0 - t) * theta1 + t * theta2;
  detail::rotate_pair(xt, detail::kRotU[Axis], detail::kRotV[Axis], theta);
  return T(1.0);
}

// hfStretch3D(xt, x0, sx, sy, sz)
template<class T, class Ctx>
T stretch3d(std::span<Arg<T>> args, Ctx&)
{
  auto xt = args[0].array;
  auto x0 = args[1].array;
  for (int i = 0; i < 3; ++i)
  {
    put(xt, i, at(x0, i) + (at(xt, i) - at(x0, i)) / args[2 + i].real);
  }
  return T(1.0);
}

// hfTaperX/Y/Z(xt, w1, w2, s1, s2): the scale is s1 below w1, s2 above w2, linear between,
// 1 when |scale| < EPS; the two cross coordinates are divided by it (in the original's order).
template<int Axis, class T, class Ctx>
T taper(std::span<Arg<T>> args, Ctx&)
{
  auto xt = args[0].array;
  const T& w1 = args[1].real;
  const T& w2 = args[2].real;
  const T& s1 = args[3].real;
  const T& s2 = args[4].real;
  T w = at(xt, Axis);
  T t = (w - w1) / (w2 - w1);
  T scale = select(w < w1, s1, select(w > w2, s2, (1.0 - t) * s1 + t * s2));
  scale = select(fabs(scale) < T(kEps), T(1.0), scale);
  // x: (y, z); y: (z, x); z: (x, y) -- the order hftaper*.c writes them.
  constexpr int first[3] = { 1, 2, 0 };
  constexpr int second[3] = { 2, 0, 1 };
  put(xt, first[Axis], at(xt, first[Axis]) / scale);
  put(xt, second[Axis], at(xt, second[Axis]) / scale);
  return T(1.0);
}

// hfSpaceMapCubic / hfSpaceMapExp(xt, source, target, b): each key point (3 entries of source,
// target and b) pulls xt by dt = target - source with a weight of the normalised distance.
// The key count is size(source) / 3, rounded up as the original's `i += 3` loop does.
template<bool Cubic, class T, class Ctx>
T space_map(std::span<Arg<T>> args, Ctx&)
{
  auto xt = args[0].array;
  auto from = args[1].array;
  auto to = args[2].array;
  auto ratio = args[3].array;
  const std::int64_t n = size_of(from);
  for (std::int64_t i = 0; i < n; i += 3)
  {
    T dt[3];
    T u[3];
    for (int k = 0; k < 3; ++k)
    {
      dt[k] = at(to, i + k) - at(from, i + k);
    }
    for (int k = 0; k < 3; ++k)
    {
      u[k] = (at(xt, k) - at(to, i + k)) / (at(ratio, i + k) * (1.0 + sqrt(dt[k] * dt[k])));
      u[k] = u[k] * u[k];
    }
    if constexpr (Cubic)
    {
      T r = sqrt(u[0] + u[1] + u[2]);
      T w = ((1.0 - r) * (1.0 - r)) * (1.0 - r) / (1.0 + r);
      auto near = r <= T(1.0);
      for (int k = 0; k < 3; ++k)
      {
        T moved = at(xt, k) - w * dt[k];
        put(xt, k, select(near, moved, at(xt, k)));
      }
    }
    else
    {
      T w = exp(-(u[0] + u[1] + u[2]));
      for (int k = 0; k < 3; ++k)
      {
        put(xt, k, at(xt, k) - w * dt[k]);
      }
    }
  }
  return T(1.0);
}

} // namespace frep::library
