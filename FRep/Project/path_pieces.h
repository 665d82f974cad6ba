// A path through k coordinates as polynomial pieces, the one form every path of the engine takes
// before it is written into a model (sweep_text.h's sweeps, path_family.h's families): piece i is
// c_i(u) = c[0] + c[1] u + c[2] u^2 + c[3] u^3 per coordinate, u in [0, 1], over the path
// parameter t in [i / n, (i + 1) / n] of n pieces, each piece starting where the one before
// ends. A polyline is linear pieces; a uniform Catmull-Rom spline cubic ones; the mapping's
// centripetal Catmull-Rom is cubic too (Mapping/path.h gives its pieces).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace frep::project
{

/// One piece: per coordinate, the coefficients c[0..3] of c(u) = sum c[j] u^j, u in [0, 1].
using PathPiece = std::vector<std::array<double, 4>>;

/// The pieces joining `points` (each of the same size) by straight segments; closed: back to the
/// first point. Needs 2 points (3 when closed).
std::vector<PathPiece> polyline_pieces(const std::vector<std::vector<double>>& points, bool closed);

/// The uniform Catmull-Rom spline through `points`: an open path's end segments get their outer
/// neighbours mirrored (2 p0 - p1), a closed one wraps. Needs 2 points (3 when closed).
std::vector<PathPiece> catmull_rom_pieces(
  const std::vector<std::vector<double>>& points, bool closed);

/// Why `pieces` cannot be a path of `coordinates` coordinates ("" when they can): none, a piece
/// of another size, a coefficient that is not finite.
std::string path_pieces_error(const std::vector<PathPiece>& pieces, std::size_t coordinates);

/// The point of piece i at u, and its derivative by u.
double piece_value(const std::array<double, 4>& c, double u);
double piece_slope(const std::array<double, 4>& c, double u);

} // namespace frep::project
