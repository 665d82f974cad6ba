// The paper's Fig. 8 scene for animation frames ("render": {"scene": "floor"}): the plane of the
// two dynamic coordinates laid out as a checkerboard floor — its squares are the spreadsheet's
// cells when the spreadsheet's grid is on the same coordinates, so the square a shape stands on
// is the cell that shows it — with the path drawn on it, and each frame's cross-section
// standing on the floor at its (dynamic) point, its shadow cast by the key light. The camera is
// fixed for the whole animation and frames the floor, so the shape is seen travelling its path.
// "Standing": on_floor puts the frame's shape box over its point; stand_on_floor then moves
// the section itself up or down until its lowest point (a mesh's lowest vertex, a ray-cast
// solid's raycast::lowest_z) is on the board, so no shape floats above its shadow.
#pragma once

#include "Mapping/mapping_plan.h"
#include "Mapping/mapping_spec.h"
#include "Scene/framing.h"
#include "Scene/section_mesh.h"

#include "Raycast/raycast.h"
#include "Imaging/camera.h"

#include <array>

namespace frep::mapping
{

struct FloorScene
{
  raycast::Floor floor;
  imaging::Camera camera;
  /// Dynamic-plane point (u, v) -> world floor point: x = ox + sx u, y = oy + sy v.
  std::array<double, 4> plane_to_floor{ 0.0, 1.0, 0.0, 1.0 }; ///< ox, sx, oy, sy
  std::array<double, 3> shape_anchor{}; ///< world point of the shape box put on the floor point
  bool ok = false; ///< false: the plan has no two dynamic coordinates
};

/// The scene of every frame of `plan` (one camera: `settings` azimuth, and its elevation raised
/// to at least 30 degrees so the board is seen from above), for pictures of width / height =
/// aspect. The shape's box — what sizes the board (a square is 0.55 of its larger side) and
/// stands on it — is the shown box (shown_box: the render settings' view_box, else the
/// framing's box of the solids, else the plan's world box); the camera fits the board's
/// corners and, at each frame's point, that frame's solid's box (the framing's) or the shape's
/// box, standing on the board, within 92% of the picture over the caption's band.
FloorScene make_floor_scene(const Plan& plan,
  const Spec& spec,
  double aspect,
  const Framing& framing = {});

/// `frame` moved over its dynamic point on the floor, the bottom of its shape box on the board:
/// the frame's transform followed by the translation to that point. stand_on_floor then puts
/// the section itself on the board.
Sample on_floor(const FloorScene& scene, const Sample& frame);

/// A meshed 3-D section (world space, as make_section made it) moved vertically so that its
/// lowest vertex is at the floor's height. Returns the distance moved (0 for an empty or 2-D
/// section).
double stand_on_floor(Section& section, const raycast::Floor& floor);

/// The ray-cast counterpart: `frame` (already on_floor) with the vertical translation that puts
/// the lowest point of its solid (raycast::lowest_z of the section's tape, mapped to the world
/// as raycast_sample maps it) at the floor's height. Unchanged when the solid is empty or the
/// plan cannot be ray-cast. `threads` 0 = all cores. `bounds`: the solid's bounds when the
/// caller has them (Framing::solid_of), else searched again.
Sample stand_on_floor(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& frame,
  const raycast::Floor& floor,
  int threads = 1,
  const mesh::SolidBounds* bounds = nullptr);

} // namespace frep::mapping
