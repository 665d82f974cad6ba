// hfA_Crackles and hfA_Circles: a procedural pattern value mapped through a piecewise-constant
// table (input_map thresholds, input_attr rows of size(output) values). Double-only (table
// search). Both write 1.1 into input_attr[n_map] (0-based) before the search, as the original
// does, so the search can read it back.
#include "Library/detail/array_access.h"
#include "Library/detail/library_double.h"

#include <cmath>

namespace frep::library
{
namespace
{

constexpr double kPi = 3.1415926535897932384626; // M_PI as pattern.h defines it

/// pattern.h Noise(): the Gardner series with amplitude 1, normalised to [0, 1].
double gardner_noise(double xt, double yt, double zt, double phase, double a2)
{
  const double a1 = 1.0;
  const double a2x = a2 * xt;
  const double a2y = a2 * yt;
  const double a2z = a2 * zt;
  const double sx = std::sin(a2x);
  const double sy = std::sin(a2y);
  const double sz = std::sin(a2z);
  const double a1d = a1 / 1.17;
  const double sx2 = a1d * std::sin(a2x / 1.35 + phase * sz);
  const double sy2 = a1d * std::sin(a2y / 1.35 + phase * sx);
  const double sz2 = a1d * std::sin(a2z / 1.35 + phase * sy);
  const double serx = a1 * sx + sx2;
  const double sery = a1 * sy + sy2;
  const double serz = a1 * sz + sz2;
  double ss = serx * sery * serz;
  const double c = 2.17 / 1.17;
  const double c_min = std::pow(-a1 * c, 3);
  const double c_max = -c_min;
  ss = (ss - c_min) / (c_max - c_min);
  return ss;
}

/// pattern.h cycle(): the fractional part quantised to 1/1000, through a sine.
double cycle(double value)
{
  const int i = c_int((value - std::floor(value)) * 1000.0);
  return (1.0 + std::sin(static_cast<double>(i) * 2.0 * kPi / 1000.0)) / 2.0;
}

double crackles_value(double xt, double yt, double zt, double phase, double freq)
{
  const double noise_x = -1 + (gardner_noise(xt, xt, zt, phase, freq) * 2.0);
  const double noise_y = -1 + (gardner_noise(yt, yt, xt, phase, freq) * 2.0);
  const double noise_z = -1 + (gardner_noise(zt, zt, yt, phase, freq) * 2.0);
  return cycle(noise_x + noise_y + noise_z);
}

/// output = row i of the colour table.
void copy_row(std::span<double> output, std::span<double> colors, std::int64_t row)
{
  const std::int64_t width = size_of(output);
  for (std::int64_t j = 0; j < width; ++j)
  {
    output[j] = at(colors, width * row + j);
  }
}

} // namespace

// hfA_Crackles(x, output, freq, input_attr, input_map): every matching interval is applied
// (the original has no break here, unlike hfA_Circles).
double a_crackles(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  auto output = args[1].array;
  const double freq = args[2].real;
  auto colors = args[3].array;
  auto map = args[4].array;
  const double xt = at(x, 0);
  const double yt = at(x, 1);
  const double zt = at(x, 2);
  const double phase = (std::sqrt(xt * xt) + std::sqrt(yt * yt) + std::sqrt(zt * zt)) / 3.0;
  const double noise = crackles_value(xt, yt, zt, phase, freq);
  const std::int64_t n_map = size_of(map);
  put(colors, n_map, 1.0 + 0.1);
  for (std::int64_t i = 0; i < n_map - 1; ++i)
  {
    if ((noise >= map[i]) && (noise < map[i + 1]))
    {
      copy_row(output, colors, i);
    }
  }
  return 1.0;
}

// hfA_Circles(x, output, input_attr, input_map): concentric unit rings, fmod(|x|, 1).
double a_circles(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  auto output = args[1].array;
  auto colors = args[2].array;
  auto map = args[3].array;
  const double xt = at(x, 0) * at(x, 0);
  const double yt = at(x, 1) * at(x, 1);
  const double zt = at(x, 2) * at(x, 2);
  const double noise = std::fmod(std::sqrt(xt + yt + zt), 1.0);
  const std::int64_t n_map = size_of(map);
  put(colors, n_map, 1.0 + 0.1);
  for (std::int64_t i = 0; i < n_map - 1; ++i)
  {
    if ((noise >= map[i]) && (noise < map[i + 1]))
    {
      copy_row(output, colors, i);
      break;
    }
  }
  return 1.0;
}

} // namespace frep::library
