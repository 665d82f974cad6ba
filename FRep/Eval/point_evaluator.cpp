#include "Eval/point_evaluator.h"

#include "Eval/detail/instruction_value.h"
#include "Compiler/detail/tape_check.h"

#include <algorithm>
#include <cassert>
#include <limits>
#include <stdexcept>

namespace frep
{

PointEvaluator::PointEvaluator(std::shared_ptr<const Tape> tape)
  : tape_(std::move(tape))
{
  if (!tape_)
  {
    throw std::invalid_argument("PointEvaluator: null tape");
  }
  eval::check_tape(*tape_, "PointEvaluator");
  slots_.assign(tape_->slot_count, 0.0);
  std::size_t widest_in = 0;
  std::size_t widest_out = 0;
  call_scratch_.reserve(tape_->calls.size());
  for (const CallSite& site : tape_->calls)
  {
    // Scratch is made once per evaluator: evaluate() must not allocate per point.
    call_scratch_.push_back(site.function ? site.function->make_scratch() : nullptr);
    widest_in = std::max(widest_in, site.inputs.size());
    widest_out = std::max(widest_out, site.outputs.size());
  }
  call_in_.assign(widest_in, 0.0);
  call_out_.assign(widest_out, 0.0);
}

int PointEvaluator::evaluate(std::span<const double> inputs, std::span<double> outputs)
{
  const Tape& tape = *tape_;
  assert(inputs.size() >= tape.input_count);
  double* s = slots_.data();
  int error = 0;
  for (const Instruction& ins : tape.code)
  {
    switch (ins.op)
    {
      case Opcode::Input:
        s[ins.out] = inputs[static_cast<std::size_t>(ins.index)];
        break;
      case Opcode::ErrorIf:
        if (s[ins.a] != 0.0)
        {
          // Instructions are pure, so the rest cannot change the outcome: the first error in
          // program order wins and the outputs are NaN anyway.
          error = ins.index;
        }
        break;
      case Opcode::Call:
      {
        const CallSite& site = tape.calls[static_cast<std::size_t>(ins.index)];
        const std::size_t n_in = site.inputs.size();
        const std::size_t n_out = site.outputs.size();
        for (std::size_t k = 0; k < n_in; ++k)
        {
          call_in_[k] = s[site.inputs[k]];
        }
        const int status =
          site.function->evaluate(call_scratch_[static_cast<std::size_t>(ins.index)].get(),
            std::span<const double>(call_in_.data(), n_in),
            std::span<double>(call_out_.data(), n_out));
        if (status != 0)
        {
          error = status;
          break;
        }
        for (std::size_t k = 0; k < n_out; ++k)
        {
          s[site.outputs[k]] = call_out_[k];
        }
        break;
      }
      default:
        s[ins.out] = eval::apply(ins, s[ins.a], s[ins.b], s[ins.c]);
        break;
    }
    if (error != 0)
    {
      break;
    }
  }
  const std::size_t n = std::min(outputs.size(), tape.outputs.size());
  for (std::size_t k = 0; k < n; ++k)
  {
    outputs[k] = error != 0 ? std::numeric_limits<double>::quiet_NaN() : s[tape.outputs[k]];
  }
  return error;
}

double PointEvaluator::value(std::span<const double> inputs)
{
  double v = 0;
  evaluate(inputs, std::span<double>(&v, tape_->outputs.empty() ? 0 : 1));
  return tape_->outputs.empty() ? std::numeric_limits<double>::quiet_NaN() : v;
}

} // namespace frep
