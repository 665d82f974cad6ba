// Internal: the rays of a picture in model space. A sample at continuous picture coordinates
// (sx, sy) and depth lambda (the distance along the camera's view direction, world units) is at
//   perspective:   m = E + lambda (F + a R + b U)
//   orthographic:  m = E + a R + b U + lambda F
// with a = (sx - cx) / focal, b = (cy - sy) / focal and E, R, U, F the eye and the camera's
// axes mapped into model space (the world mapping is affine, so this is exact and a piece of
// the view between two depths is the convex hull of its eight corners).
#pragma once

#include "Imaging/camera.h"

#include "Eval/interval.h"

#include <array>

namespace frep::raycast::detail
{

using Vec3 = std::array<double, 3>;

/// An affine map w = M m + t (row-major 3 x 4) and its inverse.
struct Affine3
{
  std::array<double, 12> forward{};
  std::array<double, 12> inverse{};
  /// Null when the matrix is singular or not finite.
  static bool make(const std::array<double, 12>& m, Affine3& out);
  Vec3 point(const Vec3& m) const;        ///< model -> world
  Vec3 to_model(const Vec3& w) const;     ///< world -> model
  Vec3 vector_to_model(const Vec3& w) const;
  /// A model-space gradient as a world-space one (inverse transpose).
  Vec3 gradient_to_world(const Vec3& g) const;
};

struct ViewRays
{
  bool orthographic = false;
  double cx = 0.0, cy = 0.0, focal = 1.0; ///< samples (see the file comment)
  double near = 1e-6;                     ///< smallest depth (perspective)
  Vec3 eye{}, right{}, up{}, forward{};   ///< world
  Vec3 e{}, r{}, u{}, f{};                ///< model
  /// World width of one sample at depth lambda.
  double footprint(double lambda) const { return orthographic ? 1.0 / focal : lambda / focal; }

  /// Origin and direction (model space) of the ray of sample centre (sx, sy) as a function of
  /// depth: m = o + lambda d.
  void ray(double sx, double sy, Vec3& o, Vec3& d) const;
  /// World-space origin and direction of that ray (the direction is not unit: its forward
  /// component is 1, so the world point at depth lambda is origin + lambda direction).
  Vec3 world_origin(double sx, double sy) const;
  Vec3 world_direction(double sx, double sy) const;
};

/// The rays of a width x height sample picture of `camera`, mapped into model space by `map`.
ViewRays make_view_rays(const imaging::Camera& camera, int width, int height, const Affine3& map);

/// The depths [lo, hi] where o + lambda d is inside `box` (lo > hi: never), from `from` on.
std::array<double, 2> clip_to_box(const Vec3& o, const Vec3& d, const std::array<Interval, 3>& box,
  double from);

/// The face of `box` where the ray enters it at depth `lambda` (0..5: -x, +x, -y, +y, -z, +z),
/// the face whose plane is nearest to the entry point.
int entry_face(const Vec3& o, const Vec3& d, double lambda, const std::array<Interval, 3>& box);

/// The model-space bounding box of the view piece over samples [x0, x1] x [y0, y1] (picture
/// coordinates of the rays at its corners) and depths [l0, l1], intersected with `box`.
/// Returns false when the intersection is empty.
bool piece_box(const ViewRays& view, double x0, double x1, double y0, double y1, double l0,
  double l1, const std::array<Interval, 3>& box, std::array<Interval, 3>& out);

} // namespace frep::raycast::detail
