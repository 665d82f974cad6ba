// One section of a space-time model at a time, meshed (3 space coordinates) or contoured (2) on a
// grid, and what its mesh says: the volume or area, the pieces, and (3-D) the genus. Shared by
// section_measures and topology_events.
#pragma once

#include "Compiler/model.h"
#include "Eval/interval.h"
#include "Mesh/mesh_topology.h"
#include "Sample/grid.h"

#include <string>
#include <vector>

namespace frep::project::detail
{

struct SectionShape
{
  std::string error;
  double measure = 0.0;       ///< volume or area
  mesh::ShapeTopology topology; ///< pieces, and (3-D) the genus
};

/// The section at `time` of the model's coordinate `time_coordinate` (1-based), over `grid`
/// (2 or 3 axes: the other coordinates, in order).
SectionShape section_shape(const Model& model, int time_coordinate, double time,
  const GridSpec& grid, const std::vector<double>& parameters);

/// The grid of `samples` points per axis over the box `space`.
GridSpec section_grid(const std::vector<Interval>& space, int samples);

} // namespace frep::project::detail
