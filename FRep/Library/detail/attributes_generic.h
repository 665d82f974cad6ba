// The hfA_* attribute functions of LIBRARY.md section 4 that are straight-line arithmetic,
// generic over the scalar type. Output arrays are written in place like the original; a
// conditional write becomes `out[i] = select(cond, new, out[i])`. The table-driven and noise
// functions with value-dependent control flow are double-only (attribute_*.cpp).
#pragma once

#include "Library/detail/array_access.h"
#include "Library/library.h"
#include "Library/detail/scalar_ops.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace frep::library
{

namespace detail
{
/// a == b and a != b built from ordered comparisons (NaN compares unequal, as in C).
template<class T>
auto equal(const T& a, const T& b)
{
  return logical_and(a <= b, a >= b);
}

/// (int)v == k for a small integer k, as a value test.
template<class T>
auto int_is(const T& v, double k)
{
  return logical_and(v > T(k - 0.5), v < T(k + 0.5));
}
} // namespace detail

// hfA_Wave(v, c1, c2, freq): (1 + sin(freq v)) / 2 rescaled into [min(c1,c2), max(c1,c2)].
template<class T, class Ctx>
T a_wave(std::span<Arg<T>> args, Ctx&)
{
  const T& x = args[0].real;
  const T& c1 = args[1].real;
  const T& c2 = args[2].real;
  const T& freq = args[3].real;
  T c = (1.0 + sin(freq * x)) / 2.0;
  return select(c1 > c2, c * (c1 - c2) + c2, c * (c2 - c1) + c1);
}

// hfA_CheckerBoard(x, block_size, gap_size, output, input_block, input_gap): output gets the
// block attributes inside a block of the lattice, the gap attributes elsewhere; nothing is
// written when the two attribute arrays differ in size.
template<class T, class Ctx>
T a_checkerboard(std::span<Arg<T>> args, Ctx&)
{
  auto x = args[0].array;
  auto cube = args[1].array;
  auto gap = args[2].array;
  auto out = args[3].array;
  auto c_cube = args[4].array;
  auto c_space = args[5].array;
  T lmin[3];
  T lmax[3];
  for (int i = 0; i < 3; ++i)
  {
    T period = at(gap, i) + at(cube, i);
    T delta = floor(at(x, i) / period);
    T center = (at(gap, i) + at(cube, i)) * delta;
    lmin[i] = center;
    lmax[i] = center + at(cube, i);
  }
  if (c_cube.size() != c_space.size())
  {
    return T(1.0);
  }
  auto inside = logical_and(at(x, 0) > lmin[0], at(x, 0) < lmax[0]);
  inside = logical_and(inside, at(x, 1) > lmin[1]);
  inside = logical_and(inside, at(x, 1) < lmax[1]);
  inside = logical_and(inside, at(x, 2) > lmin[2]);
  inside = logical_and(inside, at(x, 2) < lmax[2]);
  for (std::int64_t i = 0; i < size_of(c_cube); ++i)
  {
    put(out, i, select(inside, c_cube[i], c_space[i]));
  }
  return T(1.0);
}

// hfA_Union(f1, f2, output, input1, input2, operator): returns the R-union of f1, f2; where it
// exceeds -EPS, output takes input1 or input2 (whichever side is inside), or, where both or
// neither are, the combination chosen by (int)operator (0 first, 1 second, 2 sum, 3 min, 4 max;
// anything else leaves output alone).
template<class T, class Ctx>
T a_union(std::span<Arg<T>> args, Ctx&)
{
  const T& f1 = args[0].real;
  const T& f2 = args[1].real;
  auto result = args[2].array;
  auto c1 = args[3].array;
  auto c2 = args[4].array;
  T op = c_int_value(args[5].real);
  T f1_u_f2 = f1 + f2 + sqrt(f1 * f1 + f2 * f2);
  auto active = f1_u_f2 > T(-kEps);
  auto only_first = logical_and(f1 >= T(0.0), f2 < T(0.0));
  auto only_second = logical_and(f2 >= T(0.0), f1 < T(0.0));
  for (std::int64_t i = 0; i < size_of(result); ++i)
  {
    T a = at(c1, i);
    T b = at(c2, i);
    T old = result[i];
    T by_op = select(detail::int_is(op, 0.0),
      a,
      select(detail::int_is(op, 1.0),
        b,
        select(detail::int_is(op, 2.0),
          a + b,
          select(detail::int_is(op, 3.0),
            select(a > b, b, a),
            select(detail::int_is(op, 4.0), select(a > b, a, b), old)))));
    T chosen = select(only_first, a, select(only_second, b, by_op));
    result[i] = select(active, chosen, old);
  }
  return f1_u_f2;
}

// hfA_NoiseG(x, freq, phase): Gardner series with amplitude 1, normalised to [0, 1]. The
// original does not check the size of x.
template<class T, class Ctx>
T a_noise_g(std::span<Arg<T>> args, Ctx&)
{
  auto x = args[0].array;
  const T& a2 = args[1].real;
  const T& phase = args[2].real;
  const double a1 = 1.0;
  T a2x = a2 * at(x, 0);
  T a2y = a2 * at(x, 1);
  T a2z = a2 * at(x, 2);
  T sx = sin(a2x);
  T sy = sin(a2y);
  T sz = sin(a2z);
  const double a1d = a1 / 1.17;
  T sx2 = a1d * sin(a2x / 1.35 + phase * sz);
  T sy2 = a1d * sin(a2y / 1.35 + phase * sx);
  T sz2 = a1d * sin(a2z / 1.35 + phase * sy);
  T serx = a1 * sx + sx2;
  T sery = a1 * sy + sy2;
  T serz = a1 * sz + sz2;
  T ss = serx * sery * serz;
  const double c = 2.17 / 1.17;
  const double c_min = std::pow(-a1 * c, 3.0);
  const double c_max = -c_min;
  return (ss - c_min) / (c_max - c_min);
}

// hfA_SetColor(f, s, r, g, b): where f >= 0, s[1..3] = r, g, b.
template<class T, class Ctx>
T a_set_color(std::span<Arg<T>> args, Ctx&)
{
  auto inside = args[0].real >= T(0.0);
  auto s = args[1].array;
  for (int i = 0; i < 3; ++i)
  {
    put(s, i, select(inside, args[2 + i].real, at(s, i)));
  }
  return T(1.0);
}

// hfA_SetAttributes(f, s, s1): where f >= 0, copies min(size s, size s1) items of s1 into s.
template<class T, class Ctx>
T a_set_attributes(std::span<Arg<T>> args, Ctx&)
{
  auto inside = args[0].real >= T(0.0);
  auto s = args[1].array;
  auto s1 = args[2].array;
  const std::int64_t n = std::min(size_of(s), size_of(s1));
  for (std::int64_t i = 0; i < n; ++i)
  {
    s[i] = select(inside, s1[i], s[i]);
  }
  return T(1.0);
}

// hfA_Lerp(s, s1, s2, f, fmin, fmax) (and hfA_Cerp, registered with the same C function):
// t = (f - fmin) / (fmax - fmin); s = s1 below 0, s2 above 1, the blend between; returns t.
template<class T, class Ctx>
T a_lerp(std::span<Arg<T>> args, Ctx&)
{
  auto s = args[0].array;
  auto s1 = args[1].array;
  auto s2 = args[2].array;
  T t = (args[3].real - args[4].real) / (args[5].real - args[4].real);
  auto below = t < T(0.0);
  auto above = t > T(1.0);
  for (std::int64_t i = 0; i < size_of(s); ++i)
  {
    T a = at(s1, i);
    T b = at(s2, i);
    s[i] = select(below, a, select(above, b, (1.0 - t) * a + t * b));
  }
  return t;
}

// hfA_Clamp(f, a, b)
template<class T, class Ctx>
T a_clamp(std::span<Arg<T>> args, Ctx&)
{
  const T& f = args[0].real;
  const T& a = args[1].real;
  const T& b = args[2].real;
  return select(f < a, a, select(f > b, b, f));
}

// hfA_Floor(v): (int) truncation toward zero, as a double.
template<class T, class Ctx>
T a_floor(std::span<Arg<T>> args, Ctx&)
{
  return c_int_value(args[0].real);
}

// hfA_Pulse(f, a, b): as coded, 1 iff b <= f <= a (the comment of the original swaps them).
template<class T, class Ctx>
T a_pulse(std::span<Arg<T>> args, Ctx&)
{
  const T& f = args[0].real;
  const T& upper = args[1].real;
  const T& lower = args[2].real;
  return select(f < lower, T(0.0), select(f > upper, T(0.0), T(1.0)));
}

// hfA_Step(f, a)
template<class T, class Ctx>
T a_step(std::span<Arg<T>> args, Ctx&)
{
  return select(args[0].real < args[1].real, T(0.0), T(1.0));
}

// hfA_SmoothStep(_, _, _, f, a, b): the table declares six arguments, the code reads the last
// three.
template<class T, class Ctx>
T a_smooth_step(std::span<Arg<T>> args, Ctx&)
{
  const T& f = args[3].real;
  const T& a = args[4].real;
  const T& b = args[5].real;
  T t = (f - a) / (b - a);
  T smooth = t * t * (3.0 - 2.0 * t);
  return select(f > b, T(1.0), select(f < a, T(0.0), smooth));
}

// hfA_Modulo(a, b): a - b * (int)(a / b), plus b when negative.
template<class T, class Ctx>
T a_modulo(std::span<Arg<T>> args, Ctx&)
{
  const T& a = args[0].real;
  const T& b = args[1].real;
  T n = c_int_value(a / b);
  T r = a - n * b;
  return select(r < T(0.0), r + b, r);
}

// hfA_RGBToHSV(in, out): out = (h in degrees, s, v) of the colour in[1..3].
template<class T, class Ctx>
T a_rgb_to_hsv(std::span<Arg<T>> args, Ctx&)
{
  auto rgb = args[0].array;
  auto hsv = args[1].array;
  T r = at(rgb, 0);
  T g = at(rgb, 1);
  T b = at(rgb, 2);
  T gb_min = select(g < b, g, b);
  T themin = select(r < gb_min, r, gb_min);
  T gb_max = select(g > b, g, b);
  T themax = select(r > gb_max, r, gb_max);
  T delta = themax - themin;
  T v = themax;
  T s = select(themax > T(0.0), delta / themax, T(0.0));
  T h = T(0.0);
  auto is_r = logical_and(detail::equal(themax, r), logical_not(detail::equal(themax, g)));
  h = select(is_r, h + (g - b) / delta, h);
  auto is_g = logical_and(detail::equal(themax, g), logical_not(detail::equal(themax, b)));
  h = select(is_g, h + (2.0 + (b - r) / delta), h);
  auto is_b = logical_and(detail::equal(themax, b), logical_not(detail::equal(themax, r)));
  h = select(is_b, h + (4.0 + (r - g) / delta), h);
  h = select(delta > T(0.0), h * 60.0, T(0.0));
  put(hsv, 0, h);
  put(hsv, 1, s);
  put(hsv, 2, v);
  return T(1.0);
}

} // namespace frep::library
