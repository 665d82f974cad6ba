#include "Eval/detail/block_runner.h"

#include "Compiler/detail/tape_check.h"

#include <algorithm>
#include <limits>
#include <new>
#include <stdexcept>

namespace frep::eval
{

namespace
{

/// Whether some instruction reads a slot that no earlier instruction wrote (it then reads the
/// register file's initial 0).
bool reads_unwritten_slot(const Tape& tape)
{
  std::vector<unsigned char> written(tape.slot_count, 0);
  const auto unwritten = [&](std::uint32_t s) { return s < written.size() && !written[s]; };
  for (const Instruction& ins : tape.code)
  {
    if (ins.op == Opcode::Call)
    {
      const CallSite& site = tape.calls[static_cast<std::size_t>(ins.index)];
      if (std::any_of(site.inputs.begin(), site.inputs.end(), unwritten))
      {
        return true;
      }
      for (std::uint32_t s : site.outputs)
      {
        written[s] = 1;
      }
      continue;
    }
    const int reads = operand_count(ins.op);
    if ((reads >= 1 && unwritten(ins.a)) || (reads >= 2 && unwritten(ins.b)) ||
      (reads >= 3 && unwritten(ins.c)))
    {
      return true;
    }
    if (ins.op != Opcode::ErrorIf && ins.out < written.size())
    {
      written[ins.out] = 1;
    }
  }
  return std::any_of(tape.outputs.begin(), tape.outputs.end(), unwritten);
}

} // namespace

void BlockRunner::AlignedFree::operator()(double* p) const
{
  ::operator delete[](p, std::align_val_t(64));
}

BlockRunner::BlockRunner(int block, SimdLevel simd)
  : block_(block)
  , simd_(simd)
{
  if (block_ <= 0)
  {
    throw std::invalid_argument("BatchEvaluator: block_size must be positive");
  }
  lane_errors_.assign(static_cast<std::size_t>(block_), 0);
}

BlockRunner::~BlockRunner() = default;

void BlockRunner::bind(std::shared_ptr<const Tape> tape, bool trusted,
  std::shared_ptr<const JitKernel> jit)
{
  if (!tape)
  {
    throw std::invalid_argument("BatchEvaluator: null tape");
  }
  if (tape == tape_)
  {
    jit_ = std::move(jit);
    if (!jit_ && program_.code.empty() && !tape_->code.empty())
    {
      program_ = make_batch_program(*tape_); // it ran machine code until now
    }
    return;
  }
  jit_ = std::move(jit);
  bool clear = false;
  if (!trusted)
  {
    // The last untrusted tape is remembered: walks come back to their root tape often.
    if (tape != checked_)
    {
      check_tape(*tape, "BatchEvaluator");
      checked_ = tape;
      checked_reads_unwritten_ = reads_unwritten_slot(*tape);
    }
    clear = checked_reads_unwritten_;
  }
  if (jit_)
  {
    program_ = BatchProgram{}; // the machine code replaces it
  }
  else
  {
    program_ = make_batch_program(*tape);
  }
  // 64-byte aligned rows: whole cache lines per register row, aligned vector loads. A slot read
  // before it is written reads 0, so the rows are cleared for a tape that does so; a trusted
  // (simplified) tape never does (it writes such a 0 itself), and then a reused register file
  // needs no clearing.
  const std::size_t slots = std::max<std::size_t>(tape->slot_count, 1);
  const std::size_t needed = slots * static_cast<std::size_t>(block_);
  if (needed > reg_capacity_)
  {
    regs_.reset(static_cast<double*>(::operator new[](needed * sizeof(double), std::align_val_t(64))));
    std::fill(regs_.get(), regs_.get() + needed, 0.0);
    reg_capacity_ = needed;
  }
  else if (clear)
  {
    std::fill(regs_.get(), regs_.get() + needed, 0.0);
  }
  rows_.resize(slots);
  for (std::size_t s = 0; s < slots; ++s)
  {
    rows_[s] = regs_.get() + s * static_cast<std::size_t>(block_);
  }
  calls_.scratch.clear();
  std::size_t widest_in = 0;
  std::size_t widest_out = 0;
  for (const CallSite& site : tape->calls)
  {
    calls_.scratch.push_back(site.function->make_scratch());
    widest_in = std::max(widest_in, site.inputs.size());
    widest_out = std::max(widest_out, site.outputs.size());
  }
  calls_.in.assign(widest_in, 0.0);
  calls_.out.assign(widest_out, 0.0);
  tape_ = std::move(tape);
}

std::size_t BlockRunner::run(std::span<const double* const> inputs, std::size_t base, int n,
  double* values, std::uint32_t* errors, std::span<double* const> attributes)
{
  const Tape& tape = *tape_;
  if (jit_ && !tape.can_fail && !tape.outputs.empty())
  {
    return run_jit_direct(inputs, base, n, values, errors, attributes);
  }
  std::fill(lane_errors_.begin(), lane_errors_.begin() + n, 0u);
  Block blk;
  blk.regs = regs_.get();
  blk.rows = rows_.data();
  blk.errors = lane_errors_.data();
  blk.n = n;
  blk.stride = block_;
  blk.inputs = inputs.data();
  blk.base = base;
  if (jit_)
  {
    run_jit(inputs, base, n);
  }
  else
  {
    run_block(tape, program_, blk, calls_, simd_);
  }

  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const std::uint32_t* err = lane_errors_.data();
  std::size_t failed = 0;
  for (int i = 0; i < n; ++i)
  {
    failed += err[i] != 0;
  }
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
    copy_out(tape.outputs.empty() ? nullptr : rows_[tape.outputs[0]], values + base);
  }
  const std::size_t attribute_count =
    std::min(attributes.size(), tape.outputs.empty() ? 0 : tape.outputs.size() - 1);
  for (std::size_t j = 0; j < attribute_count; ++j)
  {
    if (attributes[j] != nullptr)
    {
      copy_out(rows_[tape.outputs[j + 1]], attributes[j] + base);
    }
  }
  if (errors)
  {
    std::copy(err, err + n, errors + base);
  }
  return failed;
}

