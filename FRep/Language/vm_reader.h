// Reads the field's plain tape format (`.vm`: the Prospero Challenge, Fidget, MPR): one SSA
// instruction per line, `NAME OPCODE OPERAND...`, `#` comments, the last instruction the value,
// negative inside. It becomes a HyperFun program of one object `my_model(x[n], a[1])` whose
// value is the tape's with the sign flipped (FRep: F >= 0 inside), so every tool, filter and
// evaluator takes a .vm file wherever it takes a .hf file.
//
// Opcodes: const C, var-x, var-y, var-z, neg, square, sqrt, abs, add, sub, mul, div, min, max.
// Values are doubles: constants are read correctly rounded from their text (Fidget reads f32);
// min/max compare as HyperFun's max/min do; square a is a * a. sqrt of a negative value and a
// division by zero are run-time errors of that point (HyperFun's policy: the point is outside),
// where a float tape would give NaN or infinity.
#pragma once

#include "Language/parser.h"

#include <string>
#include <string_view>

namespace frep
{

/// Parses .vm text. Errors (file:line:col): unknown opcode, wrong operand count, an operand
/// that names no earlier instruction, a name defined twice, a constant that is not a finite
/// number, no instruction at all.
ParseResult parse_vm(std::string_view text, std::string file_name);

/// Whether a file name has the .vm extension (any case).
bool is_vm_file(std::string_view file_name);

} // namespace frep
