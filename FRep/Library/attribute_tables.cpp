// Table-driven attribute functions: hfA_LookUpTable, hfA_SmoothLookUpTable (piecewise constant /
// linear colour maps) and hfA_Spline (Catmull-Rom through a list of colours). Double-only (the
// table row is chosen by value). The original's quirks are kept: below the first map entry the
// lookup tables end up with the LAST row (the first-row copy is overwritten because no interval
// matched), and hfA_Spline at v = vmax evaluates span nspans-3 at x = 3.
#include "Library/detail/array_access.h"
#include "Library/detail/library_double.h"

namespace frep::library
{
namespace
{

template<bool Smooth>
double lookup(DoubleArgs args)
{
  const double t = args[0].real;
  auto output = args[1].array;
  auto colors = args[2].array;
  auto entry = args[3].array;
  const std::int64_t width = size_of(output);
  const std::int64_t n_entries = size_of(entry);
  bool filled = false;
  if (t < at(entry, 0))
  {
    for (std::int64_t j = 0; j < width; ++j)
    {
      output[j] = at(colors, j);
    }
  }
  else
  {
    for (std::int64_t i = 0; i < n_entries - 1; ++i)
    {
      if ((t >= entry[i]) && (t < entry[i + 1]))
      {
        filled = true;
        if constexpr (Smooth)
        {
          const double l = (t - entry[i]) / (entry[i + 1] - entry[i]);
          for (std::int64_t j = 0; j < width; ++j)
          {
            output[j] = (1 - l) * at(colors, width * i + j) + (l)*at(colors, width * (i + 1) + j);
          }
        }
        else
        {
          for (std::int64_t j = 0; j < width; ++j)
          {
            output[j] = at(colors, width * i + j);
          }
        }
        break;
      }
    }
  }
  if (!filled)
  {
    for (std::int64_t j = 0; j < width; ++j)
    {
      output[j] = at(colors, width * (n_entries - 1) + j);
    }
  }
  return 1.0;
}

} // namespace

// hfA_LookUpTable(t, output, input_attr, input_map)
double a_lookup_table(DoubleArgs args, DoubleContext&)
{
  return lookup<false>(args);
}

// hfA_SmoothLookUpTable(t, output, input_attr, input_map)
double a_smooth_lookup_table(DoubleArgs args, DoubleContext&)
{
  return lookup<true>(args);
}

// hfA_Spline(s, list, v, vmin, vmax): list holds size(list)/size(s) knots of size(s) values.
double a_spline(DoubleArgs args, DoubleContext&)
{
  // Catmull-Rom basis rows as the original's CRij macros.
  constexpr double cr[4][4] = { { -0.5, 1.5, -1.5, 0.5 },
    { 1.0, -2.5, 2.0, -0.5 },
    { -0.5, 0.0, 0.5, 0.0 },
    { 0.0, 1.0, 0.0, 0.0 } };
  auto s = args[0].array;
  auto knot = args[1].array;
  const double xmin = args[3].real;
  const double xmax = args[4].real;
  const std::int64_t n = size_of(s);
  if (n == 0)
  {
    return 1.0;
  }
  const std::int64_t size = size_of(knot) / n;
  double x = (args[2].real - xmin) / (xmax - xmin);
  if (x < 0.0)
  {
    for (std::int64_t i = 0; i < n; ++i)
    {
      s[i] = at(knot, i);
    }
  }
  else if (x > 1.0)
  {
    for (std::int64_t i = 0; i < n; ++i)
    {
      s[i] = at(knot, (size - 1) * n + i);
    }
  }
  else
  {
    const std::int64_t nspans = size - 3;
    x = x * static_cast<double>(nspans);
    std::int64_t span = c_int(x);
    if (span >= nspans)
    {
      span = nspans - 3;
    }
    x -= static_cast<double>(span);
    for (std::int64_t i = 0; i < n; ++i)
    {
      double c[4];
      for (int row = 0; row < 4; ++row)
      {
        c[row] =
          cr[row][0] * at(knot, (span + 0) * n + i) + cr[row][1] * at(knot, (span + 1) * n + i) +
          cr[row][2] * at(knot, (span + 2) * n + i) + cr[row][3] * at(knot, (span + 3) * n + i);
      }
      // c[0] is the original's c3 (cubic coefficient) ... c[3] its c0.
      s[i] = ((c[0] * x + c[1]) * x + c[2]) * x + c[3];
    }
  }
  return 1.0;
}

} // namespace frep::library
