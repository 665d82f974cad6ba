// The camera (and, in the floor scene, the floor) that frame one ray-cast shape: what
// vtkFRepRayCaster and `frepkit render` show. The solid's outline seen from the view direction
// (raycast::silhouette) is fitted, not its box: a ball's box's corners seen obliquely spread 1.6
// times the ball, which left it at half the picture. The mapping frames many samples at once
// (Scene/framing.h) from the same silhouettes.
#pragma once

#include "Raycast/raycast.h"

#include <optional>

namespace frep::raycast
{

struct ShapeView
{
  double azimuth_deg = 0.0;   ///< imaging::fit_box's directions
  double elevation_deg = 0.0;
  double aspect = 1.0;        ///< the picture's width / height
  imaging::FitOptions fit;     ///< view angle, orthographic, fill
  /// Fit the solid's silhouette (true) or the bounding sphere of the shape's box (false).
  bool frame_solid = true;
  /// Stand the solid on a checkerboard floor (its lowest point) and frame the floor too.
  bool floor = false;
  int silhouette_pixels = 64; ///< rays per side of the silhouette's picture
  int threads = 1;            ///< 0 = all cores
};

struct FramedShape
{
  imaging::Camera camera;
  std::optional<Floor> floor; ///< when ShapeView::floor
};

/// The camera looking from `view`'s direction that frames `shape`'s solid (its silhouette within
/// the fit's fill of the picture's width or height, the focal point at the depth of its bounds'
/// centre), or the box's bounding sphere when `frame_solid` is off or no ray meets the solid.
/// With the floor, the floor is at the solid's lowest point (lowest_z) under its bounds and the
/// board's corners are framed too. Sets `shape.bounds` when framing the solid (render then does
/// not search again).
FramedShape frame_shape(Shape& shape, const ShapeView& view);

} // namespace frep::raycast
