// FRepKit tape -> libfive::Tree, instruction by instruction, so libfive evaluates and meshes the
// very function FRepKit's compiler produced from the .hf (libfive has no HyperFun reader).
//
// Exact counterparts: arithmetic, sqrt, exp, log, sin, cos, tan, asin, acos, atan, atan2, abs,
// min, max; R-functions as their formulas (Union = a + b + sqrt(a^2 + b^2), Intersect =
// a + b - sqrt(a^2 + b^2), Semantics/detail/op_semantics.h). By formula (same value up to
// rounding and except on the edge cases noted): log10, sinh/cosh/tanh through exp, a^n through
// libfive's integer pow (HyperFun's 0 for |a| < 1e-6 not kept), a^b for a non-constant b as exp(b log a),
// comparisons and logic through libfive's compare (-1/0/1), Select c ? b : a as a*b + (1-a)*c
// (NaN where the branch not taken is infinite). Run-time error checks (ErrorIf) are dropped:
// libfive has no errors, it yields NaN/inf. Anything else (floor, ceil, trunc, frac, fmod, mod,
// round, opaque library calls, more than 3 inputs) has no libfive counterpart: the translation
// fails and says which opcodes.
#pragma once

#include "Compiler/tape.h"

#include <libfive/tree/tree.hpp>

#include <cstddef>
#include <string>

namespace peers
{

struct LibfiveTranslation
{
  libfive::Tree tree = libfive::Tree::invalid(); ///< F (FRepKit's sign: >= 0 inside)
  std::string unsupported;       ///< opcodes with no counterpart (empty: the tree is valid)
  std::size_t dropped_checks = 0; ///< ErrorIf instructions left out
  std::size_t approximated = 0;   ///< instructions translated by formula (see above)
};

LibfiveTranslation tape_to_libfive(const frep::Tape& tape);

} // namespace peers
