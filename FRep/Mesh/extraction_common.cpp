#include "Mesh/detail/extraction_common.h"

#include "Eval/thread_pool.h"

#include <atomic>
#include <mutex>

#include <cmath>
#include <sstream>

namespace frep::mesh::detail
{

GridFrame::GridFrame(const GridSpec& grid, int dim)
  : dimension(dim)
{
  for (int a = 0; a < dimension; ++a)
  {
    const GridAxis& axis = grid.axes[static_cast<std::size_t>(a)];
    lo[a] = axis.lo;
    samples[a] = axis.samples;
    step[a] = axis.step();
  }
}

std::string validate(const Tape* tape,
  const GridSpec& grid,
  int dimension,
  const ExtractOptions& options)
{
  std::ostringstream message;
  if (!tape)
  {
    return "no model to extract from";
  }
  if (tape->input_count != static_cast<std::uint32_t>(dimension))
  {
    message << "the object has " << tape->input_count << " free coordinate"
            << (tape->input_count == 1 ? "" : "s") << "; "
            << (dimension == 3 ? "a surface needs 3" : "a contour needs 2")
            << " (fix the others to values: a slice)";
    return message.str();
  }
  if (grid.axes.size() != static_cast<std::size_t>(dimension))
  {
    message << "the grid has " << grid.axes.size() << " axes; "
            << (dimension == 3 ? "a surface needs 3" : "a contour needs 2");
    return message.str();
  }
  if (std::string axes = check_grid_axes(grid, 2); !axes.empty())
  {
    return axes;
  }
  std::array<std::int64_t, 3> samples{};
  for (int a = 0; a < dimension; ++a)
  {
    samples[static_cast<std::size_t>(a)] = grid.axes[static_cast<std::size_t>(a)].samples;
  }
  if (std::string size = check_grid_size(
        std::span<const std::int64_t>(samples.data(), static_cast<std::size_t>(dimension)),
        options.max_samples,
        "ExtractOptions::max_samples");
      !size.empty())
  {
    return size;
  }
  if (!std::isfinite(options.iso))
  {
    return "the iso value must be a finite number";
  }
  if (options.leaf_cells < 1)
  {
    return "leaf_cells must be at least 1";
  }
  return {};
}

BoxSign classify(const IntervalResult& r, double iso)
{
  // Failed points count as outside: a box that is below the iso value wherever F is defined is
  // outside even if some points fail; inside needs every point to succeed.
  if (r.value.hi < iso)
  {
    return BoxSign::Outside;
  }
  if (r.value.lo >= iso && !r.may_fail)
  {
    return BoxSign::Inside;
  }
  return BoxSign::Unknown;
}

std::array<Interval, 3> box_intervals(const GridFrame& frame, const CellBox& box)
{
  std::array<Interval, 3> intervals{};
  for (int a = 0; a < frame.dimension; ++a)
  {
    intervals[a] = Interval{ frame.coord(a, box.c0[a]), frame.coord(a, box.c1[a]) };
  }
  return intervals;
}

std::vector<CellBox> split(const CellBox& box, std::int64_t leaf, int dimension)
{
  std::array<std::array<std::int64_t, 3>, 3> cuts{}; // per axis: start, middle, end
  std::array<int, 3> parts{ 1, 1, 1 };
  for (int a = 0; a < dimension; ++a)
  {
    const std::int64_t size = box.c1[a] - box.c0[a];
    cuts[a][0] = box.c0[a];
    if (size > leaf)
    {
      const std::int64_t half = ((size / 2 + leaf - 1) / leaf) * leaf;
      cuts[a][1] = box.c0[a] + half;
      cuts[a][2] = box.c1[a];
      parts[a] = 2;
    }
    else
    {
      cuts[a][1] = box.c1[a];
    }
  }
  std::vector<CellBox> children;
  for (int k = 0; k < parts[2]; ++k)
  {
    for (int j = 0; j < parts[1]; ++j)
    {
      for (int i = 0; i < parts[0]; ++i)
      {
        CellBox child = box;
        const std::array<int, 3> pick{ i, j, k };
        for (int a = 0; a < dimension; ++a)
        {
          child.c0[a] = cuts[a][pick[a]];
          child.c1[a] = cuts[a][pick[a] + 1];
        }
        children.push_back(child);
      }
    }
  }
  return children;
}

std::string merge_pieces(std::vector<Piece>& pieces, const GridFrame& frame,
  const CellBox& range, std::int64_t block_cells, Surface& surface,
  std::vector<std::uint64_t>& keys)
{
  std::size_t point_total = 0;
  std::size_t cell_total = 0;
  for (const Piece& piece : pieces)
  {
    point_total += piece.keys.size();
    cell_total += piece.cells.size();
  }
  if (point_total >= std::numeric_limits<std::uint32_t>::max())
  {
    return "the mesh would have more than 4294967294 points: use a coarser grid or a smaller box";
  }
  // A point can repeat only if it lies on a face between blocks: one of its vertex coordinates
  // (other than along its own edge) is a multiple of the block size.
  auto may_repeat = [&](std::uint64_t key)
  {
    if (key == unshared_key)
    {
      return false;
    }
    const int kind = static_cast<int>(key % 4u);
    std::uint64_t v = key / 4u;
    for (int a = 0; a < frame.dimension; ++a)
    {
      const auto coordinate = static_cast<std::int64_t>(v % static_cast<std::uint64_t>(frame.samples[a]));
      v /= static_cast<std::uint64_t>(frame.samples[a]);
      if (a != kind && (coordinate - range.c0[a]) % block_cells == 0)
      {
        return true;
      }
    }
    return false;
  };

  surface.points.clear();
  surface.cells.clear();
  surface.points.reserve(point_total * 3);
  surface.cells.reserve(cell_total);
  keys.clear();
  keys.reserve(point_total);
  std::unordered_map<std::uint64_t, std::uint32_t> shared;
  std::vector<std::uint32_t> remap;
  for (Piece& piece : pieces)
  {
    remap.resize(piece.keys.size());
    for (std::size_t p = 0; p < piece.keys.size(); ++p)
    {
      const std::uint64_t key = piece.keys[p];
      const auto id = static_cast<std::uint32_t>(keys.size());
      if (may_repeat(key))
      {
        auto [it, added] = shared.try_emplace(key, id);
        if (!added)
        {
          remap[p] = it->second;
          continue;
        }
      }
      remap[p] = id;
      keys.push_back(key);
      surface.points.insert(surface.points.end(), piece.points.begin() + std::ptrdiff_t(3 * p),
        piece.points.begin() + std::ptrdiff_t(3 * p + 3));
    }
    for (std::uint32_t local : piece.cells)
    {
      surface.cells.push_back(remap[local]);
    }
    // Release as we go: the merged copy replaces the pieces.
    piece = Piece{};
  }
  return {};
}

CellBox cell_range(const GridSpec& grid, int dimension)
{
  CellBox range;
  for (int a = 0; a < dimension; ++a)
  {
    const GridAxis& axis = grid.axes[static_cast<std::size_t>(a)];
    range.c0[a] = axis.begin;
    range.c1[a] = axis.part_end() - 1;
  }
  return range;
}

std::vector<CellBox> blocks_of(const CellBox& range, int dimension, std::int64_t block_cells)
{
  std::array<std::int64_t, 3> count{ 1, 1, 1 };
  for (int a = 0; a < dimension; ++a)
  {
    count[a] = (range.c1[a] - range.c0[a] + block_cells - 1) / block_cells;
  }
  std::vector<CellBox> blocks;
  blocks.reserve(static_cast<std::size_t>(count[0] * count[1] * count[2]));
  for (std::int64_t k = 0; k < count[2]; ++k)
  {
    for (std::int64_t j = 0; j < count[1]; ++j)
    {
      for (std::int64_t i = 0; i < count[0]; ++i)
      {
        CellBox box;
        const std::array<std::int64_t, 3> b{ i, j, k };
        for (int a = 0; a < dimension; ++a)
        {
          box.c0[a] = range.c0[a] + b[a] * block_cells;
          box.c1[a] = std::min(range.c1[a], box.c0[a] + block_cells);
        }
        blocks.push_back(box);
      }
    }
  }
  return blocks;
}

bool for_each_block(ThreadPool& pool, const std::vector<CellBox>& blocks, const RunControl& run,
  const std::function<void(std::size_t index, const CellBox& block, int slot)>& body,
  std::size_t& block_count)
{
  block_count = blocks.size();
  std::atomic<bool> cancelled{ false };
  std::atomic<std::size_t> done{ 0 };
  std::mutex progress_mutex;
  std::size_t reported = 0; // under progress_mutex
  // About 200 progress calls at most, so the callback never costs anything.
  const std::size_t report_every = std::max<std::size_t>(1, blocks.size() / 200);
  pool.parallel_for(blocks.size(),
    [&](std::size_t index, int slot)
    {
      if (cancelled.load(std::memory_order_relaxed) || run.cancel_requested())
      {
        cancelled = true;
        return;
      }
      body(index, blocks[index], slot);
      const std::size_t finished = done.fetch_add(1) + 1;
      if (run.progress && (finished % report_every == 0 || finished == blocks.size()))
      {
        std::lock_guard lock(progress_mutex);
        // Threads can reach the lock out of order: report only forward steps.
        if (finished > reported)
        {
          reported = finished;
          if (!run.progress(double(finished) / double(blocks.size())))
          {
            cancelled = true;
          }
        }
      }
    });
  return !cancelled.load();
}


} // namespace frep::mesh::detail
