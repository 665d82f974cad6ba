// Joining tapes: a finished tape is read back into a DAG, so that several tapes (the operands
// of a composed model) and new operations on their outputs become one DAG, which emit() turns
// into one tape with the usual dead-code elimination, scheduling and slot reuse. Reading a tape
// back is exact: every instruction becomes the node of the same opcode, and the DAG only folds
// and rewrites where the result is the same double (dag.h).
#pragma once

#include "Compiler/detail/lower.h"
#include "Compiler/tape.h"

#include <span>
#include <vector>

namespace frep::compiler
{

/// Appends `tape` to `out`: its Input k reads the node `inputs[k]`; its ErrorIf and Call
/// instructions become effects after those already in `out`, in tape order (so the first error
/// of a point stays the one reported); its error table is appended to out.errors, error ids
/// renumbered (a call site's function is wrapped so that the ids it returns are renumbered
/// too). Returns the nodes of the tape's outputs (value, s[1..]).
/// Throws std::invalid_argument for a malformed tape or a wrong number of inputs.
std::vector<NodeId> append_tape(Lowered& out, const Tape& tape, std::span<const NodeId> inputs);

} // namespace frep::compiler
