// Convolution surfaces with the Cauchy kernel along segments and triangles (hfConvLine,
// hfConvCurve, hfConvLineR, hfConvTriangle, hfConvMesh). Double-only: a zero-length segment
// aborts the program (the original calls error()), and the triangle code reorders vertices by
// edge length. Expressions keep the original's grouping for bit-identical values.
#include "Library/detail/array_access.h"
#include "Library/detail/library_double.h"

#include <cmath>
#include <limits>

namespace frep::library
{
namespace
{

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double sq(double v)
{
  return v * v;
}

/// Field of one segment b -> e (length l, already known non-zero) at x, kernel width s.
double segment_field(const double b[3], const double e[3], double l, std::span<double> x, double s)
{
  double ax = (e[0] - b[0]) / l;
  double ay = (e[1] - b[1]) / l;
  double az = (e[2] - b[2]) / l;
  double dx = x[0] - b[0];
  double dy = x[1] - b[1];
  double dz = x[2] - b[2];
  double xx = dx * ax + dy * ay + dz * az;
  double p = std::sqrt(1 + s * s * (dx * dx + dy * dy + dz * dz - xx * xx));
  double q = std::sqrt(1 + s * s * (dx * dx + dy * dy + dz * dz + l * l - 2 * l * xx));
  return xx / (2 * p * p * (p * p + s * s * xx * xx)) + (l - xx) / (2 * p * p * q * q) +
         (std::atan(s * xx / p) + std::atan(s * (l - xx) / p)) / (2 * s * p * p * p);
}

double length(const double b[3], const double e[3])
{
  return std::sqrt(sq(e[0] - b[0]) + sq(e[1] - b[1]) + sq(e[2] - b[2]));
}

/// Field of one triangle a1 a2 a3 (9 coordinates) at x with kernel width s: the term the
/// original adds, (arc1 + arc2 + arc3) / (2 q S).
double triangle_field(const double vertices[9], std::span<double> x, double s)
{
  double a1x = vertices[0], a1y = vertices[1], a1z = vertices[2];
  double a2x = vertices[3], a2y = vertices[4], a2z = vertices[5];
  double a3x = vertices[6], a3y = vertices[7], a3z = vertices[8];
  double len0 = std::sqrt(sq(a2x - a1x) + sq(a2y - a1y) + sq(a2z - a1z));
  double len1 = std::sqrt(sq(a3x - a2x) + sq(a3y - a2y) + sq(a3z - a2z));
  double len2 = std::sqrt(sq(a1x - a3x) + sq(a1y - a3y) + sq(a1z - a3z));
  // Make a1-a2 the longest edge (so the foot of the height lies on it).
  if ((len1 >= len2) && (len1 > len0))
  {
    double tx = a1x, ty = a1y, tz = a1z;
    a1x = a2x, a1y = a2y, a1z = a2z;
    a2x = a3x, a2y = a3y, a2z = a3z;
    a3x = tx, a3y = ty, a3z = tz;
  }
  else if ((len2 >= len1) && (len2 > len0))
  {
    double tx = a1x, ty = a1y, tz = a1z;
    a1x = a3x, a1y = a3y, a1z = a3z;
    a3x = a2x, a3y = a2y, a3z = a2z;
    a2x = tx, a2y = ty, a2z = tz;
  }
  len0 = std::sqrt(sq(a2x - a1x) + sq(a2y - a1y) + sq(a2z - a1z));
  double a21x = a2x - a1x;
  double a21y = a2y - a1y;
  double a21z = a2z - a1z;
  double a13x = a1x - a3x;
  double a13y = a1y - a3y;
  double a13z = a1z - a3z;
  double t = -(a21x * a13x + a21y * a13y + a21z * a13z) / sq(len0);
  double bx = a1x + t * a21x;
  double by = a1y + t * a21y;
  double bz = a1z + t * a21z;
  double dx = x[0] - bx;
  double dy = x[1] - by;
  double dz = x[2] - bz;
  double ux = a2x - bx;
  double uy = a2y - by;
  double uz = a2z - bz;
  double ul = std::sqrt(sq(ux) + sq(uy) + sq(uz));
  ux = ux / ul;
  uy = uy / ul;
  uz = uz / ul;
  double vx = a3x - bx;
  double vy = a3y - by;
  double vz = a3z - bz;
  double vl = std::sqrt(sq(vx) + sq(vy) + sq(vz));
  vx = vx / vl;
  vy = vy / vl;
  vz = vz / vl;
  double d2 = sq(dx) + sq(dy) + sq(dz);
  double u = dx * ux + dy * uy + dz * uz;
  double v = dx * vx + dy * vy + dz * vz;
  double h = std::sqrt(sq(a3x - bx) + sq(a3y - by) + sq(a3z - bz));
  double a1 = std::sqrt(sq(a1x - bx) + sq(a1y - by) + sq(a1z - bz));
  double a2 = std::sqrt(sq(a2x - bx) + sq(a2y - by) + sq(a2z - bz));
  double g = v - h;
  double m = a2 * g + u * h;
  double k = u * h - a1 * g;
  double c2 = 1.0 / (sq(s)) + d2 - sq(u);
  double c = std::sqrt(c2);
  double q = c2 - sq(v);
  double w = c2 - 2.0 * v * h + sq(h);
  double big_a2 = sq(a1) * w + sq(h) * (q + sq(u)) - 2.0 * a1 * h * u * g;
  double big_a = std::sqrt(big_a2);
  double big_b2 = sq(a2) * w + sq(h) * (q + sq(u)) + 2.0 * a2 * h * u * g;
  double big_b = std::sqrt(big_b2);
  double n1 = a1 + u;
  double n2 = a2 - u;
  double n3 = a1 * n1 + v * h;
  double n4 = -a1 * u - g * h;
  double n5 = -a2 * n2 - v * h;
  double n6 = -a2 * u + g * h;
  double arc1 = k * (std::atan(n3 / big_a) + std::atan(n4 / big_a)) / big_a;
  double arc2 = m * (std::atan(n5 / big_b) + std::atan(n6 / big_b)) / big_b;
  double arc3 = v * (std::atan(n1 / c) + std::atan(n2 / c)) / c;
  return (arc1 + arc2 + arc3) / (2.0 * q * s);
}

} // namespace

// hfConvLine(x, begin, end, S, T): N = size(S) segments.
double conv_line(DoubleArgs args, DoubleContext& ctx)
{
  auto x = args[0].array;
  auto begin = args[1].array;
  auto end = args[2].array;
  auto s = args[3].array;
  if (x.size() != 3)
  {
    return kWrongDimension;
  }
  double f = 0.0;
  for (std::int64_t n = 0; n < size_of(s); ++n)
  {
    const double b[3] = { at(begin, 3 * n), at(begin, 3 * n + 1), at(begin, 3 * n + 2) };
    const double e[3] = { at(end, 3 * n), at(end, 3 * n + 1), at(end, 3 * n + 2) };
    double l = length(b, e);
    if (l == 0.0)
    {
      ctx.abort_if(true, "ERROR:Tips of the segment take same coordinate!");
      return kNaN;
    }
    f += segment_field(b, e, l, x, s[n]);
  }
  return f - args[4].real;
}

// hfConvCurve(x, vect, S, T): the polyline through N + 1 points of vect, N = size(S). (Its
// error text has no "ERROR:" prefix in the original.)
double conv_curve(DoubleArgs args, DoubleContext& ctx)
{
  auto x = args[0].array;
  auto vect = args[1].array;
  auto s = args[2].array;
  if (x.size() != 3)
  {
    return kWrongDimension;
  }
  double f = 0.0;
  for (std::int64_t n = 0; n < size_of(s); ++n)
  {
    const double b[3] = { at(vect, 3 * n), at(vect, 3 * n + 1), at(vect, 3 * n + 2) };
    const double e[3] = {
      at(vect, 3 * (n + 1)), at(vect, 3 * (n + 1) + 1), at(vect, 3 * (n + 1) + 2)
    };
    double l = length(b, e);
    if (l == 0.0)
    {
      ctx.abort_if(true, "Tips of the segment take same coordinate!");
      return kNaN;
    }
    f += segment_field(b, e, l, x, s[n]);
  }
  return f - args[3].real;
}

// hfConvLineR(x, begin, end, R): S = 1/R for R < 1 (else 1); the running sum stops growing
// at 1 and the field value of the last segment at distance R is subtracted. N = size(end)/3.
double conv_line_r(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  auto begin = args[1].array;
  auto end = args[2].array;
  const double r = args[3].real;
  double s = 1.0;
  if (r < 1)
  {
    s = 1 / r;
  }
  if (x.size() != 3)
  {
    return kWrongDimension;
  }
  const std::int64_t count = size_of(end) / 3;
  double threshold = 0;
  double f = 0.0;
  for (std::int64_t n = 0; n < count; ++n)
  {
    const double b[3] = { at(begin, 3 * n), at(begin, 3 * n + 1), at(begin, 3 * n + 2) };
    const double e[3] = { end[3 * n], end[3 * n + 1], end[3 * n + 2] };
    double l = length(b, e);
    double ax = (e[0] - b[0]) / l;
    double ay = (e[1] - b[1]) / l;
    double az = (e[2] - b[2]) / l;
    double dx = x[0] - b[0];
    double dy = x[1] - b[1];
    double dz = x[2] - b[2];
    double p_t = std::sqrt(1 + sq(s) * sq(r));
    double q_t2 = 1 + sq(s) * (sq(r) + sq(l));
    threshold = l / (2.0 * sq(p_t) * q_t2) + (std::atan(s * l / p_t)) / (2.0 * s * sq(p_t) * p_t);
    double xx = dx * ax + dy * ay + dz * az;
    double p = std::sqrt(1 + sq(s) * (sq(dx) + sq(dy) + sq(dz) - sq(xx)));
    double q2 = 1 + sq(s) * (sq(dx) + sq(dy) + sq(dz) + sq(l) - 2.0 * l * xx);
    double f_tmp = xx / (2.0 * p * p * (p * p + s * s * xx * xx)) + (l - xx) / (2.0 * p * p * q2) +
                   (std::atan(s * xx / p) + std::atan(s * (l - xx) / p)) / (2.0 * s * p * p * p);
    if (f < 1.0)
    {
      f = f + f_tmp;
      if (f > 1.0)
      {
        f = 1.0;
      }
    }
  }
  return f - threshold;
}

// hfConvTriangle(x, vect, S, T): N = size(S) triangles, 9 coordinates each in vect.
double conv_triangle(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  auto vect = args[1].array;
  auto s = args[2].array;
  if (x.size() != 3)
  {
    return kWrongDimension;
  }
  double f = 0.0;
  for (std::int64_t n = 0; n < size_of(s); ++n)
  {
    double vertices[9];
    for (int k = 0; k < 9; ++k)
    {
      vertices[k] = at(vect, 9 * n + k);
    }
    f += triangle_field(vertices, x, s[n]);
  }
  return f - args[3].real;
}

// hfConvMesh(x, vect, tri, S, T): N = size(S) triangles whose corners are 1-based vertex
// indices (tri, truncated like C's (int)) into the coordinate list vect.
double conv_mesh(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  auto vect = args[1].array;
  auto tri = args[2].array;
  auto s = args[3].array;
  if (x.size() != 3)
  {
    return kWrongDimension;
  }
  double f = 0.0;
  for (std::int64_t n = 0; n < size_of(s); ++n)
  {
    double vertices[9];
    for (int corner = 0; corner < 3; ++corner)
    {
      const std::int64_t base = 3 * (static_cast<std::int64_t>(c_int(at(tri, 3 * n + corner))) - 1);
      for (int k = 0; k < 3; ++k)
      {
        vertices[3 * corner + k] = at(vect, base + k);
      }
    }
    f += triangle_field(vertices, x, s[n]);
  }
  return f - args[4].real;
}

} // namespace frep::library
