// Internal to FRep/Mesh: what surface (3-D) and contour (2-D) extraction share — the grid's
// coordinates, validation, the interval-culled walk over boxes of cells, the pieces each block
// of cells produces and their merge into one point set without duplicates.
#pragma once

#include "Eval/batch_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/region_walker.h"
#include "Mesh/surface.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace frep
{
class ThreadPool;
}

namespace frep::mesh::detail
{

/// Key of a point no other piece can produce (cell centres).
constexpr std::uint64_t unshared_key = std::numeric_limits<std::uint64_t>::max();

/// Sample coordinates: frep::grid_coordinate(lo, step, i) with step = frep::grid_step(lo, hi,
/// samples) (Sample/grid.h, the sampler's positions), computed this one way everywhere so that
/// neighbouring boxes see bit-identical positions and values.
struct GridFrame
{
  int dimension = 3;
  std::array<double, 3> lo{};
  std::array<double, 3> step{};
  std::array<std::int64_t, 3> samples{ 1, 1, 1 };

  GridFrame(const GridSpec& grid, int dimension);
  double coord(int axis, std::int64_t i) const { return grid_coordinate(lo[axis], step[axis], i); }
  std::int64_t cells(int axis) const { return samples[axis] - 1; }
  std::int64_t vertex(std::int64_t i, std::int64_t j, std::int64_t k) const
  {
    return i + samples[0] * (j + samples[1] * k);
  }
  /// Key of the crossing on the edge from vertex (i, j, k) along `axis`, or of the vertex
  /// itself (axis 3).
  std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k, int axis) const
  {
    return static_cast<std::uint64_t>(vertex(i, j, k)) * 4u + static_cast<std::uint64_t>(axis);
  }
};

/// Empty when the request can be run; else the message for ExtractResult::error.
std::string validate(const Tape* tape,
  const GridSpec& grid,
  int dimension,
  const ExtractOptions& options);

/// Cell range [c0, c1) per axis.
struct CellBox
{
  std::array<std::int64_t, 3> c0{};
  std::array<std::int64_t, 3> c1{};
};

/// What one block of cells produced: points (keyed by grid edge or vertex) and cells in local
/// point ids.
struct Piece
{
  std::vector<std::uint64_t> keys;
  std::vector<double> points;
  std::vector<std::uint32_t> cells;
  std::size_t samples = 0;
  std::size_t failed_samples = 0;
  std::size_t boxes_tested = 0;
  std::size_t boxes_culled = 0;
  std::size_t sample_instructions = 0;
};

/// Scratch of one worker: the local index of the piece being built.
class PieceBuilder
{
public:
  void begin(Piece* piece)
  {
    piece_ = piece;
    index_.clear();
  }
  Piece& piece() { return *piece_; }

  /// The local id of the point with this key, created at `position` the first time.
  template <class Position>
  std::uint32_t point(std::uint64_t key, Position&& position)
  {
    auto [it, added] = index_.try_emplace(key, static_cast<std::uint32_t>(piece_->keys.size()));
    if (added)
    {
      const std::array<double, 3> p = position();
      piece_->keys.push_back(key);
      piece_->points.insert(piece_->points.end(), p.begin(), p.end());
    }
    return it->second;
  }
  std::uint32_t unshared_point(const std::array<double, 3>& p)
  {
    piece_->keys.push_back(unshared_key);
    piece_->points.insert(piece_->points.end(), p.begin(), p.end());
    return static_cast<std::uint32_t>(piece_->keys.size() - 1);
  }

private:
  Piece* piece_ = nullptr;
  std::unordered_map<std::uint64_t, std::uint32_t> index_;
};

/// Joins the pieces in order: points with the same key become one (only keys on the faces
/// between blocks of `block_cells` can repeat). Fills surface.points/cells and keys (per point).
/// Returns an error message when the mesh exceeds 2^32 - 1 points.
std::string merge_pieces(std::vector<Piece>& pieces, const GridFrame& frame,
  const CellBox& range, std::int64_t block_cells, Surface& surface,
  std::vector<std::uint64_t>& keys);

