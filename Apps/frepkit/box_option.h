// --box of mesh, slice and render: one parser for both of its syntaxes.
//   all minima, then all maxima:   --box -1,-1,-1,1,1,1
//   a range per axis, by name:     --box x1=-1:1,x2=-1:1,x3=-1:1   (or x=-1:1,y=-1:1,z=-1:1)
#pragma once

#include <string>
#include <vector>

namespace frepkit
{

/// The box of --box over the axes driven by `free` (0-based coordinate indices in axis order, 2
/// or 3 of them), as make_grid wants it: all minima, then all maxima; empty when `entries` is
/// empty (the default box). `entries` are --box's comma-separated entries, either 2 * axes
/// numbers or one NAME=LO:HI per axis, NAME the free coordinate (x4, x[4]) or the axis (x, y,
/// z; case-insensitive), in any order. Throws UserError for a wrong count, an entry that is not
/// a number or not NAME=LO:HI, an unknown or fixed coordinate, an axis given twice or missing, a
/// non-finite bound, lo >= hi and a mixture of both syntaxes.
std::vector<double> parse_box(const std::vector<std::string>& entries, const std::vector<int>& free);

} // namespace frepkit
