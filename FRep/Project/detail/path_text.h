// A path's pieces (path_pieces.h) as HyperFun statements: the one way the engine writes a path
// into a model (write_sweep, write_path_family, path_family). The pieces are summed, each over
// its own parameter clamped to [0, 1]:
//   c(t) = c_0(0) + sum_i (c_i(u_i) - c_i(0)),  u_i = min(max(n t - i, 0), 1),
// which telescopes to c_k(u) on piece k. Unlike picking the piece by floor(n t), every term is
// monotone in t and continuous, so an enclosure over a box of t that straddles two pieces stays
// as tight as the path is (the projector's boxes shrink to its tolerance there; with floor the
// piece's u spanned [0, 1] and they never did).
#pragma once

#include "Project/path_pieces.h"

#include <string>
#include <vector>

namespace frep::project::detail
{

/// `v` as a HyperFun literal: fixed notation with 9 decimals (an exponent is a syntax error),
/// a negative value in parentheses.
std::string hf_literal(double v);

/// Statements setting mt (t clamped to [0, 1]), ms (n t), mu1..mun (each piece's u) and
/// `names[a]` = the path's coordinate a at t, where t is the expression `parameter`.
std::string path_position_text(const std::vector<PathPiece>& pieces, const std::string& parameter,
  const std::vector<std::string>& names);

/// After path_position_text: statements setting `names[a]` = dc_a/du of the piece at t (where
/// two pieces meet with the same slope the sum telescopes again; where they do not, the slope is
/// the later piece's from the joint on).
std::string path_slope_text(
  const std::vector<PathPiece>& pieces, const std::vector<std::string>& names);

} // namespace frep::project::detail
