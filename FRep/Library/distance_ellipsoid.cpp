// hfDEllipsoid: signed Euclidean distance to an ellipsoid (> 0 inside), by Newton iteration on
// the closest-point parameter t, as the original: at most 128 steps, stop when |s(t)| < 1e-6.
#include "Library/detail/array_access.h"
#include "Library/detail/library_double.h"

#include <cmath>

namespace frep::library
{

// hfDEllipsoid(x, center, a, b, c)
double distance_ellipsoid(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  auto center = args[1].array;
  const double a = args[2].real;
  const double b = args[3].real;
  const double c = args[4].real;
  if (x.size() != 3 || (std::fabs(a) < kEps) || (std::fabs(b) < kEps) || (std::fabs(c) < kEps))
  {
    return kWrongDimension;
  }
  const double cx = at(center, 0);
  const double cy = at(center, 1);
  const double cz = at(center, 2);
  const double xx = x[0] - cx;
  const double yy = x[1] - cy;
  const double zz = x[2] - cz;
  const double a2 = a * a;
  const double b2 = b * b;
  const double c2 = c * c;
  const double u2 = xx * xx;
  const double v2 = yy * yy;
  const double w2 = zz * zz;
  const double a2u2 = a2 * u2;
  const double b2v2 = b2 * v2;
  const double c2w2 = c2 * w2;
  const double uratio = xx / a;
  const double vratio = yy / b;
  const double wratio = zz / c;
  const double length = std::sqrt(xx * xx + yy * yy + zz * zz);
  double t;
  bool inside;
  if (uratio * uratio + vratio * vratio + wratio * wratio < 1.0)
  {
    t = 0.0;
    inside = true;
  }
  else
  {
    double max = a;
    if (b > max)
    {
      max = b;
    }
    if (c > max)
    {
      max = c;
    }
    t = max * length;
    inside = false;
  }
  constexpr int kMaxIteration = 128;
  constexpr double kEpsilon = 1e-6;
  for (int i = 0; i < kMaxIteration; ++i)
  {
    const double p = t + a2;
    const double q = t + b2;
    const double r = t + c2;
    const double p2 = p * p;
    const double q2 = q * q;
    const double r2 = r * r;
    const double s = p2 * q2 * r2 - a2u2 * q2 * r2 - b2v2 * p2 * r2 - c2w2 * p2 * q2;
    if (std::fabs(s) < kEpsilon)
    {
      break;
    }
    const double pq = p * q;
    const double pr = p * r;
    const double qr = q * r;
    const double pqr = p * q * r;
    const double ds = 2.0 * (pqr * (qr + pr + pq) - a2u2 * qr * (q + r) - b2v2 * pr * (p + r) -
                              c2w2 * pq * (p + q));
    t -= s / ds;
  }
  const double closestx = (a2 * x[0] + t * cx) / (t + a2);
  const double closesty = (b2 * x[1] + t * cy) / (t + b2);
  const double closestz = (c2 * x[2] + t * cz) / (t + c2);
  const double diffx = closestx - x[0];
  const double diffy = closesty - x[1];
  const double diffz = closestz - x[2];
  const double distance = std::sqrt(diffx * diffx + diffy * diffy + diffz * diffz);
  return inside ? distance : -distance;
}

} // namespace frep::library
