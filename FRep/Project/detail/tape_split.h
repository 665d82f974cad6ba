// A tape F(x', t) split where its kept inputs x' end: the prefix computes, from x' alone, the
// values the rest reads; the suffix computes F from those values and t. For one point x' the
// projector evaluates the prefix once and searches T with the suffix alone: Meta5D's key shapes
// (about 1100 instructions that depend on x1..x3 only) are then computed once per point instead
// of once per box of T, in intervals. Exact: the suffix runs the same instructions on the same
// doubles, so suffix(prefix(x'), t) is F(x', t) bit for bit, and an enclosure of the suffix with
// prefix(x') as degenerate intervals holds every such value.
#pragma once

#include "Compiler/tape.h"

#include <cstddef>
#include <memory>

namespace frep::project::detail
{

struct SplitTape
{
  /// Inputs: x' (the tape's first `kept`); outputs: the values the suffix reads (null when there
  /// are none and nothing in it can fail). A prefix that fails at x' fails every t.
  std::shared_ptr<const Tape> prefix;
  /// Inputs: the prefix's outputs, then t (the tape's eliminated inputs, in order); one output, F.
  std::shared_ptr<const Tape> suffix;
};

/// Splits `tape` (inputs: `kept` of x', then t). Instructions keep their order within each part.
SplitTape split_tape(const Tape& tape, std::size_t kept);

} // namespace frep::project::detail
