// CLI (Common Layer Interface, ASCII) as hfp -cli writes it: a header ($$HEADERSTART, $$ASCII,
// $$UNITS/1, $$DATE/ddmmyy, $$HEADEREND), then $$GEOMETRYSTART, per layer with material
// "$$LAYER/z" and one "$$POLYLINE/id,dir,n,x1,y1,...,xn,yn" per closed loop (dir 1 =
// counter-clockwise, an outer boundary; 0 = clockwise, a hole; the last point repeats the
// first), and $$GEOMETRYEND. Unlike hfp every polyline is closed (also where the solid meets the
// box) and all have id 1 (one part; hfp numbered its chains).
#pragma once

#include "contour_loops.h"

#include <ostream>
#include <vector>

namespace frepkit
{

void write_cli_header(std::ostream& out);
void write_cli_layer(std::ostream& out, double z, const std::vector<ContourLoop>& loops);
void write_cli_end(std::ostream& out);

} // namespace frepkit
