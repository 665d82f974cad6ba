#include "Sample/detail/tiled_evaluation.h"

#include "Eval/thread_pool.h"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>

namespace frep::sample
{

namespace
{

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Grows box to hold input k of the samples [first, first + count).
void grow(std::vector<Interval>& box, std::span<const double* const> inputs, std::size_t first,
  std::size_t count)
{
  for (std::size_t k = 0; k < box.size(); ++k)
  {
    const double* x = inputs[k] + first;
    const auto [lo, hi] = std::minmax_element(x, x + count);
    box[k].lo = std::min(box[k].lo, *lo);
    box[k].hi = std::max(box[k].hi, *hi);
  }
}

std::vector<Interval> empty_box(std::size_t dimension)
{
  return std::vector<Interval>(dimension, Interval{ kInf, -kInf });
}

/// Whether a box's enclosure decides the side of iso of every sample in it (no failure and no
/// NaN possible: a possible NaN makes the enclosure the whole line), and the bound to give them.
bool decides_side(const IntervalResult& r, double iso, double& bound)
{
  if (r.may_fail)
  {
    return false;
  }
  if (r.value.lo >= iso)
  {
    bound = r.value.lo;
    return true;
  }
  if (r.value.hi < iso)
  {
    bound = r.value.hi;
    return true;
  }
  return false;
}

/// Samples [first, first + n) decided by a box: the bound, and no error.
void fill_side(double* values, std::uint32_t* errors, std::size_t first, std::size_t n, double bound)
{
  std::fill_n(values + first, n, bound);
  if (errors)
  {
    std::fill_n(errors + first, n, 0u);
  }
}

} // namespace

/// What one pool participant keeps between tasks: its region walker (the tapes simplified per
/// box, their interval evaluators and the batch runner, all rebound from box to box: no
/// evaluator is made per box), and the gathered samples of a tile.
struct TiledEvaluator::Worker
{
  RegionWalker walker;
  std::vector<std::vector<double>> in;
  std::vector<const double*> in_rows;
  std::vector<double> values;
  std::vector<std::uint32_t> errors;
  std::vector<std::vector<double>> attributes;
  std::vector<double*> attribute_rows;
  std::vector<std::size_t> index;
  std::size_t decided = 0;

  Worker(const std::shared_ptr<const Tape>& tape, const RegionWalkerOptions& options)
    : walker(tape, options)
  {
  }

