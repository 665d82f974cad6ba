#include "Sample/grid_sampler.h"

#include "Eval/batch_evaluator.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/tape_simplifier.h"
#include "Eval/thread_pool.h"
#include "Sample/detail/tiled_evaluation.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <new>
#include <sstream>

namespace frep
{
namespace
{

// Samples per block: enough batch blocks (256 samples each) for the batch evaluator to spread
// over the pool (it runs fewer than 32 blocks on the caller alone), few enough for progress
// reports and cancel checks several times a second and for block buffers that stay in cache.
constexpr std::size_t block_samples = std::size_t(1) << 16;
// Samples per gradient task: one GradientEvaluator call is ~0.1-1 us, so a task is well above
// the pool's hand-off cost and a block still makes 64 tasks.
constexpr std::size_t gradient_chunk = 1024;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The sample counter of the part: the index on every axis of the next sample (axis 0 fastest)
// and the position of axes 1.. (constant along a row of axis 0).
class PartCursor
{
public:
  explicit PartCursor(const GridSpec& grid)
    : axes_(grid.axes)
  {
    for (const GridAxis& axis : axes_)
    {
      step_.push_back(grid_step(axis.lo, axis.hi, axis.samples));
      index_.push_back(axis.begin);
      position_.push_back(grid_coordinate(axis.lo, step_.back(), axis.begin));
    }
  }

  // Writes the coordinates of the next `count` samples into coordinates[k][0..count), and their
  // runs along axis 0 into `runs`.
  void fill(std::vector<std::vector<double>>& coordinates, std::size_t count,
    std::vector<sample::SampleRun>& runs)
  {
    const std::size_t dimension = axes_.size();
    runs.clear();
    std::size_t p = 0;
    while (p < count)
    {
      // The rest of the current row of axis 0, or of the block.
      const std::int64_t row_end = axes_[0].part_end();
      const std::size_t run =
        std::min(count - p, static_cast<std::size_t>(row_end - index_[0]));
      runs.push_back({ p, run, index_[0] });
      double* x = coordinates[0].data() + p;
      for (std::size_t q = 0; q < run; ++q)
      {
        x[q] = grid_coordinate(axes_[0].lo, step_[0], index_[0] + static_cast<std::int64_t>(q));
      }
      for (std::size_t k = 1; k < dimension; ++k)
      {
        std::fill_n(coordinates[k].data() + p, run, position_[k]);
      }
      p += run;
      index_[0] += static_cast<std::int64_t>(run);
      // Carry into the higher axes at the end of a row.
      for (std::size_t k = 0; k + 1 < dimension && index_[k] == axes_[k].part_end(); ++k)
      {
        index_[k] = axes_[k].begin;
        position_[k] = grid_coordinate(axes_[k].lo, step_[k], index_[k]);
        ++index_[k + 1];
        position_[k + 1] = grid_coordinate(axes_[k + 1].lo, step_[k + 1], index_[k + 1]);
      }
    }
  }

private:
  const std::vector<GridAxis>& axes_;
  std::vector<double> step_;
  std::vector<std::int64_t> index_;
  std::vector<double> position_;
};

// One pool participant's gradient evaluator and the point it evaluates at.
struct GradientSlot
{
  std::unique_ptr<GradientEvaluator> evaluator;
  std::vector<double> point;
};

/// A block's buffers, in structure of arrays as the batch evaluator reads and writes them.
struct BlockBuffers
{
  std::vector<std::vector<double>> coordinates;
  std::vector<const double*> inputs;
  std::vector<double> values;
  std::vector<std::uint32_t> errors;
  std::vector<std::uint8_t> failed;
  std::vector<std::vector<double>> attributes;
  std::vector<double*> attribute_out;
  std::vector<const double*> attribute_in;
  std::vector<double> gradients;

