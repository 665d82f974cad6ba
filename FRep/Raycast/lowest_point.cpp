// What a scene asks the ray caster about a solid: raycast::lowest_z, where it meets a floor under
// it (rays cast straight up), and raycast::silhouette, what a camera must see to frame it (rays
// cast along the view). Found by the ray caster itself, from its first hits, so the points are
// the ones the pictures draw: the same root search, the same caps where the box cuts the solid.
#include "Raycast/raycast.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frep::raycast
{
namespace
{

struct LowestHit
{
  double z, x, y;
};

/// The lowest first hit of a square orthographic picture looking up (+z) from height `below`,
/// `half` world units from its centre (cx, cy) to each edge, one ray per pixel.
std::optional<LowestHit> look_up(const Shape& shape,
  double cx,
  double cy,
  double half,
  double below,
  int pixels,
  int threads)
{
  imaging::Camera camera;
  camera.position = { cx, cy, below };
  camera.focal_point = { cx, cy, below + half };
  camera.view_up = { 0.0, 1.0, 0.0 };
  camera.orthographic = true;
  camera.parallel_scale = half;
  camera.near_distance = 1e-6 * half;
  Style style;
  style.render.supersample = 1;
  imaging::Image picture(pixels, pixels);
  std::vector<float> depth;
  RunControl run;
  run.threads = threads;
  if (!render(picture, camera, shape, nullptr, style, &depth, run).ok())
  {
    return std::nullopt;
  }
  const auto nearest = std::min_element(depth.begin(), depth.end());
  if (nearest == depth.end() || !std::isfinite(*nearest))
  {
    return std::nullopt;
  }
  // The pixel's ray: rows run top down, the picture's right and up from the camera's frame.
  const std::size_t i = static_cast<std::size_t>(nearest - depth.begin());
  const double step = 2.0 * half / pixels;
  const double a = (static_cast<double>(i % pixels) + 0.5) * step - half;
  const double b = half - (static_cast<double>(i / pixels) + 0.5) * step;
  const imaging::CameraFrame frame = imaging::camera_frame(camera);
  return LowestHit{ below + *nearest,
    cx + a * frame.right[0] + b * frame.up[0],
    cy + a * frame.right[1] + b * frame.up[1] };
}

// The world box of the solid's bounds (the map is affine: the hull of its eight corners).
void world_box(const Shape& shape,
  const mesh::SolidBounds& bounds,
  std::array<double, 3>& lo,
  std::array<double, 3>& hi)
{
  const std::array<double, 12>& m = shape.to_world;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (int c = 0; c < 8; ++c)
  {
    const std::array<double, 3> p{ (c & 1) ? bounds.box[0].hi : bounds.box[0].lo,
      (c & 2) ? bounds.box[1].hi : bounds.box[1].lo,
      (c & 4) ? bounds.box[2].hi : bounds.box[2].lo };
    for (int r = 0; r < 3; ++r)
    {
      const double w = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
      lo[r] = std::min(lo[r], w);
      hi[r] = std::max(hi[r], w);
    }
  }
}

} // namespace

std::optional<double> lowest_z(const Shape& shape, int pixels, int threads)
{
  if (!shape.tape || shape.tape->input_count != 3 || pixels < 2)
  {
    return std::nullopt;
  }
  const mesh::SolidBounds bounds =
    shape.bounds ? *shape.bounds : solid_bounds(shape.tape, shape.box);
  if (!bounds.bounded())
  {
    return std::nullopt;
  }
  std::array<double, 3> lo, hi;
  world_box(shape, bounds, lo, hi);
  const double half = 0.51 * std::max({ hi[0] - lo[0], hi[1] - lo[1], 1e-9 });
  const double below = lo[2] - 0.01 * std::max(hi[2] - lo[2], 2.0 * half) - 1e-9;
  Shape solid = shape; // drawn plain: only the depth is read
  solid.colour_function = {};
  solid.opacity = 1.0;
  solid.bounds = bounds; // both look-ups clip to the bounds found here
  const std::optional<LowestHit> coarse = look_up(
    solid, 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), half, below, pixels, threads);
  if (!coarse)
  {
    return std::nullopt;
  }
  // Again over the 4 x 4 coarse pixels around that hit: the lowest point of a round bottom lies
  // between the coarse rays.
  const double coarse_step = 2.0 * half / pixels;
  const std::optional<LowestHit> fine =
    look_up(solid, coarse->x, coarse->y, 2.0 * coarse_step, below, pixels, threads);
  return fine ? std::min(coarse->z, fine->z) : coarse->z;
}

