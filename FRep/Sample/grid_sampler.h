// The engine's grid sampler: F (and, when asked, s[] and the gradient) of a tape at every sample
// of a regular grid of any dimension, streamed to the caller block by block. One sampler for
// vtkFRepSampler, frepkit slice and anything else that wants a sampled image or volume.
//
//   frep::GridSpec grid;                       // one axis per tape input, x fastest
//   grid.axes = { { -6, 6, 128 }, { -6, 6, 128 }, { -6, 6, 128 } };
//   frep::SampleOptions options;               // F only, NaN where a sample fails, all cores
//   options.progress = [](double f) { return true; };  // false cancels
//   std::vector<double> f(frep::grid_part_size(grid));  // after frep::check_grid(...) is empty
//   frep::SampleResult r = frep::sample_grid(tape, grid, options,
//     [&](const frep::SampleBlock& b) { std::copy_n(b.values, b.count, f.data() + b.first); });
//   if (!r.ok()) { /* r.error, e.g. "grid: ... samples is more than the limit of ..." */ }
//
// Positions: Sample/grid.h (grid_coordinate), the same as the mesher's. Values are bit for bit
// those of PointEvaluator at those positions (the batch evaluator's guarantee), whatever the
// threads, the block boundaries or the part of the grid sampled.
#pragma once

#include "Compiler/tape.h"
#include "Eval/run_control.h"
#include "Sample/grid.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace frep
{

class ThreadPool;

/// What happens to a sample whose evaluation raised a run-time error or gave NaN (see
/// Documentation/compatibility.md, "Run-time errors: the policy").
enum class FailurePolicy
{
  NaN,     ///< F, s[] and the gradient are NaN (outside)
  Previous ///< hfp's: the previous sample's values (in the part's order; 0 for the first)
};

struct SampleOptions : RunControl
{
  /// s[1..attribute_count] per sample (the tape's outputs after F, computed from s[] = 0);
  /// -1 = every attribute the tape has, 0 = none.
  int attribute_count = 0;
  /// dF/dinput_k per sample (exact, forward mode: GradientEvaluator).
  bool gradients = false;
  FailurePolicy failures = FailurePolicy::NaN;
  /// Evaluate tile by tile with the tape simplified for each tile's box (Eval/tape_simplifier.h:
  /// min/max, selects and checks the box decides). The values are the same bit for bit; off is
  /// for tests and measurements.
  bool simplify = true;
  /// Run the tapes as compiled machine code once they have enough samples to pay for it
  /// (BatchOptions::jit, Eval/detail/jit_kernel.h). Identical results; off for tests and
  /// measurements.
  bool jit = true;
  /// Only the side of `iso` matters (sign images, inside/outside counts): a tile whose interval
  /// enclosure lies wholly at or above iso, or wholly below it, with no run-time error or NaN
  /// possible, is not evaluated, and its samples get that bound of F (the enclosure's lo >= iso,
  /// or its hi < iso) instead of F. Every sample's side of iso, its failure and its error are
  /// those of F bit for bit; values of evaluated samples are F. Excludes attributes and
  /// gradients (check_grid says so). Implies the tiled evaluation.
  bool sign_only = false;
  double iso = 0.0;
  /// Grids (the whole grid, not the part) with more samples are refused before anything is
  /// allocated or evaluated.
  double max_samples = max_grid_samples;
  // RunControl: threads or pool; progress is called on the calling thread with the fraction
  // done, 0 before the first block and then after every block, rising to exactly 1 (false
  // cancels before the next block); cancel is polled before every block.
};

/// One block of consecutive samples of the part, after the failure policy. Valid during the
/// call only. Blocks arrive in order, on the calling thread, and cover the part exactly once.
struct SampleBlock
{
  std::size_t first = 0; ///< index of the block's first sample in the part
  std::size_t count = 0;
  std::span<const double* const> coordinates; ///< coordinates[k][p]: input k of sample p
  const double* values = nullptr;             ///< F
  std::span<const double* const> attributes;  ///< attributes[j][p] = s[j + 1]
  const double* gradients = nullptr;          ///< dimension per sample: [p * dimension + k]
  const std::uint8_t* failed = nullptr;       ///< 1 where the sample failed (error or NaN)
};

using SampleSink = std::function<void(const SampleBlock&)>;

struct SampleResult
{
  std::string error;      ///< why nothing was sampled (bad grid, too large, wrong tape, ...)
  bool cancelled = false; ///< progress returned false or the cancel flag was set
  std::size_t samples = 0;  ///< samples evaluated (and passed to the sink)
  std::size_t failed = 0;   ///< samples that raised a run-time error or gave NaN
  std::size_t errors = 0;   ///< of those, the ones that raised a run-time error
  std::int64_t first_failed = -1;       ///< index in the part of the first failed sample
  std::uint32_t first_error = 0;        ///< its error id (tape.errors[id - 1]); 0 = NaN only
  std::vector<double> first_failed_at;  ///< its position
  int threads = 0;                      ///< threads that evaluated
  std::size_t instructions = 0;         ///< tape instructions run (simplified tapes are shorter)
  std::size_t decided = 0;              ///< samples whose side a tile decided (sign_only)
  bool ok() const { return error.empty() && !cancelled; }
};

/// Samples in the part of the grid (GridAxis::begin/end).
std::size_t grid_part_size(const GridSpec& grid);

/// Empty when `grid` can be sampled from a tape with `inputs` inputs under `options`; else
/// why not. sample_grid() checks this first; a caller that allocates storage for the samples
/// calls it before allocating.
std::string check_grid(const GridSpec& grid, std::uint32_t inputs, const SampleOptions& options);

/// Evaluates the part of `grid` block by block (a few times 2^16 samples, spread over the
/// pool) and hands each block to `sink`. Never throws: an invalid request, an exception of the
/// sink or a failed allocation come back in `error`; a cancelled run stops between blocks.
SampleResult sample_grid(std::shared_ptr<const Tape> tape, const GridSpec& grid,
  const SampleOptions& options, const SampleSink& sink);

} // namespace frep
