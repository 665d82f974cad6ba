// The pictures of the map of the topology (the mapping's "topology", made by Production's
// topology phase): the spreadsheet marked with each cell's pieces and genus and where they
// change, and the pieces and genus along the animation as a step chart.
#pragma once

#include "Mapping/mapping_plan.h"
#include "Scene/pictures.h"

#include "Mesh/mesh_topology.h"
#include "Project/space_time.h"

#include "Imaging/image.h"

#include <array>
#include <cstddef>
#include <vector>

namespace frep::mapping
{

/// A change of topology between samples `from` and `to` (indices of cells or frames), located
/// along the step between them (event.before, event.after: fractions of the step).
struct TopologyChange
{
  std::size_t from = 0, to = 0;
  project::TopologyEvent event;
};

/// The cells' or the frames' pieces and genus (one per sample, in plan order) and the changes.
struct TopologyMap
{
  std::vector<mesh::ShapeTopology> shapes;
  std::vector<TopologyChange> changes;
};

/// The composed spreadsheet (`rects`: each cell picture's place, compose_spreadsheet's) with
/// each cell's pieces, slivers and genus in its top-left corner (with a font), the two cells of every
/// change outlined in red and the gap between them barred when they are side by side or one
/// above the other.
imaging::Image topology_sheet(const imaging::Image& sheet,
  const std::vector<std::array<int, 4>>& rects,
  const TopologyMap& cells,
  PictureKit* kit);

/// The pieces and genus along the animation's time (900 x 360 pixels): steps at the located
/// changes (their middles), each change marked; and the pieces but the slivers, frame by frame.
imaging::Image topology_chart(const Plan& plan, const TopologyMap& frames, PictureKit* kit);

} // namespace frep::mapping
