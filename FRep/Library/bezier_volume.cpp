// hfBezierVolume: a trivariate Bezier function R-intersected with its bounding box. Double-only
// (loop counts come from the values l, m, n). The original fills Bernstein buffers allocated
// once per process for the first call's (l, m, n); here they are computed per call, which is
// the same for every call the original handles correctly.
#include "Library/detail/array_access.h"
#include "Library/detail/library_double.h"

#include <cmath>
#include <limits>
#include <vector>

namespace frep::library
{
namespace
{

/// The original's binomial table Combin[21][21] covers degrees 0..20; it has no entries beyond.
constexpr int kMaxDegree = 20;

double binomial(int n, int i)
{
  double c = 1.0; // exact: every intermediate value is an integer below 2^53 for n <= 20
  for (int k = 1; k <= i; ++k)
  {
    c = c * (n - i + k) / k;
  }
  return c;
}

double bernstein(int i, int n, double t)
{
  return binomial(n, i) * std::pow((1. - t), n - i) * std::pow(t, i);
}

/// The original's R_int: x + y - sqrt(x^2 + y^2).
double r_intersection(double x, double y)
{
  return (x) + (y)-std::sqrt((x * x) + (y * y));
}

} // namespace

// hfBezierVolume(x, l, m, n, bbox, w): control value w[i*m*n + j*n + k]; the code pairs j (m)
// with z and k (n) with y. Degrees above 20 (outside the original's table) give NaN.
double bezier_volume(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  const int l = c_int(args[1].real);
  const int m = c_int(args[2].real);
  const int n = c_int(args[3].real);
  auto bbox = args[4].array;
  auto ctr = args[5].array;
  if (x.size() != 3)
  {
    return kWrongDimension;
  }
  if (l - 1 > kMaxDegree || m - 1 > kMaxDegree || n - 1 > kMaxDegree)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double xt = (x[0] - at(bbox, 0)) / (at(bbox, 3) - at(bbox, 0));
  double yt = (x[1] - at(bbox, 1)) / (at(bbox, 4) - at(bbox, 1));
  double zt = (x[2] - at(bbox, 2)) / (at(bbox, 5) - at(bbox, 2));
  std::vector<double> bu(l > 0 ? l : 0);
  std::vector<double> bv(m > 0 ? m : 0);
  std::vector<double> bw(n > 0 ? n : 0);
  for (int i = 0; i < l; ++i)
  {
    bu[i] = bernstein(i, l - 1, xt);
  }
  for (int j = 0; j < m; ++j)
  {
    bv[j] = bernstein(j, m - 1, zt);
  }
  for (int k = 0; k < n; ++k)
  {
    bw[k] = bernstein(k, n - 1, yt);
  }
  double value = 0.0;
  for (int i = 0; i < l; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      for (int k = 0; k < n; ++k)
      {
        const std::int64_t index = static_cast<std::int64_t>(i) * m * n + j * n + k;
        value = value + (bu[i] * bv[j] * bw[k] * at(ctr, index));
      }
    }
  }
  xt = (at(bbox, 3) - x[0]) * (x[0] - at(bbox, 0));
  yt = (at(bbox, 4) - x[1]) * (x[1] - at(bbox, 1));
  zt = (at(bbox, 5) - x[2]) * (x[2] - at(bbox, 2));
  const double cube = r_intersection(r_intersection(xt, yt), zt);
  return r_intersection(cube, value);
}

} // namespace frep::library
