// Internal to the grid sampler: one block of samples evaluated tile by tile, each tile with the
// tape simplified for the box of its samples (Eval/tape_simplifier.h), hierarchically: the block,
// then squares of (4 tile)^2 samples (the parallel tasks), halved down to tiles of tile^2
// samples, each level simplifying its parent's tape. The values, errors and attributes
// are the full tape's bit for bit (that is the simplifier's guarantee); only the work changes.
// A tile's box is the exact bounding box of its samples' coordinates, so it encloses them
// whatever the grid's positions are.
#pragma once

#include "Compiler/tape.h"
#include "Eval/batch_evaluator.h"
#include "Eval/region_walker.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace frep
{

class ThreadPool;

namespace sample
{

/// A run of consecutive samples of a block along axis 0 (a row or a part of one). Along a run,
/// input 0 does not decrease and the other inputs are constant (grid positions are).
struct SampleRun
{
  std::size_t first = 0;   ///< index in the block
  std::size_t count = 0;
  std::int64_t column = 0; ///< axis-0 index of the first sample
};

struct TileOptions
{
  /// Samples per tile side (>= 1); tasks of (4 tile)^2 samples run on the pool. 32 rather than
  /// 16: the same time on Prospero at 1024^2 (2-D), a third less on the 200-sphere max at 128^3
  /// (3-D), where the work per box outweighed the shorter tapes of smaller tiles
  /// (frep_sample_benchmark, 2026-12-02).
  int tile = 32;
  /// Only the side of `iso` matters to the caller (SampleOptions::sign_only): a box whose
  /// interval lies wholly at or above iso, or wholly below it, with no failure possible, is not
  /// evaluated; its samples get that bound (lo >= iso, or hi < iso) instead of F.
  bool sign_only = false;
  double iso = 0.0;
  bool jit = true; ///< SampleOptions::jit
};

class TiledEvaluator
{
public:
  TiledEvaluator(std::shared_ptr<const Tape> tape, std::shared_ptr<ThreadPool> pool,
    const TileOptions& options = {});
  ~TiledEvaluator();
  TiledEvaluator(const TiledEvaluator&) = delete;
  TiledEvaluator& operator=(const TiledEvaluator&) = delete;

  /// BatchEvaluator::evaluate's contract for the `count` samples of a block whose rows are
  /// `runs` (in order, covering [0, count)). Returns the number of samples that raised an error.
  std::size_t evaluate(std::span<const double* const> inputs, std::span<const SampleRun> runs,
    std::size_t count, double* values, std::uint32_t* errors, std::span<double* const> attributes);

  /// Tape instructions run for the samples so far (each sample counts its tape's length).
  std::size_t instructions() const { return instructions_; }
  /// Samples whose side of iso a box decided without evaluating them (sign_only), so far.
  std::size_t decided() const { return decided_; }

private:
  struct Worker;
  struct Task;
  struct Walk;

  void reset_counters();          // the walkers' statistics and the decided samples
  std::size_t gather_counters();  // into the totals; returns the failures of this evaluate

  std::shared_ptr<const Tape> tape_;
  std::shared_ptr<ThreadPool> pool_;
  int tile_;
  bool sign_only_;
  double iso_;
  RegionWalkerOptions walk_options_;
  std::vector<std::unique_ptr<Worker>> workers_;
  std::unique_ptr<Worker> top_; // the caller's scratch for the serial top of the quadtree
  std::size_t instructions_ = 0;
  std::size_t decided_ = 0;
};

} // namespace sample
} // namespace frep
