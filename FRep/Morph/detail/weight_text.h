// Internal: the HyperFun statements of a metamorphosis's object (morph_text.h): the keys' space
// copied into a local array, each lattice axis's weights by the same operations as
// lattice_weights.cpp (so the values agree to the last bit where the compiler does not
// contract), each key called where its weight is not 0, and the blend axis by axis.
#pragma once

#include "Morph/key_frame.h"
#include "Morph/lattice_weights.h"

#include <string>
#include <vector>

namespace frep::morph::weight_text
{

/// A key's normalisation by distance (key_distance.h): the function the text calls and the band
/// within which the key's own F is kept.
struct KeyNormal
{
  std::string function;
  double band = 0.0;
};

/// Key k's node on each lattice axis (the first axis fastest: k = i_0 + n_0 (i_1 + ...)).
std::vector<int> lattice_indices(std::size_t k, const std::vector<int>& lattice);

/// "0", "0.25", "0.3333": node i of an axis of n, for comments.
std::string node_value(int i, int n);

/// The statements that set mw<c>_0 .. mw<c>_<n-1>, the weights of the axis whose parameter is
/// x[c], indented by two spaces.
std::string axis_statements(int c, int n, Interpolation scheme);

/// The object's body between its braces: the local copy of x[1..d], every axis's weights, with
/// an alignment the moving frame and each key's point in it (`frames`: one per key, measured),
/// the keys' calls (lattice order; with `normals`, one per key, each normalised by distance)
/// and the final `name = blend;`.
std::string body(const std::string& name,
  int d,
  const std::vector<int>& lattice,
  Interpolation scheme,
  const std::vector<std::string>& keys,
  Alignment alignment = Alignment::None,
  const std::vector<KeyFrame>& frames = {},
  const std::vector<KeyNormal>& normals = {});

} // namespace frep::morph::weight_text
