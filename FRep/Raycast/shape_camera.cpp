// frame_shape: the silhouette (or the box) fitted by one camera, with the floor under the solid.
#include "Raycast/shape_camera.h"

#include <vector>

namespace frep::raycast
{
namespace
{

/// The same camera with its focal point moved along the view to the depth of `centre` (the
/// silhouette's points are the solid's front): a solid symmetric about it is looked at there.
void look_at_depth_of(imaging::Camera& camera, const imaging::Vec3& centre)
{
  const imaging::CameraFrame f = imaging::camera_frame(camera);
  double along = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    along += (centre[a] - camera.position[a]) * f.forward[a];
  }
  for (int a = 0; along > 0.0 && a < 3; ++a)
  {
    camera.focal_point[a] = camera.position[a] + along * f.forward[a];
  }
}

} // namespace

FramedShape frame_shape(Shape& shape, const ShapeView& view)
{
  imaging::Vec3 lo{ shape.box[0].lo, shape.box[1].lo, shape.box[2].lo };
  imaging::Vec3 hi{ shape.box[0].hi, shape.box[1].hi, shape.box[2].hi };
  std::vector<imaging::Vec3> outline; // what the camera must see, when it frames the solid
  double spacing = 0.0;
  if (view.frame_solid)
  {
    shape.bounds = solid_bounds(shape.tape, shape.box);
    for (int a = 0; shape.bounds->bounded() && a < 3; ++a)
    {
      lo[a] = shape.bounds->box[a].lo;
      hi[a] = shape.bounds->box[a].hi;
    }
    Silhouette seen = silhouette(shape,
      imaging::view_frame(view.azimuth_deg, view.elevation_deg),
      view.silhouette_pixels,
      view.threads);
    outline = std::move(seen.points);
    spacing = seen.spacing;
  }
  FramedShape framed;
  if (view.floor)
  {
    const std::optional<double> bottom = lowest_z(shape, 128, view.threads);
    lo[2] = !outline.empty() && bottom ? *bottom : lo[2];
    framed.floor = floor_under(lo, hi);
    framed.floor->height = bottom ? *bottom : framed.floor->height;
    for (int c = 0; !outline.empty() && c < 4; ++c) // the board's corners
    {
      outline.push_back({ c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], framed.floor->height });
    }
  }
  if (outline.empty())
  {
    framed.camera =
      imaging::fit_box(lo, hi, view.aspect, view.azimuth_deg, view.elevation_deg, view.fit);
    return framed;
  }
  framed.camera = imaging::fit_points(
    outline, view.aspect, view.azimuth_deg, view.elevation_deg, view.fit, spacing);
  imaging::Vec3 centre{};
  for (int a = 0; a < 3; ++a)
  {
    centre[a] = 0.5 * (shape.bounds->box[a].lo + shape.bounds->box[a].hi);
  }
  look_at_depth_of(framed.camera, centre);
  return framed;
}

} // namespace frep::raycast
