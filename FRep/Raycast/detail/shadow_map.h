// Internal: the key light's view of the shape, for shadows. The light is directional, so the
// shadow rays are parallel: one orthographic picture traced like the camera's (the same pruned
// search, coherent tiles) answers every shadow query by a look-up, instead of a ray per sample.
#pragma once

#include "Raycast/detail/piece_tracer.h"
#include "Raycast/detail/view_rays.h"

#include "Eval/thread_pool.h"

#include <vector>

namespace frep::raycast::detail
{

class ShadowMap
{
public:
  /// The shape's box seen along -towards_light, `size` samples square.
  /// The solid inside `clip` (see Mesh/solid_bounds.h) seen along -towards_light.
  ShadowMap(const Shape& shape, const std::array<Interval, 3>& clip, const Affine3& map,
    const Vec3& towards_light, int size, ThreadPool& pool, Statistics& statistics);

  /// Fraction of the light that reaches world point p (0 in the shadow, 1 lit; bilinear
  /// between the four nearest samples, so shadow edges are smooth).
  float light(const Vec3& p) const;

  /// World width of a shadow-map sample (the bias of a look-up is a few of these).
  double texel() const { return 1.0 / view_.focal; }

private:
  ViewRays view_;
  int size_ = 0;
  std::vector<double> depth_; // per sample: depth of the first hit (infinity: none)
};

} // namespace frep::raycast::detail
