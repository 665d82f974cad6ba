// A 2-D contour (segments with the inside on their left, as extract_contour returns them) joined
// into closed polylines: chains that leave the box are closed along the box boundary, walking
// counter-clockwise (the box interior on the left) to the next chain that enters, so every loop
// bounds the solid's section inside the box. Outer boundaries come out counter-clockwise, holes
// clockwise. This is what layered manufacturing formats (CLI) need.
#pragma once

#include "Mesh/surface.h"

#include <array>
#include <vector>

namespace frepkit
{

struct ContourLoop
{
  std::vector<std::array<double, 2>> points; ///< closed: the last point equals the first
  double signed_area = 0;                    ///< > 0 counter-clockwise (outer), < 0 a hole
};

/// `contour` is a 2-D Surface (segments). `lo`/`hi` are the box of its grid. `box_inside` says
/// whether the box boundary is inside the solid; it is only used when no chain meets the
/// boundary (then the boundary is entirely inside or outside; inside adds the box as a loop).
std::vector<ContourLoop> close_contour_loops(const frep::mesh::Surface& contour,
  std::array<double, 2> lo,
  std::array<double, 2> hi,
  bool box_inside);

} // namespace frepkit
