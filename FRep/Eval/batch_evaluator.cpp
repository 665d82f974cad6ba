#include "Eval/batch_evaluator.h"

#include "Compiler/detail/tape_check.h"
#include "Eval/detail/block_runner.h"
#include "Eval/detail/jit_kernel.h"
#include "Eval/thread_pool.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace frep
{

struct BatchEvaluator::Impl
{
  std::shared_ptr<const Tape> tape;
  std::shared_ptr<ThreadPool> pool;
  int block = 256;
  SimdLevel simd = SimdLevel::Best;
  bool want_jit = false;
  bool jit_tried = false;
  std::shared_ptr<const eval::JitKernel> jit; // shared by the participants (thread-safe)

  /// Compiles the tape once, on first need (compiling costs about as much as interpreting a few
  /// hundred points, so an evaluator used for a handful of points never pays for it).
  void ensure_jit()
  {
    if (want_jit && !jit_tried)
    {
      jit = eval::JitKernel::compile(*tape);
      jit_tried = true;
    }
  }
  std::vector<std::unique_ptr<eval::BlockRunner>> participants; // made on first use, per slot
  std::vector<std::size_t> failures;                            // per slot, of one evaluate()
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
  impl_->tape = std::move(tape);
  impl_->pool = options.pool ? options.pool : std::make_shared<ThreadPool>(options.threads);
  impl_->block = options.block_size;
  impl_->simd = options.simd;
  impl_->want_jit = options.jit && options.simd >= SimdLevel::AVX2 && eval::jit_available() &&
    eval::jit_supports(*impl_->tape) && eval::jit_pays(*impl_->tape);
  impl_->participants.resize(static_cast<std::size_t>(impl_->pool->size()));
  impl_->failures.resize(impl_->participants.size());
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

bool BatchEvaluator::compiled() const
{
  impl_->ensure_jit();
  return impl_->jit != nullptr;
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
  std::fill(im.failures.begin(), im.failures.end(), 0);
  constexpr std::size_t kJitMinimumPoints = 512;
  if (count >= kJitMinimumPoints)
  {
    im.ensure_jit();
  }
  // A participant's runner, bound once per task (binding copies two shared pointers: atomic
  // counts that both threads would bounce between their caches block after block).
  const auto runner = [&](int slot) -> eval::BlockRunner&
  {
    std::unique_ptr<eval::BlockRunner>& mine = im.participants[static_cast<std::size_t>(slot)];
    if (!mine)
    {
      mine = std::make_unique<eval::BlockRunner>(im.block, im.simd);
    }
    mine->bind(im.tape, true, im.jit); // (checked by the constructor; the same tape costs nothing)
    return *mine;
  };
  const auto run = [&](eval::BlockRunner& mine, std::size_t block_index, int slot)
  {
    const std::size_t base = block_index * block;
    im.failures[static_cast<std::size_t>(slot)] += mine.run(inputs, base,
      static_cast<int>(std::min(block, count - base)), values, errors, attributes);
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
    eval::BlockRunner& mine = runner(slot);
    for (std::size_t b = task * per_task; b < end; ++b)
    {
      run(mine, b, slot);
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
  for (std::size_t f : im.failures)
  {
    failures += f;
  }
  return failures;
}

} // namespace frep
