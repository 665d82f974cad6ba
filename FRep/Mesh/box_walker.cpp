// The interval-culled walk over a block of cells and the extraction driver shared by surfaces
// and contours.
#include "Mesh/detail/extraction_common.h"

#include "Eval/thread_pool.h"

#include <chrono>

namespace frep::mesh::detail
{

namespace
{

RegionWalkerOptions walk_options(const ExtractOptions& options)
{
  RegionWalkerOptions o;
  o.simplify = options.simplify;
  o.freeze = true; // boxes inside boxes skip what their parent dominates
  o.jit = options.jit;
  return o;
}

} // namespace

BoxWalker::BoxWalker(const std::shared_ptr<const Tape>& tape, const GridFrame& frame,
  const ExtractOptions& options)
  : frame_(frame)
  , options_(options)
  , walker_(tape, walk_options(options))
{
}

BoxWalker::~BoxWalker() = default;

void BoxWalker::run(const CellBox& block, Piece& piece)
{
  builder_.begin(&piece);
  walk(block, walker_.root());
}

void BoxWalker::walk(const CellBox& box, const RegionWalker::Region& region)
{
  Piece& piece = builder_.piece();
  if (options_.cull)
  {
    ++piece.boxes_tested;
    const std::array<Interval, 3> intervals = box_intervals(frame_, box);
    const BoxSign sign = classify(
      walker_.enclose(region,
        std::span<const Interval>(intervals.data(), static_cast<std::size_t>(frame_.dimension))),
      options_.iso);
    if (sign != BoxSign::Unknown)
    {
      ++piece.boxes_culled;
      if (sign == BoxSign::Inside && options_.cap_boundary)
      {
        inside_box(box);
      }
      return;
    }
  }
  // Below this box, evaluate only what the box left undecided.
  const RegionWalker::Region inner = walker_.descend(region);
  const std::int64_t leaf_cells = options_.leaf_cells;
  bool is_leaf = true;
  for (int a = 0; a < frame_.dimension; ++a)
  {
    is_leaf = is_leaf && box.c1[a] - box.c0[a] <= leaf_cells;
  }
  if (is_leaf)
  {
    sample(box, inner);
    leaf(box);
    return;
  }
  for (const CellBox& child : split(box, leaf_cells, frame_.dimension))
  {
    walk(child, inner);
  }
}

void BoxWalker::sample(const CellBox& box, const RegionWalker::Region& region)
{
  std::array<std::int64_t, 3> n{ 1, 1, 1 };
  for (int a = 0; a < frame_.dimension; ++a)
  {
    n[a] = box.c1[a] - box.c0[a] + 1;
  }
  const auto count = static_cast<std::size_t>(n[0] * n[1] * n[2]);
  for (auto* v : { &xs_, &ys_, &zs_, &values_ })
  {
    v->resize(count);
  }
  std::size_t p = 0;
  for (std::int64_t k = 0; k < n[2]; ++k)
  {
    const double z = frame_.dimension == 3 ? frame_.coord(2, box.c0[2] + k) : 0.0;
    for (std::int64_t j = 0; j < n[1]; ++j)
    {
      const double y = frame_.coord(1, box.c0[1] + j);
      for (std::int64_t i = 0; i < n[0]; ++i, ++p)
      {
        xs_[p] = frame_.coord(0, box.c0[0] + i);
        ys_[p] = y;
        zs_[p] = z;
      }
    }
  }
  const std::array<const double*, 3> inputs{ xs_.data(), ys_.data(), zs_.data() };
  Piece& piece = builder_.piece();
  piece.sample_instructions += count * walker_.tape(region)->code.size();
  piece.failed_samples += walker_.evaluate(region,
    std::span<const double* const>(inputs.data(), static_cast<std::size_t>(frame_.dimension)),
    count, values_.data());
  piece.samples += count;
  for (double& v : values_)
  {
    v -= options_.iso;
  }
}

namespace
{
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}
} // namespace

ExtractResult run_extraction(const std::shared_ptr<const Tape>& tape,
  const GridSpec& grid,
  int dimension,
  const ExtractOptions& options,
  const std::function<std::unique_ptr<BoxWalker>(const GridFrame&)>& make_walker)
{
  ExtractResult result;
  result.surface.dimension = dimension;
  result.error = validate(tape.get(), grid, dimension, options);
  if (!result.error.empty())
  {
    return result;
  }
  const auto start = Clock::now();
  const GridFrame frame(grid, dimension);
  const std::shared_ptr<ThreadPool> pool = options.thread_pool();
  // Blocks of 4 leaves per axis, few enough that joining their pieces is cheap; a grid with
  // fewer than 64 of them (a 32^3 grid is one block) is cut into blocks of 2 leaves or 1, so the
  // threads share it (a costly model, such as a projection, is drawn on small grids). Decided by
  // the grid alone: the mesh does not depend on the number of threads.
  const CellBox range = cell_range(grid, dimension);
  std::int64_t block_cells = std::int64_t(options.leaf_cells) * 4;
  std::vector<CellBox> blocks = blocks_of(range, dimension, block_cells);
  while (blocks.size() < 64 && block_cells > options.leaf_cells)
  {
    block_cells /= 2;
    blocks = blocks_of(range, dimension, block_cells);
  }
  std::vector<std::unique_ptr<BoxWalker>> walkers(static_cast<std::size_t>(pool->size()));
  std::vector<Piece> pieces(blocks.size());
  std::size_t block_count = 0;
  const bool finished = for_each_block(*pool, blocks, options,
    [&](std::size_t index, const CellBox& block, int slot)
    {
      auto& walker = walkers[static_cast<std::size_t>(slot)];
      if (!walker)
      {
        walker = make_walker(frame);
      }
      walker->run(block, pieces[index]);
    },
    block_count);
  if (!finished)
  {
    result.cancelled = true;
    return result;
  }
  ExtractStatistics& stats = result.statistics;
  stats.dense_samples = 1;
  for (int a = 0; a < dimension; ++a)
  {
    stats.dense_samples *= static_cast<std::size_t>(range.c1[a] - range.c0[a] + 1);
  }
  for (const Piece& piece : pieces)
  {
    stats.boxes_tested += piece.boxes_tested;
    stats.boxes_culled += piece.boxes_culled;
    stats.samples += piece.samples;
    stats.sample_instructions += piece.sample_instructions;
    stats.failed_samples += piece.failed_samples;
  }
  stats.seconds_extract = seconds_since(start);

  const auto merge_start = Clock::now();
  std::vector<std::uint64_t> keys;
  result.error = merge_pieces(pieces, frame, range, block_cells, result.surface, keys);
  stats.seconds_merge = seconds_since(merge_start);
  if (!result.error.empty())
  {
    result.surface = Surface{};
    result.surface.dimension = dimension;
    return result;
  }
  const auto finish_start = Clock::now();
  finish_points(tape, frame, keys, options, pool, result.surface, stats);
  stats.seconds_normals = seconds_since(finish_start);
  return result;
}

} // namespace frep::mesh::detail
