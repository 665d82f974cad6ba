#include "Raycast/detail/shadow_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frep::raycast::detail
{
namespace
{

constexpr int kTile = 16;

double dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

} // namespace

ShadowMap::ShadowMap(const Shape& shape, const std::array<Interval, 3>& clip, const Affine3& map,
  const Vec3& towards_light, int size, ThreadPool& pool, Statistics& statistics)
  : size_(size)
  , depth_(static_cast<std::size_t>(size) * size, std::numeric_limits<double>::infinity())
{
  // The world box of the shape's box: its bounding sphere frames the light's picture.
  Vec3 lo{ std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  Vec3 hi{ -lo[0], -lo[1], -lo[2] };
  for (int c = 0; c < 8; ++c)
  {
    const Vec3 w = map.point({ c & 1 ? clip[0].hi : clip[0].lo,
      c & 2 ? clip[1].hi : clip[1].lo,
      c & 4 ? clip[2].hi : clip[2].lo });
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], w[k]);
      hi[k] = std::max(hi[k], w[k]);
    }
  }
  Vec3 centre, half;
  for (int k = 0; k < 3; ++k)
  {
    centre[k] = 0.5 * (lo[k] + hi[k]);
    half[k] = 0.5 * (hi[k] - lo[k]);
  }
  const double radius = std::max(std::sqrt(dot(half, half)), 1e-300);
  imaging::Camera camera;
  camera.orthographic = true;
  camera.parallel_scale = radius;
  camera.focal_point = centre;
  for (int k = 0; k < 3; ++k)
  {
    camera.position[k] = centre[k] + 2.0 * radius * towards_light[k];
  }
  camera.view_up = { 0.0, 0.0, 1.0 };
  camera.near_distance = 1e-9 * radius;
  view_ = make_view_rays(camera, size, size, map);

  TraceOptions options;
  options.from = 0.0;
  const int tiles_x = (size + kTile - 1) / kTile;
  const std::size_t tiles = static_cast<std::size_t>(tiles_x) * tiles_x;
  std::vector<std::unique_ptr<PieceTracer>> tracers(static_cast<std::size_t>(pool.size()));
  std::vector<std::vector<Hit>> hits(tracers.size());
  pool.parallel_for(tiles,
    [&](std::size_t t, int slot)
    {
      auto& tracer = tracers[static_cast<std::size_t>(slot)];
      if (!tracer)
      {
        tracer = std::make_unique<PieceTracer>(shape.tape, shape.box, clip, view_, options);
      }
      const int x0 = static_cast<int>(t % tiles_x) * kTile, y0 = static_cast<int>(t / tiles_x) * kTile;
      const int x1 = std::min(size, x0 + kTile), y1 = std::min(size, y0 + kTile);
      auto& h = hits[static_cast<std::size_t>(slot)];
      h.resize(static_cast<std::size_t>(x1 - x0) * (y1 - y0));
      tracer->trace_tile(x0, y0, x1, y1, h);
      for (int y = y0; y < y1; ++y)
      {
        for (int x = x0; x < x1; ++x)
        {
          depth_[static_cast<std::size_t>(y) * size + x] =
            h[static_cast<std::size_t>(y - y0) * (x1 - x0) + (x - x0)].lambda;
        }
      }
    });
  for (const auto& tracer : tracers)
  {
    if (tracer)
    {
      const Statistics& s = tracer->statistics();
      statistics.shadow_rays += s.rays;
      statistics.interval_evaluations += s.interval_evaluations;
      statistics.point_evaluations += s.point_evaluations;
    }
  }
}

float ShadowMap::light(const Vec3& p) const
{
  const Vec3 q{ p[0] - view_.eye[0], p[1] - view_.eye[1], p[2] - view_.eye[2] };
  const double sx = view_.cx + dot(q, view_.right) * view_.focal - 0.5;
  const double sy = view_.cy - dot(q, view_.up) * view_.focal - 0.5;
  const double lambda = dot(q, view_.forward) - 2.0 * texel();
  const double fx = std::floor(sx), fy = std::floor(sy);
  const double wx = sx - fx, wy = sy - fy;
  float reach = 0.0F;
  for (int c = 0; c < 4; ++c)
  {
    const int x = static_cast<int>(fx) + (c & 1), y = static_cast<int>(fy) + (c >> 1);
    const double w = (c & 1 ? wx : 1.0 - wx) * (c >> 1 ? wy : 1.0 - wy);
    const bool lit = x < 0 || y < 0 || x >= size_ || y >= size_ ||
                     !(depth_[static_cast<std::size_t>(y) * size_ + x] < lambda);
    reach += lit ? static_cast<float>(w) : 0.0F;
  }
  return reach;
}

} // namespace frep::raycast::detail
