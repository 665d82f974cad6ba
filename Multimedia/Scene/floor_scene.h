// The paper's Fig. 8 scene for animation frames ("render": {"scene": "floor"}): the plane of the
// two dynamic coordinates laid out as a checkerboard floor — its squares are the spreadsheet's
// cells when the spreadsheet's grid is on the same coordinates, so the square a shape stands on
// is the cell that shows it — with the path drawn on it, and each frame's cross-section
// standing on the floor at its (dynamic) point, its shadow cast by the key light. The camera is
// fixed for the whole animation and frames the floor, so the shape is seen travelling its path.
#pragma once

#include "Plan/mapping_plan.h"
#include "Plan/mapping_spec.h"

#include "Raycast/raycast.h"
#include "Render/camera.h"

#include <array>

namespace frep::mapping
{

struct FloorScene
{
  raycast::Floor floor;
  render::Camera camera;
  /// Dynamic-plane point (u, v) -> world floor point: x = ox + sx u, y = oy + sy v.
  std::array<double, 4> plane_to_floor{ 0.0, 1.0, 0.0, 1.0 }; ///< ox, sx, oy, sy
  std::array<double, 3> shape_anchor{}; ///< world point of the shape box put on the floor point
  bool ok = false; ///< false: the plan has no two dynamic coordinates
};

/// The scene of every frame of `plan` (one camera: `settings` azimuth, and its elevation raised
/// to at least 30 degrees so the board is seen from above), for pictures of width / height =
/// aspect.
FloorScene make_floor_scene(const Plan& plan, const Spec& spec, double aspect);

/// `frame` moved so that its section stands on the floor at its dynamic point: the frame's
/// transform preceded by nothing and followed by the translation to that point.
Sample on_floor(const FloorScene& scene, const Sample& frame);

} // namespace frep::mapping