Silhouette silhouette(const Shape& shape, const imaging::CameraFrame& view, int pixels, int threads)
{
  Silhouette result;
  if (!shape.tape || shape.tape->input_count != 3 || pixels < 2)
  {
    return result;
  }
  const mesh::SolidBounds bounds =
    shape.bounds ? *shape.bounds : solid_bounds(shape.tape, shape.box);
  if (!bounds.bounded())
  {
    return result;
  }
  // The solid's world box in the view's coordinates: the picture covers its corners.
  std::array<double, 3> lo, hi;
  world_box(shape, bounds, lo, hi);
  const std::array<const imaging::Vec3*, 3> axes{ &view.right, &view.up, &view.forward };
  std::array<double, 3> vlo, vhi;
  vlo.fill(std::numeric_limits<double>::infinity());
  vhi.fill(-std::numeric_limits<double>::infinity());
  for (int c = 0; c < 8; ++c)
  {
    const imaging::Vec3 p{ c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2] };
    for (int k = 0; k < 3; ++k)
    {
      const imaging::Vec3& a = *axes[k];
      const double v = a[0] * p[0] + a[1] * p[1] + a[2] * p[2];
      vlo[k] = std::min(vlo[k], v);
      vhi[k] = std::max(vhi[k], v);
    }
  }
  const double half = 0.5 * std::max({ vhi[0] - vlo[0], vhi[1] - vlo[1], 1e-9 });
  const double a0 = 0.5 * (vlo[0] + vhi[0]), b0 = 0.5 * (vlo[1] + vhi[1]);
  const double front = vlo[2] - 0.01 * std::max(vhi[2] - vlo[2], 2.0 * half) - 1e-9;
  imaging::Camera camera;
  for (int k = 0; k < 3; ++k)
  {
    camera.position[k] = a0 * view.right[k] + b0 * view.up[k] + front * view.forward[k];
    camera.focal_point[k] = camera.position[k] + half * view.forward[k];
  }
  camera.view_up = view.up;
  camera.orthographic = true;
  camera.parallel_scale = half;
  camera.near_distance = 1e-6 * half;
  Shape solid = shape; // drawn plain: only the depth is read
  solid.colour_function = {};
  solid.opacity = 1.0;
  solid.bounds = bounds;
  Style style;
  style.render.supersample = 1;
  imaging::Image picture(pixels, pixels);
  std::vector<float> depth;
  RunControl run;
  run.threads = threads;
  if (!render(picture, camera, solid, nullptr, style, &depth, run).ok())
  {
    return result;
  }
  // Each hit's world point: the pixel's ray (rows run top down) at its depth.
  const imaging::CameraFrame frame = imaging::camera_frame(camera);
  result.spacing = 2.0 * half / pixels;
  for (std::size_t i = 0; i < depth.size(); ++i)
  {
    if (!std::isfinite(depth[i]))
    {
      continue;
    }
    const double a = (static_cast<double>(i % pixels) + 0.5) * result.spacing - half;
    const double b = half - (static_cast<double>(i / pixels) + 0.5) * result.spacing;
    imaging::Vec3 p;
    for (int k = 0; k < 3; ++k)
    {
      p[k] =
        camera.position[k] + a * frame.right[k] + b * frame.up[k] + depth[i] * frame.forward[k];
    }
    result.points.push_back(p);
  }
  return result;
}

} // namespace frep::raycast
