#include "Eval/batch_evaluator.h"

#include "Eval/batch_kernel.h"
#include "Eval/batch_program.h"
#include "Compiler/tape_check.h"
#include "Eval/thread_pool.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <new>
#include <stdexcept>
#include <vector>

namespace frep
{

namespace
{

// 64-byte aligned doubles: whole cache lines per register row, aligned vector loads.
struct AlignedDoubles
{
  struct Free
  {
    void operator()(double* p) const { ::operator delete[](p, std::align_val_t(64)); }
  };
  std::unique_ptr<double[], Free> data;

  explicit AlignedDoubles(std::size_t n)
    : data(static_cast<double*>(::operator new[](n * sizeof(double), std::align_val_t(64))))
  {
    std::fill(data.get(), data.get() + n, 0.0);
  }
};

// Everything one participant of the pool writes while evaluating a block.
struct Participant
{
  AlignedDoubles regs;
  std::vector<const double*> rows; // where each slot's lanes are (see eval::Block::rows)
  std::vector<std::uint32_t> errors;
  eval::CallState calls;
  std::size_t failures = 0;

  Participant(const Tape& tape, int block)
    : regs(std::max<std::size_t>(tape.slot_count, 1) * static_cast<std::size_t>(block))
    , rows(std::max<std::size_t>(tape.slot_count, 1))
    , errors(static_cast<std::size_t>(block), 0)
  {
    for (std::size_t s = 0; s < rows.size(); ++s)
    {
      rows[s] = regs.data.get() + s * static_cast<std::size_t>(block);
    }
    std::size_t widest_in = 0;
    std::size_t widest_out = 0;
    for (const CallSite& site : tape.calls)
    {
      calls.scratch.push_back(site.function->make_scratch());
      widest_in = std::max(widest_in, site.inputs.size());
      widest_out = std::max(widest_out, site.outputs.size());
    }
    calls.in.assign(widest_in, 0.0);
    calls.out.assign(widest_out, 0.0);
  }
};

} // namespace

struct BatchEvaluator::Impl
{
  std::shared_ptr<const Tape> tape;
  eval::BatchProgram program;
  std::shared_ptr<ThreadPool> pool;
  int block = 256;
  SimdLevel simd = SimdLevel::Best;
  std::vector<std::unique_ptr<Participant>> participants; // made on first use, per pool slot
};

BatchEvaluator::BatchEvaluator(std::shared_ptr<const Tape> tape, const BatchOptions& options)
  : impl_(std::make_unique<Impl>())
{
  if (!tape)
  {
    throw std::invalid_argument("BatchEvaluator: null tape");
  }
  if (options.block_size <= 0)
  {
    throw std::invalid_argument("BatchEvaluator: block_size must be positive");
  }
  eval::check_tape(*tape, "BatchEvaluator");
  impl_->program = eval::make_batch_program(*tape);
  impl_->tape = std::move(tape);
  impl_->pool = options.pool ? options.pool : std::make_shared<ThreadPool>(options.threads);
  impl_->block = options.block_size;
  impl_->simd = options.simd;
  impl_->participants.resize(static_cast<std::size_t>(impl_->pool->size()));
}

BatchEvaluator::~BatchEvaluator() = default;

const Tape& BatchEvaluator::tape() const
{
  return *impl_->tape;
}

int BatchEvaluator::threads() const
{
  return impl_->pool->size();
}

std::size_t BatchEvaluator::evaluate(std::span<const double* const> inputs,
  std::size_t count,
  double* values,
  std::uint32_t* errors,
  std::span<double* const> attributes)
{
  Impl& im = *impl_;
  const Tape& tape = *im.tape;
  if (inputs.size() < tape.input_count)
  {
    throw std::invalid_argument("BatchEvaluator::evaluate: fewer input arrays than tape inputs");
  }
  if (count == 0)
  {
    return 0;
  }
  const std::size_t block = static_cast<std::size_t>(im.block);
  const std::size_t blocks = (count + block - 1) / block;
  const std::size_t attribute_count =
    std::min(attributes.size(), tape.outputs.empty() ? 0 : tape.outputs.size() - 1);
  for (auto& p : im.participants)
  {
    if (p)
    {
      p->failures = 0;
    }
  }
  const auto run = [&](std::size_t block_index, int slot)
  {
    std::unique_ptr<Participant>& mine = im.participants[static_cast<std::size_t>(slot)];
    if (!mine)
    {
      mine = std::make_unique<Participant>(tape, im.block);
    }
    Participant& p = *mine;
    const std::size_t base = block_index * block;
    const int n = static_cast<int>(std::min(block, count - base));
    std::fill(p.errors.begin(), p.errors.begin() + n, 0u);
    eval::Block blk;
    blk.regs = p.regs.data.get();
    blk.rows = p.rows.data();
    blk.errors = p.errors.data();
    blk.n = n;
    blk.stride = im.block;
    blk.inputs = inputs.data();
    blk.base = base;
    eval::run_block(tape, im.program, blk, p.calls, im.simd);

    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    const std::uint32_t* err = p.errors.data();
    const auto row = [&](std::uint32_t slot_index) { return p.rows[slot_index]; };
    std::size_t failed = 0;
    for (int i = 0; i < n; ++i)
    {
      failed += err[i] != 0;
    }
    p.failures += failed;
    // Copy an output row out; lanes that failed read NaN (the common case: none failed).
    const auto copy_out = [&](const double* source, double* target)
    {
      if (source == nullptr || failed == static_cast<std::size_t>(n))
      {
        // (a block whose lanes all failed may have stopped early: its rows are not written)
        std::fill(target, target + n, nan);
      }
      else if (failed == 0)
      {
        std::copy(source, source + n, target);
      }
      else
      {
        for (int i = 0; i < n; ++i)
        {
          const double v = source[i];
          target[i] = err[i] != 0 ? nan : v;
        }
      }
    };
    if (values)
    {
      copy_out(tape.outputs.empty() ? nullptr : row(tape.outputs[0]), values + base);
    }
    for (std::size_t j = 0; j < attribute_count; ++j)
    {
      if (attributes[j] != nullptr)
      {
        copy_out(row(tape.outputs[j + 1]), attributes[j] + base);
      }
    }
    if (errors)
    {
      std::copy(err, err + n, errors + base);
    }
  };
  // Hand blocks out in tasks of several blocks: one block is about a microsecond of work on a
  // short tape, comparable to the pool's hand-off. Keep at least 8 tasks per participant so
  // the dynamic schedule still balances. Below kSerialBlocks blocks waking the workers costs
  // more than it saves (measured: 4096 points ran slower on 2 threads than on 1): the caller
  // does it all.
  constexpr std::size_t kSerialBlocks = 32;
  const std::size_t participants = static_cast<std::size_t>(im.pool->size());
  const std::size_t per_task = blocks < kSerialBlocks
    ? blocks
    : std::clamp<std::size_t>(blocks / (8 * participants), 1, 64);
  const std::size_t tasks = (blocks + per_task - 1) / per_task;
  const auto run_task = [&](std::size_t task, int slot)
  {
    const std::size_t end = std::min(blocks, (task + 1) * per_task);
    for (std::size_t b = task * per_task; b < end; ++b)
    {
      run(b, slot);
    }
  };
  if (tasks == 1)
  {
    run_task(0, 0);
  }
  else
  {
    im.pool->parallel_for(tasks, run_task);
  }
  std::size_t failures = 0;
  for (auto& p : im.participants)
  {
    if (p)
    {
      failures += p->failures;
    }
  }
  return failures;
}

} // namespace frep
