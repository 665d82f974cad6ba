// Reads the field's plain tape format (`.vm`: the Prospero Challenge, Fidget, MPR): one SSA
// instruction per line, `NAME OPCODE OPERAND...`, `#` comments, the last instruction the value,
// negative inside. It becomes a HyperFun program of one object `my_model(x[n], a[1])` whose
// value is the tape's with the sign flipped (FRep: F >= 0 inside), so every tool, filter and
// evaluator takes a .vm file wherever it takes a .hf file.
//
// Opcodes (Fidget's text format, plus recip, an opcode of Fidget's that its reader lacks; MPR
// reads libfive trees and has no text reader): const C,
// var-x, var-y, var-z; neg square sqrt abs recip exp ln sin cos tan asin acos atan floor ceil
// round not (one operand); add sub mul div min max atan2 compare and or mod (two). Fidget's
// rand and mix (pseudo-random hashes of f32 bit patterns) are refused: no double rule exists.
//
// Values are doubles and follow Fidget's rules (f32 there) where they give a number, and
// HyperFun's run-time errors (the point is outside) where a float tape gives NaN or infinity:
// - const: correctly rounded from its text (Fidget reads f32). square a = a * a.
// - min/max compare as HyperFun's max/min do (a < b ? a : b); Fidget propagates NaN.
// - sqrt a: error for a < 0. ln a: error for a <= 0 (Fidget -inf / NaN). asin, acos: error for
//   |a| > 1 (NaN). exp, sin, cos, atan, atan2 a b = atan2(a, b), floor, ceil: C's, no error
//   (exp may overflow to inf, as Fidget's).
// - div a b, recip a = 1 / a: HyperFun's division, an error for |divisor| < 1e-6. Differs from
//   Fidget for 0 < |divisor| < 1e-6, where a float tape has a finite quotient.
// - tan a: HyperFun's, an error where |cos a| < 1e-6 (Fidget: a finite value above ~1e6).
// - round a: half away from zero (C round, Rust's round; not HyperFun's round-half-up),
//   exactly: int(a) + int(2 * frac(a)).
// - compare a b: -1 if a < b, 1 if a > b, 0 if equal (inf == inf too), NaN if either is NaN.
// - and a b = (a == 0 ? a : b); or a b = (a != 0 ? a : b); not a = (a == 0 ? 1 : 0): exact
//   zero tests (-0 is zero, NaN is not), not HyperFun's |v| >= 1e-6 truthiness.
// - mod a b: Rust's rem_euclid, r = fmod(a, b), r < 0 ? r + |b| : r (in [0, |b|], = |b| only
//   when r + |b| rounds up; -0 for a negative exact multiple), bit for bit while
//   |a / b| < 2^52 (beyond that the value is not fmod's); |b| < 1e-6 is HyperFun's division
//   error, as div; fmod(inf, b) is NaN (no error), mod a inf = a (a >= 0) or inf.
// Choices become if-statements over exact comparisons, which the compiler merges with Select:
// a .vm model always compiles to a straight-line tape (no interpreter fallback). fmod, which
// the language lacks, is built from exact arithmetic (about 40 tape instructions per mod).
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
