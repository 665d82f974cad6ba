#include "Sample/grid.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace frep
{

GridSpec box_grid(std::span<const double> lo,
  std::span<const double> hi,
  std::span<const std::int64_t> samples)
{
  GridSpec grid;
  grid.axes.resize(lo.size());
  for (std::size_t k = 0; k < lo.size(); ++k)
  {
    GridAxis& axis = grid.axes[k];
    axis.lo = lo[k];
    axis.hi = k < hi.size() ? hi[k] : axis.hi;
    axis.samples = k < samples.size() ? samples[k] : axis.samples;
  }
  return grid;
}

std::string check_grid_axes(const GridSpec& grid, std::int64_t min_samples)
{
  std::ostringstream message;
  for (std::size_t a = 0; a < grid.axes.size(); ++a)
  {
    const GridAxis& axis = grid.axes[a];
    if (axis.samples < min_samples)
    {
      message << "grid: at least " << min_samples << " sample"
              << (min_samples == 1 ? " is" : "s are") << " needed on every axis (axis " << a
              << " has " << axis.samples << ")";
      return message.str();
    }
    const double step = axis.step();
    if (!std::isfinite(axis.lo) || !std::isfinite(axis.hi) || !std::isfinite(step) || !(step > 0.0))
    {
      message << "grid: axis " << a << ": cannot place " << axis.samples << " samples in ["
              << axis.lo << ", " << axis.hi << "] ("
              << (axis.samples > 1 ? "the box's minimum must be less than its maximum, both finite"
                                   : "not finite")
              << ")";
      return message.str();
    }
    const std::int64_t end = axis.part_end();
    if (axis.begin < 0 || end - axis.begin < min_samples || end > axis.samples)
    {
      message << "grid: axis " << a << ": the part [" << axis.begin << ", " << end
              << ") is not a range of at least " << min_samples << " of the samples [0, "
              << axis.samples << ")";
      return message.str();
    }
  }
  return {};
}

std::string check_grid_size(std::span<const std::int64_t> samples, double limit,
  const char* option)
{
  double total = 1.0;
  for (const std::int64_t n : samples)
  {
    total *= static_cast<double>(n);
  }
  // Indices are 64-bit and the mesher keys a grid edge as vertex * 4 + axis.
  limit = std::min(limit, 1e18);
  if (total <= limit)
  {
    return {};
  }
  std::ostringstream message;
  message << "grid: ";
  for (std::size_t a = 0; a < samples.size(); ++a)
  {
    message << (a == 0 ? "" : " x ") << samples[a];
  }
  message << " = " << total << " samples is more than the limit of " << limit << " (" << option
          << ")";
  return message.str();
}

} // namespace frep