  BlockBuffers(std::size_t dimension, std::size_t block, std::size_t attribute_count,
    bool with_gradients)
    : coordinates(dimension, std::vector<double>(block))
    , values(block)
    , errors(block)
    , failed(block)
    , attributes(attribute_count, std::vector<double>(block))
    , gradients(with_gradients ? block * dimension : 0)
  {
    for (const auto& column : coordinates)
    {
      inputs.push_back(column.data());
    }
    for (auto& column : attributes)
    {
      attribute_out.push_back(column.data());
      attribute_in.push_back(column.data());
    }
  }
  BlockBuffers(const BlockBuffers&) = delete;
  BlockBuffers& operator=(const BlockBuffers&) = delete;
};

/// failed[p]: sample p raised an error or is NaN. (Through plain pointers: a byte store could
/// otherwise change the buffers' own pointers, reloaded per sample.)
void mark_failed(const std::uint32_t* errors, const double* values, std::size_t count,
  std::uint8_t* failed)
{
  for (std::size_t p = 0; p < count; ++p)
  {
    failed[p] = errors[p] != 0 || std::isnan(values[p]) ? 1 : 0;
  }
}

/// The gradients of the block's first `count` samples that did not fail: pointwise evaluators,
/// one per pool slot, over chunks of the block.
void block_gradients(ThreadPool& pool, const std::shared_ptr<const Tape>& tape,
  std::vector<GradientSlot>& slots, BlockBuffers& b, std::size_t count)
{
  const std::size_t dimension = b.coordinates.size();
  const std::size_t tasks = (count + gradient_chunk - 1) / gradient_chunk;
  pool.parallel_for(tasks,
    [&](std::size_t task, int slot)
    {
      GradientSlot& s = slots[static_cast<std::size_t>(slot)];
      if (!s.evaluator)
      {
        s.evaluator = std::make_unique<GradientEvaluator>(tape);
        s.point.resize(dimension);
      }
      const std::size_t end = std::min(count, (task + 1) * gradient_chunk);
      for (std::size_t p = task * gradient_chunk; p < end; ++p)
      {
        if (b.failed[p])
        {
          continue; // the policy fills it in
        }
        for (std::size_t k = 0; k < dimension; ++k)
        {
          s.point[k] = b.coordinates[k][p];
        }
        s.evaluator->evaluate(
          s.point, std::span<double>(b.gradients.data() + p * dimension, dimension));
      }
    });
}

/// The last successful sample's values, for FailurePolicy::Previous (0 before the first).
struct PreviousSample
{
  double value = 0.0;
  std::vector<double> attributes;
  std::vector<double> gradient;
};

/// Failed samples of the block [first, first + count), in order: counted (the first one's
/// position and error kept in `result`), then NaN or the previous sample's values (the previous
/// sample is final by then: it succeeded or was itself filled in before).
void fill_failed(BlockBuffers& b, std::size_t first, std::size_t count, bool gradients,
  FailurePolicy policy, PreviousSample& previous, SampleResult& result)
{
  const std::size_t dimension = b.coordinates.size();
  const std::size_t attribute_count = b.attributes.size();
  for (std::size_t p = 0; p < count; ++p)
  {
    double* g = gradients ? b.gradients.data() + p * dimension : nullptr;
    if (!b.failed[p])
    {
      previous.value = b.values[p];
      for (std::size_t j = 0; j < attribute_count; ++j)
      {
        previous.attributes[j] = b.attributes[j][p];
      }
      if (g)
      {
        std::copy_n(g, dimension, previous.gradient.data());
      }
      continue;
    }
    if (result.failed++ == 0)
    {
      result.first_failed = static_cast<std::int64_t>(first + p);
      result.first_error = b.errors[p];
      for (std::size_t k = 0; k < dimension; ++k)
      {
        result.first_failed_at.push_back(b.coordinates[k][p]);
      }
    }
    const bool hfp = policy == FailurePolicy::Previous;
    b.values[p] = hfp ? previous.value : nan;
    for (std::size_t j = 0; j < attribute_count; ++j)
    {
      b.attributes[j][p] = hfp ? previous.attributes[j] : nan;
    }
    for (std::size_t k = 0; g && k < dimension; ++k)
    {
      g[k] = hfp ? previous.gradient[k] : nan;
    }
  }
}

/// The tiled evaluator (tile by tile, tapes simplified per tile) when the tape has anything a
/// box can decide or only the side of iso is asked for; else null (the batch evaluator).
std::unique_ptr<sample::TiledEvaluator> make_tiled(const std::shared_ptr<const Tape>& tape,
  const std::shared_ptr<ThreadPool>& pool, const SampleOptions& options)
{
  if (!options.sign_only && !(options.simplify && may_simplify(*tape)))
  {
    return nullptr;
  }
  sample::TileOptions tiles;
  tiles.sign_only = options.sign_only;
  tiles.iso = options.iso;
  tiles.jit = options.jit;
  return std::make_unique<sample::TiledEvaluator>(tape, pool, tiles);
}

} // namespace

std::size_t grid_part_size(const GridSpec& grid)
{
  if (grid.axes.empty())
  {
    return 0;
  }
  std::size_t total = 1;
  for (const GridAxis& axis : grid.axes)
  {
    const std::int64_t n = axis.part_end() - axis.begin;
    total *= n > 0 ? static_cast<std::size_t>(n) : 0;
  }
  return total;
}

std::string check_grid(const GridSpec& grid, std::uint32_t inputs, const SampleOptions& options)
{
  std::ostringstream message;
  if (grid.axes.empty() || grid.axes.size() != inputs)
  {
    message << "the grid has " << grid.axes.size() << " axes; the object has " << inputs
            << " free coordinate" << (inputs == 1 ? "" : "s")
            << " (one axis per free coordinate, at least one)";
    return message.str();
  }
  if (std::string axes = check_grid_axes(grid, 1); !axes.empty())
  {
    return axes;
  }
  std::vector<std::int64_t> samples;
  for (const GridAxis& axis : grid.axes)
  {
    samples.push_back(axis.samples);
  }
  if (std::string size = check_grid_size(samples, options.max_samples,
        "SampleOptions::max_samples");
    !size.empty())
  {
    return size + "; refused before allocating anything";
  }
  if (options.attribute_count < -1)
  {
    return "attribute_count must be -1 (all), 0 (none) or a number of s[] values";
  }
  if (options.sign_only && (options.attribute_count != 0 || options.gradients))
  {
    return "sign_only sampling gives F's side of iso only: no attributes or gradients";
  }
  return {};
}

SampleResult sample_grid(std::shared_ptr<const Tape> tape, const GridSpec& grid,
  const SampleOptions& options, const SampleSink& sink)
{
  SampleResult result;
  if (!tape)
  {
    result.error = "no model to sample";
    return result;
  }
  result.error = check_grid(grid, tape->input_count, options);
  if (!result.error.empty())
  {
    return result;
  }
  try
  {
    const std::size_t dimension = grid.axes.size();
    const std::size_t available = tape->outputs.empty() ? 0 : tape->outputs.size() - 1;
    const std::size_t attribute_count = options.attribute_count < 0
      ? available
      : std::min(available, static_cast<std::size_t>(options.attribute_count));
    const FailurePolicy policy = options.failures;

    std::shared_ptr<ThreadPool> pool = options.thread_pool();
    BatchOptions batch_options;
    batch_options.pool = pool;
    batch_options.jit = options.jit;
    BatchEvaluator batch(tape, batch_options);
    result.threads = batch.threads();
    const std::unique_ptr<sample::TiledEvaluator> tiled = make_tiled(tape, pool, options);
    std::vector<sample::SampleRun> runs;

    const std::size_t total = grid_part_size(grid);
    const std::size_t block = std::min(total, block_samples);
    BlockBuffers b(dimension, block, attribute_count, options.gradients);
    std::vector<GradientSlot> slots(options.gradients ? static_cast<std::size_t>(pool->size()) : 0);
    PreviousSample previous;
    previous.attributes.assign(attribute_count, 0.0);
    previous.gradient.assign(options.gradients ? dimension : 0, 0.0);

    const auto stop = [&](double fraction)
    {
      const bool go_on = !options.progress || options.progress(fraction);
      return !go_on || options.cancel_requested();
    };
    PartCursor cursor(grid);
    if (stop(0.0))
    {
      result.cancelled = true;
      return result;
    }
    for (std::size_t first = 0; first < total;)
    {
      const std::size_t count = std::min(block, total - first);
      cursor.fill(b.coordinates, count, runs);
      if (tiled)
      {
        result.errors += tiled->evaluate(std::span<const double* const>(b.inputs), runs, count,
          b.values.data(), b.errors.data(), std::span<double* const>(b.attribute_out));
      }
      else
      {
        result.errors += batch.evaluate(std::span<const double* const>(b.inputs), count,
          b.values.data(), b.errors.data(), std::span<double* const>(b.attribute_out));
        result.instructions += count * tape->code.size();
      }
      mark_failed(b.errors.data(), b.values.data(), count, b.failed.data());
      if (options.gradients)
      {
        block_gradients(*pool, tape, slots, b, count);
      }
      fill_failed(b, first, count, options.gradients, policy, previous, result);

      SampleBlock out;
      out.first = first;
      out.count = count;
      out.coordinates = b.inputs;
      out.values = b.values.data();
      out.attributes = b.attribute_in;
      out.gradients = options.gradients ? b.gradients.data() : nullptr;
      out.failed = b.failed.data();
      if (sink)
      {
        sink(out);
      }
      result.samples += count;
      first += count;
      // A request to stop after the last block changes nothing: the work is complete.
      if (stop(static_cast<double>(first) / static_cast<double>(total)) && first < total)
      {
        result.cancelled = true;
        break;
      }
    }
    if (tiled)
    {
      result.instructions += tiled->instructions();
      result.decided = tiled->decided();
    }
  }
  catch (const std::bad_alloc&)
  {
    result.error = "not enough memory to sample the grid";
  }
  catch (const std::exception& e)
  {
    result.error = std::string("sampling failed: ") + e.what();
  }
  return result;
}

} // namespace frep
