// Conservative interval evaluation of a tape over a box: the result encloses F at every point of
// the box (never wrong; functions without a tight rule return the whole real line). Used to
// cull boxes that are certainly inside or outside. R-functions use their monotonicity in each
// argument (tight), not naive interval arithmetic on the expanded formula.
#pragma once

#include "Compiler/tape.h"
#include "Eval/interval.h"
#include "Eval/tape_simplifier.h"

#include <cstdint>
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

/// What the evaluation of a box lets the boxes inside it skip (IntervalEvaluator::evaluate with
/// `outer` and `inner`). Where an operand of max/min or of an R-function is dominated over the
/// box (max/min: decided; an R-union: the operand is negative and at least twice as large in
/// magnitude as the other, so it moves the result by at most a tenth of its own change), its
/// instruction's result is frozen at its enclosure over this box, and every instruction that
/// only it read is skipped. Always sound: a sub-box's values of any instruction lie in its
/// enclosure over the box. Looser than evaluating the sub-box in full, and only ever used for
/// enclosures (culling); the values that reach an output come from the tape itself.
struct IntervalFreeze
{
  enum Action : std::uint8_t
  {
    Evaluate = 0,
    Skip = 1,  ///< no instruction that is evaluated reads it
    Frozen = 2 ///< its result is `value` (and NaN is possible when `nan`)
  };
  std::vector<std::uint8_t> action; ///< per instruction of the tape
  std::vector<Interval> value;      ///< per instruction: its enclosure over the box
  std::vector<std::uint8_t> nan;
  std::vector<std::uint32_t> active; ///< the instructions not skipped, in order
  std::size_t frozen = 0;
  std::size_t skipped = 0;
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

  /// The same for a box inside the box `outer` was made for (null: none), which may be skipped
  /// as it says; with `inner`, records each instruction's enclosure over this box, for
  /// make_freeze. `choices` may be empty; when given, instructions skipped keep Choice::Keep.
  IntervalResult evaluate(std::span<const Interval> box, std::span<Choice> choices,
    const IntervalFreeze* outer, IntervalFreeze* inner);
  /// Makes `inner` (recorded by the last evaluate) the freeze for boxes inside that box: what
  /// `outer` froze and skipped, and what this box dominates. False (and `inner` unusable) if the
  /// tape cannot be frozen (opaque calls). Worth it only when it skips a good part of the tape.
  bool make_freeze(const IntervalFreeze* outer, IntervalFreeze& inner);

  const Tape& tape() const { return *tape_; }

  /// After an evaluate: the enclosure of output `i` (0 is F, as evaluate returns) over its box in
  /// `value`; false when it may be NaN there (then `value` holds only the non-NaN values).
  bool output(std::size_t i, Interval& value) const;

  /// Evaluates `tape` from now on, keeping the buffers (for walks that evaluate many boxes, each
  /// with its own simplified tape). A `trusted` tape (one TapeSimplifier made) is not checked
  /// again. Rebinding the same tape costs nothing.
  void rebind(std::shared_ptr<const Tape> tape, bool trusted = false);

private:
  IntervalResult run(std::span<const Interval> box, Choice* choices,
    const IntervalFreeze* outer = nullptr, IntervalFreeze* inner = nullptr);
  void find_producers(); // producers_, for make_freeze

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
  std::vector<std::size_t> position_;   // the inverse: a tape index's in code_, or kNotInCode
  static constexpr std::size_t kNotInCode = ~std::size_t(0);
  std::vector<Interval> slots_;        // encloses the slot's non-NaN values over the box
  std::vector<unsigned char> may_nan_; // the slot may be NaN somewhere in the box
  // For freezing: the instruction whose result each operand (a, b, c) of each instruction reads
  // (-1: none or an unwritten slot), made on first use per tape.
  std::vector<std::int32_t> producers_;
  std::int32_t result_ = -1; // the instruction whose result is outputs[0]
  std::vector<std::uint8_t> needed_;
  std::vector<std::uint32_t> readers_, dominated_; // per instruction, for make_freeze
  std::vector<std::uint32_t> losers_;              // instructions some reader dominates
};

} // namespace frep
