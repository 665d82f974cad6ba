// --box and --grid of mesh and slice: the box and the number of samples per axis (samples, not
// cells: --grid 128 puts 128 samples on each axis, the first on the box's minimum and the last on
// its maximum; hfp's -g counts cells, g + 1 samples).
#pragma once

#include "Compiler/tape.h"
#include "Sample/grid.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace frepkit
{

constexpr double kDefaultBoxHalfSize = 10.0;
constexpr std::int64_t kDefaultSamples = 128;

/// --box if given, else the solid's own box (frep::mesh::find_solid_bounds over the tape's inputs,
/// the free coordinates): "frepkit: box [..] x [..] (the solid's bounds; --box to choose)" on
/// stderr unless `quiet`. Empty (make_grid's -10..10) with a warning when the solid is unbounded
/// (reaches +-1000, or its enclosures are too loose to tell) or empty.
std::vector<double> box_or_solid_bounds(const std::vector<double>& box,
  const std::shared_ptr<const frep::Tape>& tape,
  bool quiet);

/// A grid over `axes` (2 or 3) axes from --box (empty = -10..10 on each axis, else 2 * axes
/// numbers: all minima, then all maxima) and --grid (empty = 128, else one value for every axis or
/// one per axis). Throws UserError for a wrong count, min >= max, a non-finite bound or fewer than
/// 2 samples. Too many samples are left to the consumer (the mesher refuses with its message).
frep::GridSpec make_grid(const std::vector<double>& box,
  const std::vector<std::int64_t>& grid,
  int axes);

/// "128 x 128 x 128 samples over [-10, 10] x [-10, 10] x [-10, 10]"
std::string describe_grid(const frep::GridSpec& grid);

} // namespace frepkit