/// Runs body(index, blocks[index], slot) for every block, spread over the pool, and reports
/// progress (blocks done / blocks) through run.progress, never concurrently. Returns false when
/// progress or run.cancel asked to stop (the remaining blocks are skipped).
bool for_each_block(ThreadPool& pool, const std::vector<CellBox>& blocks, const RunControl& run,
  const std::function<void(std::size_t index, const CellBox& block, int slot)>& body,
  std::size_t& block_count);

/// The cells to polygonise: those between each axis's part of the samples (validated).
CellBox cell_range(const GridSpec& grid, int dimension);

/// Blocks of at most block_cells cells per axis covering `range`, starting at its corner.
std::vector<CellBox> blocks_of(const CellBox& range, int dimension, std::int64_t block_cells);

/// Computes what the options ask for on the merged points: root refinement along the grid edge
/// (3-D and 2-D), outward normals (3-D), s[] attributes.
void finish_points(const std::shared_ptr<const Tape>& tape, const GridFrame& frame,
  const std::vector<std::uint64_t>& keys, const ExtractOptions& options,
  const std::shared_ptr<ThreadPool>& pool,
  Surface& surface, ExtractStatistics& statistics);


/// How an interval enclosure classifies a box.
enum class BoxSign
{
  Unknown,
  Inside,
  Outside
};
BoxSign classify(const IntervalResult& r, double iso);

/// The cells' box as intervals (positions of its extreme samples), one per axis of the frame.
std::array<Interval, 3> box_intervals(const GridFrame& frame, const CellBox& box);

/// Splits `box` (some axis longer than `leaf` cells) into up to 8 children whose sizes are
/// multiples of `leaf` except the last along each axis.
std::vector<CellBox> split(const CellBox& box, std::int64_t leaf, int dimension);

/// Walks one block of cells: boxes whose enclosure proves them inside or outside are skipped
/// (inside ones on the grid's boundary get caps), the others are split down to leaves of
/// options.leaf_cells cells, which are sampled and handed to leaf(). One walker per thread.
class BoxWalker
{
public:
  BoxWalker(const std::shared_ptr<const Tape>& tape, const GridFrame& frame,
    const ExtractOptions& options);
  virtual ~BoxWalker();
  BoxWalker(const BoxWalker&) = delete;
  BoxWalker& operator=(const BoxWalker&) = delete;

  void run(const CellBox& block, Piece& piece);

protected:
  /// A leaf box, sampled: g(i, j, k) = F - iso at its sample (i, j, k) relative to box.c0.
  virtual void leaf(const CellBox& box) = 0;
  /// A box proven inside (only called when caps are wanted).
  virtual void inside_box(const CellBox& /*box*/) {}

  /// F - iso at the leaf's samples, i fastest (NaN where the evaluation failed).
  const std::vector<double>& values() const { return values_; }

  const GridFrame& frame_;
  const ExtractOptions& options_;
  PieceBuilder builder_;

private:
  /// The region walker: the model's tape at the root, a simplified one below a box that decided
  /// some of its instructions (the values are the same bit for bit), freezes per depth.
  void walk(const CellBox& box, const RegionWalker::Region& region);
  void sample(const CellBox& box, const RegionWalker::Region& region);

  RegionWalker walker_;
  std::vector<double> xs_, ys_, zs_, values_;
};

/// The whole extraction for walkers made by make_walker: validation, blocks in parallel with
/// progress and cancellation, statistics, merge, per-point finishing.
ExtractResult run_extraction(const std::shared_ptr<const Tape>& tape,
  const GridSpec& grid,
  int dimension,
  const ExtractOptions& options,
  const std::function<std::unique_ptr<BoxWalker>(const GridFrame&)>& make_walker);

} // namespace frep::mesh::detail
