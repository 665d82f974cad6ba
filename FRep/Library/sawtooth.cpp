// hfSawtooth: truncated Fourier series of a sawtooth wave. Double-only: the number of terms is
// the value (int)n.
#include "Library/detail/array_access.h"
#include "Library/detail/library_double.h"

#include <cmath>

namespace frep::library
{

// hfSawtooth(t, n, a, f) = (2 / (a pi)) (0.5 - sum_{k=1}^{n-1} sin(2 pi k f t) / k); 0 if n <= 1.
double sawtooth(DoubleArgs args, DoubleContext&)
{
  constexpr double kPi = 3.1415926535897932384626; // M_PI as myfunc.c defines it
  const double t = args[0].real;
  const int n = c_int(args[1].real);
  const double a = args[2].real;
  const double f = args[3].real;
  double res = 0.5;
  if (n <= 1)
  {
    return 0.0;
  }
  for (int ni = 1; ni < n; ++ni)
  {
    const double di = static_cast<double>(ni);
    res -= std::sin(2 * kPi * di * f * t) / di;
  }
  res *= (2 / (a * kPi));
  return res;
}

} // namespace frep::library
