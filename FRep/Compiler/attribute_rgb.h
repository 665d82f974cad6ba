// The model's attributes as colours, the way hfp -ct does it: s[1], s[2], s[3] are red, green
// and blue in [0, 1] (hfp writes them unchanged into VRML's Color node and averages them per
// triangle for POV-Ray). One rule for every output that colours by s[] — the CLI's mesh files,
// frepkit map's pictures, FRepStudio's views: each component is clamped to [0, 1] (VRML requires
// it; hfp wrote values outside as they were), a missing component (s_dim < 3) is 0, and NaN (a
// point whose evaluation failed) is 0.
#pragma once

#include "Compiler/tape.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace frep
{

/// Linear RGB in [0, 1].
using AttributeRgb = std::array<float, 3>;

/// The colour of one point from its attributes s[1..count] (`s` points at s[1]).
AttributeRgb attribute_rgb(const float* s, std::size_t count);

/// One colour per point from `attributes`, `count` values per point for `points` points (a
/// mesh::Surface's attributes, attribute_count and point_count()); empty when count is 0 or
/// there are fewer values than that.
std::vector<AttributeRgb> attribute_colours(const std::vector<float>& attributes,
  std::size_t count,
  std::size_t points);

/// True when one of the tape's s[1..count] (outputs 1..count) is not the constant 0, i.e. the
/// model sets it. A model whose header has no s[] still has s[1] (= 0): false then.
bool tape_sets_attributes(const Tape& tape, std::size_t count);

/// Colours are written when the object has s[3] or more and sets one of s[1..3].
bool tape_sets_colours(const Tape& tape, int s_dim);

/// A component in [0, 1] -> 0..255, rounded (clamped first).
std::uint8_t colour_byte(float component);

} // namespace frep
