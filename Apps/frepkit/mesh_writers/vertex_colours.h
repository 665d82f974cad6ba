// Colours per point from the model's attributes, the way hfp -ct does it: s[1], s[2], s[3] are
// red, green and blue in [0, 1] (hfp writes them unchanged into VRML's Color node and averages
// them per triangle for POV-Ray). We clamp to [0, 1] (VRML requires it; hfp wrote values outside
// as they were), missing components (s_dim < 3) are 0, and NaN (a failed point) is 0.
#pragma once

#include "Compiler/tape.h"
#include "mesh_document.h"

#include <cstdint>
#include <vector>

namespace frepkit
{

/// One colour per point of `surface` from its attributes (empty if it has none).
std::vector<Rgb> colours_from_attributes(const frep::mesh::Surface& surface);

/// True when one of the tape's s[1..count] (outputs 1..count) is not the constant 0, i.e. the
/// model sets it. A model whose header has no s[] still has s[1] (= 0): false then.
bool tape_sets_attributes(const frep::Tape& tape, std::size_t count);

/// Colours are written when the object has s[3] or more and sets one of s[1..3].
inline bool tape_sets_colours(const frep::Tape& tape, int s_dim)
{
  return s_dim >= 3 && tape_sets_attributes(tape, 3);
}

/// [0, 1] -> 0..255, rounded.
std::uint8_t colour_byte(float component);

} // namespace frepkit