  void size_buffers(std::size_t dimension, std::size_t samples, std::size_t attribute_count)
  {
    in.resize(dimension);
    in_rows.resize(dimension);
    for (std::size_t k = 0; k < dimension; ++k)
    {
      in[k].resize(samples);
      in_rows[k] = in[k].data();
    }
    values.resize(samples);
    errors.resize(samples);
    attributes.resize(attribute_count);
    attribute_rows.resize(attribute_count);
    for (std::size_t j = 0; j < attribute_count; ++j)
    {
      attributes[j].resize(samples);
      attribute_rows[j] = attributes[j].data();
    }
  }
};

/// A rectangle of the block's samples: runs [row0, row1) and axis-0 indices [column0, column1).
struct Rectangle
{
  std::size_t row0 = 0, row1 = 0;
  std::int64_t column0 = 0, column1 = 0;
};

namespace
{

/// Calls f(first, count) for the samples of each row of the rectangle.
template<class F>
void for_each_segment(std::span<const SampleRun> runs, const Rectangle& r, F&& f)
{
  for (std::size_t i = r.row0; i < r.row1; ++i)
  {
    const SampleRun& run = runs[i];
    const std::int64_t lo = std::max(r.column0, run.column);
    const std::int64_t hi = std::min(r.column1, run.column + static_cast<std::int64_t>(run.count));
    if (lo < hi)
    {
      f(run.first + static_cast<std::size_t>(lo - run.column), static_cast<std::size_t>(hi - lo));
    }
  }
}

/// Splits a rectangle that holds more than tile^2 samples: each side that is not much shorter
/// than the other is halved (on multiples of the tile); a side four times longer than the other
/// is cut in four, and a lone row in four (on multiples of tile^2). Always at least two parts.
std::vector<Rectangle> children(const Rectangle& r, std::size_t tile)
{
  const std::size_t rows = r.row1 - r.row0;
  const std::size_t columns = static_cast<std::size_t>(r.column1 - r.column0);
  std::vector<std::size_t> row_cut{ r.row0 };
  if (rows > tile && rows * 2 >= columns)
  {
    row_cut.push_back(r.row0 + (rows / 2 + tile - 1) / tile * tile);
  }
  row_cut.push_back(r.row1);
  const std::size_t unit = rows > 1 ? tile : tile * tile;
  const std::size_t parts = rows == 1 || columns >= 4 * rows ? 4 : (columns > tile && columns * 2 >= rows ? 2 : 1);
  std::vector<std::int64_t> column_cut{ r.column0 };
  for (std::size_t k = 1; k < parts; ++k)
  {
    const std::int64_t at =
      r.column0 + static_cast<std::int64_t>((columns * k / parts + unit - 1) / unit * unit);
    if (at > column_cut.back() && at < r.column1)
    {
      column_cut.push_back(at);
    }
  }
  column_cut.push_back(r.column1);
  std::vector<Rectangle> out;
  for (std::size_t i = 0; i + 1 < row_cut.size(); ++i)
  {
    for (std::size_t j = 0; j + 1 < column_cut.size(); ++j)
    {
      out.push_back({ row_cut[i], row_cut[i + 1], column_cut[j], column_cut[j + 1] });
    }
  }
  return out;
}

/// The rectangle of every run: all rows, the columns from the least to the greatest.
Rectangle bounding_rectangle(std::span<const SampleRun> runs)
{
  std::int64_t column_lo = std::numeric_limits<std::int64_t>::max();
  std::int64_t column_hi = std::numeric_limits<std::int64_t>::min();
  for (const SampleRun& run : runs)
  {
    column_lo = std::min(column_lo, run.column);
    column_hi = std::max(column_hi, run.column + static_cast<std::int64_t>(run.count));
  }
  return { 0, runs.size(), column_lo, column_hi };
}

} // namespace

/// A rectangle to evaluate on the pool, with the tape simplified for it so far.
struct TiledEvaluator::Task
{
  Rectangle rectangle;
  std::shared_ptr<const Tape> tape;
};

/// The quadtree of one task: boxes evaluated on intervals, decided ones filled (sign_only),
/// the tape simplified per box, the leaves (tiles) evaluated by the worker's batch runner.
struct TiledEvaluator::Walk
{
  std::span<const SampleRun> runs;
  std::span<const double* const> coordinates;
  std::size_t leaf_samples;
  std::size_t tile;
  double* values;
  std::uint32_t* errors;
  std::span<double* const> attributes;
  Worker& w;
  std::vector<Task>* tasks; // set in the serial phase: collect rectangles of <= task_samples
  std::size_t task_samples;
  bool sign_only;
  double iso;

  /// Whether a box's enclosure is of use: to decide its samples' side (sign_only) or to simplify
  /// the tape (a tape whose boxes stopped paying for it, like a blend, is not enclosed at all).
  bool enclosing(const RegionWalker::Region& region) const
  {
    return sign_only || w.walker.would_simplify(region);
  }

  /// With sign_only, fills the rectangle with the bound when the box's enclosure decides it.
  bool decided(const Rectangle& r, const IntervalResult& enclosure)
  {
    double bound = 0.0;
    if (!sign_only || !decides_side(enclosure, iso, bound))
    {
      return false;
    }
    for_each_segment(runs, r,
      [&](std::size_t first, std::size_t n)
      {
        fill_side(values, errors, first, n, bound);
        w.decided += n;
      });
    return true;
  }

