// hfA_HSVToRGB. Double-only: the hue is wrapped into [0, 360] by repeated +-360 steps, as the
// original's while loops do (bit for bit). Where those loops could not terminate in reasonable
// time (|h| beyond 360 * 2^20, or non-finite h: the original loops forever on -inf/+inf), the
// hue is reduced with fmod instead.
#include "Library/detail/array_access.h"
#include "Library/detail/library_double.h"

#include <cmath>

namespace frep::library
{

// hfA_HSVToRGB(in, out): in = (h degrees, s, v), out = (r, g, b).
double a_hsv_to_rgb(DoubleArgs args, DoubleContext&)
{
  auto hsv = args[0].array;
  auto rgb = args[1].array;
  double h = at(hsv, 0);
  const double s = at(hsv, 1);
  const double v = at(hsv, 2);
  constexpr double kStepLimit = 360.0 * 1048576.0;
  if (!(std::fabs(h) <= kStepLimit))
  {
    h = std::isfinite(h) ? std::fmod(h, 360.0) : 0.0;
  }
  while (h < 0.0)
  {
    h += 360.0;
  }
  while (h > 360.0)
  {
    h -= 360.0;
  }
  double r, g, b;
  if (h < 120.0)
  {
    r = (120.0 - h) / 60.0;
    g = h / 60.0;
    b = 0;
  }
  else if (h < 240.0)
  {
    r = 0;
    g = (240.0 - h) / 60.0;
    b = (h - 120.0) / 60.0;
  }
  else
  {
    r = (h - 240.0) / 60.0;
    g = 0;
    b = (360.0 - h) / 60.0;
  }
  r = (r < 1) ? r : 1;
  g = (g < 1) ? g : 1;
  b = (b < 1) ? b : 1;
  put(rgb, 0, (1.0 - s + s * r) * v);
  put(rgb, 1, (1.0 - s + s * g) * v);
  put(rgb, 2, (1.0 - s + s * b) * v);
  return 1.0;
}

} // namespace frep::library
