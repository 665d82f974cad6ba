// The one walk of regions every subdividing algorithm shares (the mesher's boxes of cells, the
// ray caster's frustum pieces, the tiled sampler's rectangles, the normals' bricks, the solid's
// bounds): enclose a region's F on intervals, let the caller cull what is decided, and for what
// is left push a shorter tape (TapeSimplifier: the same values bit for bit) when it pays, plus
// what the region's enclosure lets the regions inside skip (interval freezes); evaluate points
// with the tape of the region they lie in, compiled once its samples pay. libfive and Fidget
// call this a tape stack.
//
// The caller keeps its own recursion and split rule (cells, pixels and depths, rectangles of
// runs, axis by axis) and asks the walker three things per region:
//
//   RegionWalker walker(tape, options);            // one per thread
//   void visit(const RegionWalker::Region& region, Box box) {
//     const IntervalResult r = walker.enclose(region, box);
//     if (decided(r)) return;                        // culled: the caller's rule
//     const RegionWalker::Region inner = walker.descend(region);
//     if (leaf(box)) walker.evaluate(inner, points...); else for (child : split(box)) visit(inner, child);
//   }
//   visit(walker.root(), whole);
//
// The walk must be depth first: a region's descend() is valid until the next enclose() at its
// depth (one level of tapes and one freeze per depth, rebound from region to region: nothing is
// allocated per region once the deepest depth has been reached).
#pragma once

#include "Compiler/tape.h"
#include "Eval/interval_evaluator.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

namespace frep
{

struct RegionWalkerOptions
{
  /// Push a shorter tape for a region that decides some of its instructions (min/max,
  /// conditions). Off: every region evaluates the walker's tape. Default on.
  bool simplify = true;
  /// Interval freezes: what a region's enclosure dominates is not evaluated again by the regions
  /// inside it while they keep its tape (IntervalEvaluator::make_freeze). Looser enclosures,
  /// fewer instructions: worth it for deep walks (mesher, ray caster). Default off.
  bool freeze = false;
  /// With `freeze`: a freeze is made at every freeze_every-th depth; the others pass their
  /// parent's on (making one costs about half an interval evaluation). Default 1.
  int freeze_every = 1;
  /// Points are evaluated by compiled machine code once a tape's samples pay for compiling it
  /// (eval::LazyKernel). Default on.
  bool jit = true;
  /// With `jit`: the walker's own tape is compiled at its first evaluation, whatever its count
  /// (walks that evaluate it in many small batches, like the ray caster's marches). Default off.
  bool compile_root_now = false;
  /// Lanes per block of the point evaluation (> 0). Default 256.
  int block = 256;
};

/// Counters of one walker since it was made (or reset_statistics).
struct RegionWalkerStatistics
{
  std::size_t enclosures = 0;     ///< interval evaluations
  std::size_t simplify_tries = 0; ///< regions whose choices were simplified
  std::size_t simplified = 0;     ///< ... and pushed a shorter tape
  std::size_t points = 0;         ///< points evaluated
  std::size_t instructions = 0;   ///< point evaluations times the tape's length
  std::size_t failed_points = 0;  ///< points that raised a run-time error
};

class RegionWalker
{
  struct Level;     // a tape and what evaluates it (region_walker.cpp)
  class LazyFreeze; // what a region lets the regions inside skip

public:
  /// `tape` is checked once (eval::check_tape; throws std::invalid_argument like the
  /// evaluators when it is not valid). Not thread-safe: one walker per thread.
  explicit RegionWalker(std::shared_ptr<const Tape> tape, const RegionWalkerOptions& options = {});
  ~RegionWalker();
  RegionWalker(const RegionWalker&) = delete;
  RegionWalker& operator=(const RegionWalker&) = delete;

  /// A region's place in the walk: its tape and depth, and what the region around it lets it
  /// skip. A small value the walker hands out; valid during the depth-first walk below the
  /// region that made it.
  class Region
  {
  public:
    std::size_t depth() const { return depth_; }

  private:
    friend class RegionWalker;
    Level* level_ = nullptr;
    std::size_t depth_ = 0;
    LazyFreeze* link_ = nullptr;
  };

  /// The outermost region: the walker's tape, depth 0.
  Region root();
  /// An outermost region for `tape`, a tape the walker simplified for a region earlier (a task
  /// handed from one walker to another, as the tiled sampler hands rectangles to its threads):
  /// trusted, not checked again. `tape` being the walker's own tape gives root().
  Region root(std::shared_ptr<const Tape> tape);

  /// The tape a region evaluates.
  const std::shared_ptr<const Tape>& tape(const Region& region) const;

  /// Encloses F over `box` (one interval per tape input) with the region's tape (and its
  /// freeze). With `simplify` (and the options', while the tape has instructions a box can
  /// decide and its tries still pay: after 16 tries, one in 8 must shorten it), also records
  /// what the box decides, for descend().
  IntervalResult enclose(const Region& region, std::span<const Interval> box, bool simplify = true);

  /// Whether enclose() at `region` would record choices (simplification is on, the tape has
  /// instructions a box can decide and its tries still pay): a walk that encloses only to
  /// simplify can skip the enclosure when not.
  bool would_simplify(const Region& region) const;

  /// The region for the boxes inside the box the last enclose() at `region` evaluated: the
  /// tape simplified for that box when it is at least an eighth shorter (worth_switching),
  /// else the same tape with the box's freeze. Without an enclose() before: the same tape.
  Region descend(const Region& region);

  /// F at `count` points with the region's tape (eval::BlockRunner::evaluate's contract: values,
  /// optional errors, attributes). Returns the number of points that raised an error.
  std::size_t evaluate(const Region& region, std::span<const double* const> inputs,
    std::size_t count, double* values, std::uint32_t* errors = nullptr,
    std::span<double* const> attributes = {});

  /// Forgets what the walks so far taught it (whether simplifying a tape's boxes pays), so the
  /// next walk tries again as a new walker would: for many small walks that each deserve their
  /// own trial (the projector's, one per point: the first boxes of a point's search rarely
  /// simplify, the deep ones do).
  void restart();

  const RegionWalkerStatistics& statistics() const { return statistics_; }
  void reset_statistics() { statistics_ = {}; }

private:
  struct Walk;
  Level& level_below(std::size_t depth, std::shared_ptr<const Tape> tape);

  std::unique_ptr<Walk> walk_;
  RegionWalkerStatistics statistics_;
};

} // namespace frep
