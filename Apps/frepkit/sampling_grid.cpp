#include "sampling_grid.h"

#include "Mesh/coordinate_bounds.h"
#include "Mesh/solid_bounds.h"
#include "number_format.h"
#include "user_error.h"

#include <cmath>
#include <iostream>

namespace frepkit
{

std::vector<double> box_or_solid_bounds(const std::vector<double>& box,
  const std::shared_ptr<const frep::Tape>& tape,
  bool quiet)
{
  if (!box.empty() || !tape || tape->input_count == 0)
  {
    return box;
  }
  const frep::mesh::SolidBoundsOptions options;
  const frep::mesh::SolidBounds bounds = frep::mesh::find_solid_bounds(tape, options);
  if (!bounds.bounded())
  {
    const std::string search =
      "[-" + format_short(options.search) + ", " + format_short(options.search) + "]";
    std::cerr << "frepkit: warning: "
              << (bounds.status == frep::mesh::SolidBounds::Status::Empty
                     ? "the solid is empty in " + search
                     : "the solid reaches the edge of " + search +
                         " (unbounded, or its intervals are too loose to tell)")
              << "; using -10..10 on each axis (choose with --box)\n";
    return {};
  }
  std::vector<double> result(2 * bounds.box.size());
  std::string text;
  for (std::size_t k = 0; k < bounds.box.size(); ++k)
  {
    // Rounded outwards to about 3 significant digits of the extent: a box one can retype.
    const frep::Interval axis = frep::mesh::readable(bounds.box[k]);
    result[k] = axis.lo;
    result[k + bounds.box.size()] = axis.hi;
    text += std::string(k == 0 ? "" : " x ") + "[" + format_short(result[k]) + ", " +
            format_short(result[k + bounds.box.size()]) + "]";
  }
  if (!quiet)
  {
    std::cerr << "frepkit: box " << text << " (the solid's bounds; --box to choose)\n";
  }
  return result;
}

frep::GridSpec make_grid(const std::vector<double>& box,
  const std::vector<std::int64_t>& grid,
  int axes)
{
  static const char* const kMinNames[] = { "xmin", "ymin", "zmin" };
  static const char* const kMaxNames[] = { "xmax", "ymax", "zmax" };
  const std::size_t n = static_cast<std::size_t>(axes);
  frep::GridSpec result;
  result.axes.assign(n, { -kDefaultBoxHalfSize, kDefaultBoxHalfSize, kDefaultSamples });
  if (!box.empty())
  {
    if (box.size() != 2 * n)
    {
      std::string names;
      for (int pass = 0; pass < 2; ++pass)
      {
        for (int k = 0; k < axes; ++k)
        {
          names += names.empty() ? "" : ",";
          names += pass == 0 ? kMinNames[k] : kMaxNames[k];
        }
      }
      throw UserError("--box needs " + std::to_string(2 * n) + " numbers " + names + " (got " +
                      std::to_string(box.size()) + ")");
    }
    for (std::size_t k = 0; k < n; ++k)
    {
      const double lo = box[k];
      const double hi = box[k + n];
      if (!std::isfinite(lo) || !std::isfinite(hi))
      {
        throw UserError("--box: the bounds must be finite numbers");
      }
      if (!(lo < hi))
      {
        throw UserError(std::string("--box: ") + kMinNames[k] + " = " + format_short(lo) +
                        " is not less than " + kMaxNames[k] + " = " + format_short(hi));
      }
      result.axes[k].lo = lo;
      result.axes[k].hi = hi;
    }
  }
  if (!grid.empty())
  {
    if (grid.size() != 1 && grid.size() != n)
    {
      throw UserError("--grid needs 1 or " + std::to_string(n) +
                      " values (samples per axis), got " + std::to_string(grid.size()));
    }
    for (std::size_t k = 0; k < n; ++k)
    {
      const std::int64_t samples = grid.size() == 1 ? grid[0] : grid[k];
      if (samples < 2)
      {
        throw UserError(
          "--grid " + std::to_string(samples) +
          ": at least 2 samples per axis are needed (the grid counts samples, not cells)");
      }
      result.axes[k].samples = samples;
    }
  }
  return result;
}

std::string describe_grid(const frep::GridSpec& grid)
{
  std::string samples;
  std::string box;
  for (const frep::GridAxis& axis : grid.axes)
  {
    const bool first = samples.empty();
    samples += (first ? "" : " x ") + std::to_string(axis.samples);
    box += std::string(first ? "" : " x ") + "[" + format_short(axis.lo) + ", " +
           format_short(axis.hi) + "]";
  }
  return samples + " samples over " + box;
}

} // namespace frepkit
