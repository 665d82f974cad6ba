// Internal: the HyperFun statements of a metamorphosis's object (morph_text.h): the keys' space
// copied into a local array, each lattice axis's weights by the same operations as
// lattice_weights.cpp (so the values agree to the last bit where the compiler does not
// contract), each key called where its weight is not 0, and the blend axis by axis.
#pragma once

#include "Morph/key_frame.h"
#include "Morph/lattice_weights.h"
#include "Morph/timing.h"

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
/// x[c] (timed by `timing` first), indented by two spaces.
std::string axis_statements(int c, int n, Interpolation scheme, const Timing& timing = {});

/// What the object's body is written from.
struct Body
{
  std::string name; ///< the object
  int d = 0;        ///< the keys' coordinates
  std::vector<int> lattice;
  Interpolation scheme = Interpolation::Linear;
  Timing timing;
  std::vector<std::string> keys; ///< in lattice order, the objects called
  Alignment alignment = Alignment::None;
  std::vector<KeyFrame> frames;   ///< with an alignment, one per key (measured)
  std::vector<KeyNormal> normals; ///< empty, or one per key (normalised by distance)
  /// Empty, or one per key: the key's own weight as a HyperFun expression (empty: 1).
  std::vector<std::string> key_weights;
};

/// The object's body between its braces: the local copy of x[1..d], every axis's weights, with
/// key weights their normalised products, with an alignment the moving frame and each key's
/// point in it, the keys' calls (lattice order) and the final `name = blend;`.
std::string body(const Body& spec);

} // namespace frep::morph::weight_text