  /// The rectangle's box from the ends of its segments (positions rise along axis 0 and are
  /// constant along a run in the others: SampleRun's contract), and its sample count.
  std::vector<Interval> box_of(const Rectangle& r, std::size_t& samples) const
  {
    std::vector<Interval> b = empty_box(coordinates.size());
    samples = 0;
    for_each_segment(runs, r,
      [&](std::size_t first, std::size_t n)
      {
        b[0].lo = std::min(b[0].lo, coordinates[0][first]);
        b[0].hi = std::max(b[0].hi, coordinates[0][first + n - 1]);
        for (std::size_t k = 1; k < b.size(); ++k)
        {
          b[k].lo = std::min(b[k].lo, coordinates[k][first]);
          b[k].hi = std::max(b[k].hi, coordinates[k][first]);
        }
        samples += n;
      });
    return b;
  }

  void leaf(const Rectangle& r, const RegionWalker::Region& region)
  {
    w.index.clear();
    for_each_segment(runs, r,
      [&](std::size_t first, std::size_t n)
      {
        for (std::size_t q = 0; q < n; ++q)
        {
          w.index.push_back(first + q);
        }
      });
    const std::size_t n = w.index.size();
    std::vector<Interval> b = empty_box(coordinates.size());
    for (std::size_t k = 0; k < coordinates.size(); ++k)
    {
      double* column = w.in[k].data();
      for (std::size_t i = 0; i < n; ++i)
      {
        column[i] = coordinates[k][w.index[i]];
      }
      const auto [lo, hi] = std::minmax_element(column, column + n);
      b[k] = { *lo, *hi };
    }
    if (enclosing(region) && decided(r, w.walker.enclose(region, b)))
    {
      return;
    }
    w.walker.evaluate(w.walker.descend(region), w.in_rows, n, w.values.data(), w.errors.data(),
      std::span<double* const>(w.attribute_rows));
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::size_t p = w.index[i];
      values[p] = w.values[i];
      if (errors)
      {
        errors[p] = w.errors[i];
      }
      for (std::size_t j = 0; j < attributes.size(); ++j)
      {
        if (attributes[j])
        {
          attributes[j][p] = w.attributes[j][i];
        }
      }
    }
  }

  void node(const Rectangle& r, const RegionWalker::Region& region)
  {
    std::size_t samples = 0;
    const std::vector<Interval> b = box_of(r, samples);
    if (samples == 0)
    {
      return;
    }
    if (samples <= leaf_samples)
    {
      leaf(r, region);
      return;
    }
    if (enclosing(region) && decided(r, w.walker.enclose(region, b)))
    {
      return;
    }
    const RegionWalker::Region below = w.walker.descend(region);
    for (const Rectangle& child : children(r, tile))
    {
      if (tasks && samples_in(child) <= task_samples)
      {
        tasks->push_back({ child, w.walker.tape(below) });
      }
      else
      {
        node(child, below);
      }
    }
  }

  std::size_t samples_in(const Rectangle& r) const
  {
    std::size_t n = 0;
    for_each_segment(runs, r, [&](std::size_t, std::size_t count) { n += count; });
    return n;
  }
};

namespace
{

RegionWalkerOptions walk_options(const TileOptions& options)
{
  RegionWalkerOptions o;
  o.jit = options.jit;
  return o;
}

} // namespace

TiledEvaluator::TiledEvaluator(std::shared_ptr<const Tape> tape, std::shared_ptr<ThreadPool> pool,
  const TileOptions& options)
  : tape_(std::move(tape))
  , pool_(std::move(pool))
  , tile_(std::max(1, options.tile))
  , sign_only_(options.sign_only)
  , iso_(options.iso)
  , walk_options_(walk_options(options))
  , top_(std::make_unique<Worker>(tape_, walk_options_))
{
  if (!pool_)
  {
    throw std::invalid_argument("TiledEvaluator: null pool");
  }
  workers_.resize(static_cast<std::size_t>(pool_->size()));
}

