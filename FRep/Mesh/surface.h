// Surface (3-D) and contour (2-D) extraction of F = iso over a regular grid of samples, with
// interval culling: boxes whose enclosure of F excludes the iso value are never sampled, so time
// and memory grow with the surface, not the volume.
//
// The output is watertight and consistently oriented: cells are polygonised by marching cubes
// whose face ambiguities are decided from the four corner values of the face alone (the
// asymptotic decider), so the two cells sharing a face always agree; the polygons are closed
// loops of edge crossings, oriented outward (towards smaller F, since F >= 0 is the solid).
// Where the solid meets the grid's box it is capped by the box faces (optional), so a mesh of a
// shape cut by the box is still closed. Points are shared through their grid edge: no duplicates.
#pragma once

#include "Compiler/tape.h"
#include "Eval/run_control.h"
#include "Sample/grid.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace frep
{

class ThreadPool;

namespace mesh
{

struct ExtractOptions : RunControl
{
  double iso = 0.0; ///< the surface is F = iso; F >= iso is inside
  /// Close the solid where it meets the box (3-D only). Off: the mesh is open there.
  bool cap_boundary = true;
  bool normals = true;    ///< per-point outward unit normals from the model's gradient
  bool attributes = true; ///< per-point s[1..s_dim] (the tape's outputs after F)
  /// Root refinement steps per point along its grid edge (0 = linear interpolation only).
  int refine_steps = 0;
  bool cull = true; ///< interval culling; off samples every grid point (for tests/measurements)
  /// Below a box, evaluate a tape simplified for it (Eval/tape_simplifier.h: min/max, selects and
  /// checks the box decides). The samples' values are the full tape's bit for bit, so the surface
  /// is identical either way; off is for tests and measurements. Needs `cull`.
  bool simplify = true;
  /// Run the tapes as compiled machine code once they have enough samples to pay for it
  /// (BatchOptions::jit, Eval/detail/jit_kernel.h). Identical results; off for tests and
  /// measurements.
  bool jit = true;
  /// Cells per axis of the smallest box the culling tests before sampling it.
  int leaf_cells = 8;
  /// Refuse grids with more samples than this (the time would be unbounded) with an error;
  /// the engine's one grid limit by default (4096^3, Sample/grid.h).
  double max_samples = max_grid_samples;
  // RunControl: threads or pool; progress is called now and then with the fraction done in
  // [0, 1] from any worker thread, never concurrently (false cancels); cancel is polled before
  // every block of cells.
};

/// A triangle mesh (3-D) or a set of line segments (2-D contour, z = 0).
struct Surface
{
  int dimension = 3;
  std::vector<double> points;         ///< x, y, z per point
  std::vector<std::uint32_t> cells;   ///< 3 point ids per triangle (2 per segment in 2-D)
  std::vector<float> normals;         ///< 3 per point (empty when not requested)
  int attribute_count = 0;            ///< s_dim
  std::vector<float> attributes;      ///< attribute_count per point (empty when not requested)

  std::size_t point_count() const { return points.size() / 3; }
  std::size_t cell_count() const { return cells.size() / (dimension == 3 ? 3 : 2); }
};

/// Where the time went, for reports and benchmarks.
struct ExtractStatistics
{
  std::size_t boxes_tested = 0;     ///< interval evaluations
  std::size_t boxes_culled = 0;     ///< boxes proven inside or outside
  std::size_t samples = 0;          ///< points evaluated (F)
  std::size_t sample_instructions = 0; ///< tape instructions run for them (simplified tapes are shorter)
  std::size_t dense_samples = 0;    ///< points a dense run evaluates
  std::size_t failed_samples = 0;   ///< points whose evaluation raised a run-time error (NaN)
  double seconds_extract = 0;       ///< culling, sampling and polygonising
  double seconds_merge = 0;         ///< joining the pieces
  double seconds_normals = 0;       ///< gradients and attributes
};

struct ExtractResult
{
  Surface surface;
  ExtractStatistics statistics;
  std::string error;      ///< why nothing was extracted (bad grid, too large, wrong tape)
  bool cancelled = false; ///< the progress callback returned false
  bool ok() const { return error.empty() && !cancelled; }
};

/// The surface F = iso of a tape with 3 inputs (x, y, z in that order) over a grid of 3 axes
/// (Sample/grid.h), each with at least 2 samples and lo < hi. The cells between each axis's
/// part of the samples, [begin, end - 1), are meshed: a piece of a distributed run (the pieces
/// of a partition, sharing their boundary samples as VTK extents do, together give the whole
/// mesh, their shared points duplicated); the caps stay on the whole grid's box.
/// Run-time errors (NaN values) count as outside. Never throws for bad input: see `error`.
ExtractResult extract_surface(std::shared_ptr<const Tape> tape,
  const GridSpec& grid,
  const ExtractOptions& options = {});

/// The contour F = iso of a tape with 2 inputs over a grid of 2 axes (as extract_surface):
/// line segments, each oriented with the inside (F >= iso) on its left.
ExtractResult extract_contour(std::shared_ptr<const Tape> tape,
  const GridSpec& grid,
  const ExtractOptions& options = {});

} // namespace mesh
} // namespace frep
