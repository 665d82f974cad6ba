// Conservative interval evaluation of a tape over a box: the result encloses F at every point of
// the box (never wrong; functions without a tight rule return the whole real line). Used to
// cull boxes that are certainly inside or outside. R-functions use their monotonicity in each
// argument (tight), not naive interval arithmetic on the expanded formula.
#pragma once

#include "Compiler/tape.h"
#include "Eval/interval.h"
#include "Eval/tape_simplifier.h"

#include <memory>
#include <span>
#include <vector>

namespace frep
{

struct IntervalResult
{
  /// Encloses F over the box (where no error occurs). The whole real line also stands for
  /// "unknown, possibly NaN" (e.g. an unguarded sqrt of a negative part, or an opaque call).
  Interval value;
  bool may_fail = false; ///< some point of the box may raise a run-time error
};

class IntervalEvaluator
{
public:
  explicit IntervalEvaluator(std::shared_ptr<const Tape> tape);

  /// Encloses F over the box given by one interval per tape input.
  IntervalResult evaluate(std::span<const Interval> box);

  /// The same, and records in `choices` (one per instruction of the tape) what the box decides
  /// about each instruction, for TapeSimplifier: Keep unless the instruction's result is one of
  /// its operands, or a boolean constant, at every point of the box (see tape_simplifier.h).
  /// Throws std::invalid_argument if choices.size() != tape().code.size().
  IntervalResult evaluate(std::span<const Interval> box, std::span<Choice> choices);

  const Tape& tape() const { return *tape_; }

  /// Evaluates `tape` from now on, keeping the buffers (for walks that evaluate many boxes, each
  /// with its own simplified tape). A `trusted` tape (one TapeSimplifier made) is not checked
  /// again. Rebinding the same tape costs nothing.
  void rebind(std::shared_ptr<const Tape> tape, bool trusted = false);

private:
  IntervalResult run(std::span<const Interval> box, Choice* choices);

  void prepare(bool fold); // the buffers and, with fold, the program below, from tape_

  std::shared_ptr<const Tape> tape_;
  // The tape with constant operands folded into their readers (eval::make_batch_program): a
  // quarter of the instructions of the models measured are Const, each an iteration of the loop.
  // Made by the constructor only: a rebound tape is evaluated for a few boxes, and folding it
  // cost the tiled sampler more than it saved (Benchmarks/README.md, 2026-12-03).
  bool folded_ = false;
  std::vector<Instruction> code_;
  std::vector<std::uint8_t> immediate_; // eval::Immediate per instruction of code_
  std::vector<std::uint32_t> origin_;   // its index in the tape (for choices)
  std::vector<Interval> slots_;        // encloses the slot's non-NaN values over the box
  std::vector<unsigned char> may_nan_; // the slot may be NaN somewhere in the box
};

} // namespace frep