void BlockRunner::point_jit_inputs(std::span<const double* const> inputs, std::size_t base)
{
  jit_inputs_.resize(tape_->input_count);
  for (std::size_t k = 0; k < jit_inputs_.size(); ++k)
  {
    jit_inputs_[k] = inputs[k] + base;
  }
  jit_outputs_.resize(tape_->outputs.size());
}

double* BlockRunner::output_row(std::size_t j) const
{
  return regs_.get() + static_cast<std::size_t>(tape_->outputs[j]) * static_cast<std::size_t>(block_);
}

void BlockRunner::run_jit(std::span<const double* const> inputs, std::size_t base, int n)
{
  point_jit_inputs(inputs, base);
  // The outputs land in their slots' own rows, where run() copies them from.
  for (std::size_t j = 0; j < jit_outputs_.size(); ++j)
  {
    jit_outputs_[j] = output_row(j);
    rows_[tape_->outputs[j]] = jit_outputs_[j];
  }
  jit_->run(jit_inputs_.data(), jit_outputs_.data(), lane_errors_.data(), static_cast<std::size_t>(n));
}

std::size_t BlockRunner::run_jit_direct(std::span<const double* const> inputs, std::size_t base,
  int n, double* values, std::uint32_t* errors, std::span<double* const> attributes)
{
  // No lane can fail, so no output needs a NaN put in: the kernel writes straight into the
  // caller's arrays (outputs nobody asked for go to their slot rows) and nothing is copied.
  point_jit_inputs(inputs, base);
  for (std::size_t j = 0; j < jit_outputs_.size(); ++j)
  {
    double* target = j == 0 ? values : (j - 1 < attributes.size() ? attributes[j - 1] : nullptr);
    jit_outputs_[j] = target ? target + base : output_row(j);
  }
  jit_->run(jit_inputs_.data(), jit_outputs_.data(), nullptr, static_cast<std::size_t>(n));
  if (errors)
  {
    std::fill(errors + base, errors + base + n, 0u);
  }
  return 0;
}

std::size_t BlockRunner::evaluate(std::span<const double* const> inputs, std::size_t count,
  double* values, std::uint32_t* errors, std::span<double* const> attributes)
{
  if (inputs.size() < tape_->input_count)
  {
    throw std::invalid_argument("BatchEvaluator::evaluate: fewer input arrays than tape inputs");
  }
  std::size_t failed = 0;
  const std::size_t block = static_cast<std::size_t>(block_);
  for (std::size_t base = 0; base < count; base += block)
  {
    failed += run(inputs, base, static_cast<int>(std::min(block, count - base)), values, errors,
      attributes);
  }
  return failed;
}

} // namespace frep::eval
