// How much each key shape of a metamorphosis counts at a point of its parameter space (issue 29).
// The paper blends four keys bilinearly over (x4, x5) in [0, 1]^2; its conclusion asks for more
// keys and splines. Here the keys sit on a lattice: n_1 x n_2 x ... nodes, evenly spaced over
// [0, 1] on each parameter axis, node i of an axis of n at i / (n - 1). A scheme gives each node
// of an axis a weight at t; a lattice's weights are the products over its axes (a tensor
// product). The blended object is sum_k w_k(t) F_k(x).
//
// Schemes (per axis of n nodes):
//   Linear      the hat functions: the two nodes around t share it linearly (n = 2 on two axes:
//               the paper's bilinear formula). Never negative.
//   CatmullRom  the uniform Catmull-Rom spline: passes through every key (at a node, that key
//               alone), its weights C1 in t; they go slightly negative between nodes (to
//               -2/27), which lets a shape overshoot a little as a spline does. The end
//               segments repeat the end node (the spline's usual clamping).
//   BSpline     the clamped uniform B-spline of degree min(3, n - 1): C2 in t, never negative,
//               reaches the first and the last key exactly but only approaches the inner ones
//               (it smooths: an inner key is never shown alone). n = 2: Linear; n = 3: the
//               quadratic Bernstein weights; n = 4: the cubic Bernstein (Bezier) weights.
// Every scheme's weights sum to 1 (to rounding), and at t = 0 and t = 1 they are exactly 0 and 1,
// so a lattice's corners are its corner keys bit for bit. Linear and CatmullRom are exact 0 and 1
// at every node t = i / (n - 1) that is computed as such. t outside [0, 1] is clamped.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace frep::morph
{

enum class Interpolation
{
  Linear,
  CatmullRom,
  BSpline
};

/// "linear", "catmull-rom", "b-spline"; empty for another name.
std::optional<Interpolation> interpolation_from_name(std::string_view name);
std::string_view interpolation_name(Interpolation scheme);

/// The weights of the `nodes` nodes of one axis at t (see the file comment). `nodes` >= 2, else
/// std::invalid_argument; t NaN gives NaN weights.
std::vector<double> axis_weights(Interpolation scheme, int nodes, double t);

/// The weights of a lattice's keys at the point `t` of its parameter space: `nodes[a]` nodes on
/// axis a, `t[a]` its parameter; keys in lattice order, the first axis fastest (key index
/// i_0 + n_0 (i_1 + n_1 (i_2 + ...))). The two spans have the same size >= 1, else
/// std::invalid_argument.
std::vector<double> lattice_weights(Interpolation scheme,
  std::span<const int> nodes,
  std::span<const double> t);

} // namespace frep::morph
