// The engine's one grid description (GridSpec: n axes, each with its samples and the part of
// them wanted), the positions of its samples and the one limit on a grid's size, shared by every
// engine part that walks a grid (Sample/grid_sampler.h, Mesh/surface.h) and by their callers.
//
// SAMPLE POSITIONS: n samples over [lo, hi] are
//   step = (hi - lo) / (n - 1)           (grid_step; 1 when n == 1)
//   position of sample i = lo + i * step  (grid_coordinate; i the index in the whole grid)
// in double precision, computed this one way everywhere. Why this formula and not one that
// forces the last sample onto hi (or a lerp, exact at both ends):
// - it is the geometry of an image given by origin and spacing: vtkImageData::GetPoint, a .vti
//   file's Origin/Spacing, numpy's origin + i * spacing all reproduce it bit for bit, so a value
//   in vtkFRepSampler's image or frepkit slice's .vti equals a point evaluation at the point the
//   image says it belongs to (Filters/Testing/Cxx/TestFRepSampler.cxx checks every sample);
// - a part of a grid (a VTK extent, a piece of a distributed run, a mesher block) depends only
//   on the index, never on where the part ends, so neighbouring parts see identical positions;
// - hfp itself accumulates (x += delta), so no formula is bit-compatible with hfp; what hfp
//   compatibility needs is the sample count ((g + 1) samples for -g g) and the first sample on
//   the box's minimum, which this has.
// The first sample is exactly lo. The last is hi up to the rounding of the step: for most n it
// is exactly hi (over [-10, 10] every n < 78, and 98% of n up to 1024; over [-1, 1] 91%); when
// it is not, it is a unit in the last place away, and |last - hi| <= 2 eps |hi - lo| + eps |hi|.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace frep
{

/// The engine's one limit on the samples of a grid (the product over its axes): 4096^3 = 2^36,
/// the grid of hfp's largest -g (4095 cells, 4096 samples per axis). It bounds time: the
/// sampler streams its blocks (it never holds more than one block of 2^16 samples) and the
/// mesher's memory grows with the surface. The default of SampleOptions::max_samples and of
/// mesh::ExtractOptions::max_samples; a caller that stores every sample lowers it to what it can
/// hold (vtkFRepSampler's MaximumNumberOfSamples, 2^31; frepkit slice, 2^27).
constexpr double max_grid_samples = 68719476736.0;

/// The spacing of `n` samples from lo to hi: (hi - lo) / (n - 1); 1 for a single sample.
inline double grid_step(double lo, double hi, std::int64_t n)
{
  return n > 1 ? (hi - lo) / static_cast<double>(n - 1) : 1.0;
}

/// Sample `i` of an axis that starts at `lo` with spacing `step` (grid_step): lo + i * step.
/// THE sample-position formula; everything that places grid samples calls it.
inline double grid_coordinate(double lo, double step, std::int64_t i)
{
  return lo + static_cast<double>(i) * step;
}

/// Sample `i` of `n` samples over [lo, hi]: grid_coordinate(lo, grid_step(lo, hi, n), i).
inline double grid_coordinate(double lo, double hi, std::int64_t i, std::int64_t n)
{
  return grid_coordinate(lo, grid_step(lo, hi, n), i);
}

/// One axis of a grid: `samples` points from lo to hi, and the part of them wanted.
struct GridAxis
{
  double lo = -10.0;
  double hi = 10.0;
  std::int64_t samples = 64; ///< >= 1; with more than one, lo < hi. One sample lies at lo.
  /// The part wanted: indices [begin, end) of this axis (end 0 = up to the last sample).
  /// Positions are those of the whole axis: a part has exactly the values of the whole. A
  /// mesher meshes the cells between the part's samples, [begin, end - 1), so the parts of a
  /// partition share their boundary samples, as VTK's extents do.
  std::int64_t begin = 0;
  std::int64_t end = 0;

  std::int64_t part_end() const { return end == 0 ? samples : end; }
  double step() const { return grid_step(lo, hi, samples); }
  /// Sample `i` of the whole axis: grid_coordinate(lo, step(), i).
  double coordinate(std::int64_t i) const { return grid_coordinate(lo, step(), i); }
};

/// A regular grid: axis k drives tape input k. Samples are numbered with axis 0 fastest, then
/// axis 1, ... (the order of a VTK image). The sampler takes any number of axes, the mesher 3
/// (a surface) or 2 (a contour).
struct GridSpec
{
  std::vector<GridAxis> axes;
};

/// The whole grid of samples[k] points from lo[k] to hi[k] on each axis (lo.size() axes; hi and
/// samples as many, the missing ones taken as GridAxis's defaults).
GridSpec box_grid(std::span<const double> lo,
  std::span<const double> hi,
  std::span<const std::int64_t> samples);

/// Empty when every axis of `grid` places at least `min_samples` samples (finite bounds, lo < hi
/// when it has more than one) and its part is a range of at least `min_samples` of them; else
/// the first problem, as "grid: axis 2: ...". Does not check the number of axes or the size.
std::string check_grid_axes(const GridSpec& grid, std::int64_t min_samples);

/// Empty when a grid of samples[0] x samples[1] x ... samples (each >= 1) is within `limit`
/// (at most 1e18, so that indices and the mesher's edge keys fit in 64 bits); else
/// "grid: 1000 x 1000 x 1000 = 1e+09 samples is more than the limit of 1.34218e+08 (<option>)".
/// The product is taken in double: no overflow, whatever the counts.
std::string check_grid_size(std::span<const std::int64_t> samples, double limit,
  const char* option);

} // namespace frep
