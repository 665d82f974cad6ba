// Tape emission: from a lowered object (DAG + ordered effects + outputs) to straight-line code.
#pragma once

#include "Compiler/detail/lower.h"
#include "Compiler/tape.h"

#include <memory>

namespace frep::compiler
{

/// Emits only what the outputs and the effects need (dead code elimination), effects in
/// evaluation order (so the first error of a point is the one reported), each pure node just
/// before its first use, and allocates slots by linear scan on last use so the register file
/// stays small. An instruction's output never shares a slot with its own operands.
std::shared_ptr<Tape> emit(const Lowered& lowered);

} // namespace frep::compiler
