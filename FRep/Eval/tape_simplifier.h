// Tape simplification per region: from the interval evaluation of a box, a shorter tape that
// computes, at every point of that box, exactly the values of the full tape (bit for bit, the
// same error ids). Only decisions that make an instruction's result *identical* to one of its
// operands or to a boolean constant are used:
//   - max(a, b) = (a > b) ? a : b and min(a, b) = (a < b) ? a : b with separated operand ranges
//     (NaN handled as the comparison does);
//   - Select with a decided condition;
//   - comparisons and logic whose result is the same everywhere in the box (1.0 or 0.0);
//   - ErrorIf whose condition is zero everywhere in the box (it can never fire there).
// The R-functions (Union, Intersect, blends) are never replaced by an operand: a decided operand
// does not make their value equal to the other operand's.
// Instructions that nothing reads any more are removed and the survivors get a compact register
// file, so the batch kernel's rows stay in cache. Used recursively: a child box simplifies its
// parent's simplified tape.
#pragma once

#include "Compiler/tape.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace frep
{

/// What the interval evaluation of a box decided about one instruction.
enum class Choice : std::uint8_t
{
  Keep,  ///< undecided: the instruction stays
  TakeA, ///< the result is operand a at every point of the box
  TakeB, ///< ... operand b
  TakeC, ///< ... operand c (Select's else branch)
  True,  ///< a boolean result that is 1.0 everywhere
  False, ///< a boolean result that is 0.0 everywhere
  Drop   ///< an ErrorIf that cannot fire in the box
};

/// Whether any instruction of the tape can be decided by a box (min, max, Select, comparisons,
/// logic, ErrorIf): if not, recording choices and simplifying is wasted work.
bool may_simplify(const Tape& tape);

/// Whether evaluating `simplified` instead of `from` pays for making its evaluators: it must be
/// at least 4 instructions and 1/8 shorter (below that, a new register file and batch program
/// per box cost more than the instructions saved; measured with Benchmarks/frep_mesh_benchmark).
bool worth_switching(const Tape& simplified, const Tape& from);

/// Reusable scratch for simplify(): one per thread (simplification allocates nothing once the
/// scratch has grown to the tape's size, except the result).
class TapeSimplifier
{
public:
  /// The tape specialised by `choices` (one per instruction of `tape`, as recorded by
  /// IntervalEvaluator::evaluate(box, choices)), or null when no choice simplifies anything (the
  /// caller keeps `tape`). The result is valid by construction (eval::check_tape need not run on
  /// it) and writes every slot before reading it (a 0 the full tape read from an unwritten slot
  /// becomes a Const). Throws std::invalid_argument if choices.size() != tape.code.size().
  std::shared_ptr<const Tape> simplify(const Tape& tape, std::span<const Choice> choices);

  /// Instructions of the last result (for statistics).
  std::size_t last_length() const { return last_length_; }

private:
  std::uint32_t find(std::uint32_t value);  // the representative of merged names
  std::uint32_t fresh_value();
  std::uint32_t demand(std::uint32_t slot); // the value wanted from slot (new if none yet)
  // The three passes of simplify (tape_simplifier.cpp): (1) what survives, as values, in ssa_;
  // (2) merged names resolved and last readers found; (3) registers, into the result.
  void keep_backward(const Tape& tape, std::span<const Choice> choices);
  void keep_call(const Tape& tape, const Instruction& ins, std::size_t i); // (1), a Call
  void resolve_names();
  std::shared_ptr<Tape> assign_registers(const Tape& tape);

  std::vector<std::uint32_t> wanted_;   // per original slot: value read from it later, or none
  std::vector<std::uint32_t> merged_;   // per value: union-find parent (renamed values)
  std::vector<Instruction> ssa_;        // surviving instructions, operands as values
  std::vector<std::vector<std::uint32_t>> site_inputs_, site_outputs_; // calls, as values
  std::vector<std::uint32_t> output_values_;
  std::vector<std::uint32_t> last_use_; // per value: index into ssa_ of its last reader
  std::vector<std::uint32_t> slot_of_;  // per value: its register in the result
  std::vector<std::uint32_t> free_slots_;
  std::size_t last_length_ = 0;
};

} // namespace frep
