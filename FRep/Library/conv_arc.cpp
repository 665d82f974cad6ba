// hfConvArc: convolution of the Cauchy kernel along circular arcs (closed form). Double-only:
// it branches on values (arcs over 180 degrees are split, the sign of p2 picks atan or atanh)
// and writes back into the caller's arrays, as the original does:
//   angle[i] += EPS on every call, theta[i] clamped to 360 and then set to 180 when larger.
// It keeps the original's own constants: PI = 3.141592 and atanh(z) = log((1+z) sqrt(1/(1-z^2)))
// (archyp.h), not the C library's atanh.
#include "Library/detail/array_access.h"
#include "Library/detail/library_double.h"

#include <cmath>

namespace frep::library
{
namespace
{

constexpr double kArcPi = 3.141592;

double sq(double v)
{
  return v * v;
}

double qu(double v)
{
  return sq(v) * sq(v);
}

double arc_atanh(double z)
{
  return std::log((1 + z) * std::sqrt(1 / (1 - (z * z))));
}

/// Field of an arc of angle th (radians) and radius r in its own frame (x, y, z), width s.
double arc_field(double x, double y, double z, double th, double r, double s)
{
  double a = 2.0 * r * s * s;
  double d2 = sq(x) + sq(y) + sq(z);
  double b = 1.0 + sq(r) * sq(s) + sq(s) * d2;
  double p2 = -qu(r) * qu(s) + 2.0 * sq(r) * sq(s) * (sq(s) * (d2 - 2.0 * sq(z)) - 1.0) -
              sq(1.0 + sq(s) * d2);
  double p1 = (p2 < 0.0) ? std::sqrt(-p2) : std::sqrt(p2);
  double p3 = p1 * p2;
  double f1 =
    (b * y) / (x * p2 * (a * x - b)) + (a * (sq(x) + sq(y)) * std::sin(th) - b * y) /
                                         (x * p2 * (a * (x * std::cos(th) + y * std::sin(th)) - b));
  double f2;
  if (p2 < 0.0)
  {
    f2 = 2.0 * b *
         (std::atan(-a * y / p1) + std::atan((a * y - (a * x + b) * std::tan(th / 2.0)) / p1)) / p3;
  }
  else
  {
    f2 = 2.0 * b *
         (arc_atanh(a * y / p1) + arc_atanh(((a * x + b) * std::tan(th / 2.0) - a * y) / p1)) / p3;
  }
  return f1 + f2;
}

/// Rotation about the unit axis (i, j, k) with cosine c and sine s (Rodrigues' matrix, in the
/// original's term order), applied to (px, py, pz).
struct Rotation
{
  double c, s, one_c, ii, jj, kk, ij, jk, ki, is, js, ks;

  Rotation(double i, double j, double k, double cosine, double sine)
    : c(cosine)
    , s(sine)
    , one_c(1.0 - cosine)
    , ii(i * i)
    , jj(j * j)
    , kk(k * k)
    , ij(i * j)
    , jk(j * k)
    , ki(k * i)
    , is(i * sine)
    , js(j * sine)
    , ks(k * sine)
  {
  }

  void apply(double px, double py, double pz, double& ox, double& oy, double& oz) const
  {
    ox = (c + ii * one_c) * px + (-ks + ij * one_c) * py + (js + ki * one_c) * pz;
    oy = (ks + ij * one_c) * px + (c + jj * one_c) * py + (-is + jk * one_c) * pz;
    oz = (-js + ki * one_c) * px + (is + jk * one_c) * py + (c + kk * one_c) * pz;
  }
};

} // namespace

// hfConvArc(x, center, radius, theta, axis, angle, S, T): N = size(S) arcs.
double conv_arc(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  auto center = args[1].array;
  auto radius = args[2].array;
  auto theta = args[3].array;
  auto axis = args[4].array;
  auto angle = args[5].array;
  auto s_width = args[6].array;
  if (x.size() != 3)
  {
    return kWrongDimension;
  }
  const double rd = kArcPi / 180.0;
  double f = 0.0;
  for (std::int64_t n = 0; n < size_of(s_width); ++n)
  {
    const double s = s_width[n];
    const double cx = at(center, 3 * n);
    const double cy = at(center, 3 * n + 1);
    const double cz = at(center, 3 * n + 2);
    const double r = at(radius, n);
    const double ang = at(angle, n) + kEps; // "avoid error", written back to the caller
    put(angle, n, ang);
    double i = at(axis, 3 * n) + kEps;
    double j = at(axis, 3 * n + 1) + kEps;
    double k = at(axis, 3 * n + 2) + kEps;
    double length = std::sqrt(i * i + j * j + k * k);
    if (length < kEps)
    {
      length = kEps;
    }
    i /= length;
    j /= length;
    k /= length;
    const Rotation rot(i, j, k, std::cos(rd * (-ang)), std::sin(rd * (-ang)));
    const double px = x[0] - cx;
    const double py = x[1] - cy;
    const double pz = x[2] - cz;

    double th_deg = at(theta, n);
    if (th_deg > 360.0)
    {
      th_deg = 360.0;
      put(theta, n, th_deg);
    }
    if (th_deg > 180.0)
    {
      // The part beyond 180 degrees: the same field, in the frame rotated by -PI about z.
      const double over_th = (th_deg - 180.0) * rd;
      th_deg = 180.0;
      put(theta, n, th_deg);
      double tx, ty, tz;
      rot.apply(px, py, pz, tx, ty, tz);
      const Rotation over(0.0, 0.0, 1.0, std::cos(rd * (-180.0)), std::sin(rd * (-180.0)));
      double ox, oy, oz;
      over.apply(tx, ty, tz, ox, oy, oz);
      f += arc_field(ox, oy, oz, over_th, r, s);
    }
    const double th = th_deg * rd;
    double nx, ny, nz;
    rot.apply(px, py, pz, nx, ny, nz);
    f += arc_field(nx, ny, nz, th, r, s);
  }
  return f - args[7].real;
}

} // namespace frep::library