TiledEvaluator::~TiledEvaluator() = default;

std::size_t TiledEvaluator::evaluate(std::span<const double* const> inputs,
  std::span<const SampleRun> runs, std::size_t count, double* values, std::uint32_t* errors,
  std::span<double* const> attributes)
{
  if (count == 0 || runs.empty())
  {
    return 0;
  }
  const std::size_t dimension = tape_->input_count;
  if (inputs.size() < dimension)
  {
    throw std::invalid_argument("TiledEvaluator::evaluate: fewer input arrays than tape inputs");
  }
  const std::span<const double* const> coordinates = inputs.first(dimension);
  if (sign_only_ && std::any_of(attributes.begin(), attributes.end(),
                      [](const double* a) { return a != nullptr; }))
  {
    throw std::invalid_argument("TiledEvaluator: sign_only gives no attributes");
  }
  reset_counters();

  // The block: one simplification of the whole tape, on the caller's walker.
  RegionWalker& top_walker = top_->walker;
  std::vector<Interval> box = empty_box(dimension);
  grow(box, coordinates, 0, count);
  const IntervalResult enclosure = top_walker.enclose(top_walker.root(), box);
  double bound = 0.0;
  if (sign_only_ && decides_side(enclosure, iso_, bound))
  {
    fill_side(values, errors, 0, count, bound);
    decided_ += count;
    return 0;
  }
  const RegionWalker::Region block = top_walker.descend(top_walker.root());

  // The block is cut serially (simplifying as it goes) into tasks of at most (4 tile)^2 samples;
  // the tasks run on the pool, each a quadtree down to tiles of tile^2 samples.
  const std::size_t tile = static_cast<std::size_t>(tile_);
  const std::size_t leaf_samples = tile * tile;
  std::vector<Task> tasks;
  const std::size_t task_samples = 16 * tile * tile;
  const Rectangle whole = bounding_rectangle(runs);
  {
    Walk top{ runs, coordinates, leaf_samples, tile, values, errors, attributes, *top_, &tasks,
      task_samples, sign_only_, iso_ };
    top_->size_buffers(dimension, leaf_samples, attributes.size());
    if (top.samples_in(whole) <= task_samples)
    {
      tasks.push_back({ whole, top_walker.tape(block) });
    }
    else
    {
      top.node(whole, block);
    }
  }
  pool_->parallel_for(tasks.size(),
    [&](std::size_t t, int slot)
    {
      std::unique_ptr<Worker>& mine = workers_[static_cast<std::size_t>(slot)];
      if (!mine)
      {
        mine = std::make_unique<Worker>(tape_, walk_options_);
      }
      Worker& w = *mine;
      w.size_buffers(dimension, leaf_samples, attributes.size());
      Walk walk{ runs, coordinates, leaf_samples, tile, values, errors, attributes, w, nullptr, 0,
        sign_only_, iso_ };
      walk.node(tasks[t].rectangle, w.walker.root(tasks[t].tape));
    });
  return gather_counters();
}

void TiledEvaluator::reset_counters()
{
  top_->walker.reset_statistics();
  top_->decided = 0;
  for (auto& w : workers_)
  {
    if (w)
    {
      w->walker.reset_statistics();
      w->decided = 0;
    }
  }
}

std::size_t TiledEvaluator::gather_counters()
{
  std::size_t failures = 0;
  const auto gather = [&](const Worker& w)
  {
    failures += w.walker.statistics().failed_points;
    instructions_ += w.walker.statistics().instructions;
    decided_ += w.decided;
  };
  gather(*top_);
  for (const auto& w : workers_)
  {
    if (w)
    {
      gather(*w);
    }
  }
  return failures;
}

} // namespace frep::sample
