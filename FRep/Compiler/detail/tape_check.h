// Structural check of a tape before an evaluator trusts its slot indices: a malformed tape
// (from a buggy producer or a hand-built test) is refused with a message instead of reading
// outside the register file.
#pragma once

#include "Compiler/tape.h"

namespace frep::eval
{

/// Throws std::invalid_argument naming `who` and the first bad instruction, slot or call site.
void check_tape(const Tape& tape, const char* who);

/// Whether the opcode reads operand b / operand c (so only those are range-checked).
bool reads_b(Opcode op);
bool reads_c(Opcode op);
/// Whether the opcode reads operand a.
bool reads_a(Opcode op);

} // namespace frep::eval
