#include "Raycast/detail/view_rays.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace frep::raycast::detail
{
bool Affine3::make(const std::array<double, 12>& m, Affine3& out)
{
  const double a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9],
               i = m[10];
  const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  if (!(std::abs(det) > 1e-300) || !std::isfinite(det))
  {
    return false;
  }
  for (double v : m)
  {
    if (!std::isfinite(v))
    {
      return false;
    }
  }
  const double inv[9] = { (e * i - f * h) / det,
    (c * h - b * i) / det,
    (b * f - c * e) / det,
    (f * g - d * i) / det,
    (a * i - c * g) / det,
    (c * d - a * f) / det,
    (d * h - e * g) / det,
    (b * g - a * h) / det,
    (a * e - b * d) / det };
  out.forward = m;
  for (int r = 0; r < 3; ++r)
  {
    double t = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      out.inverse[4 * r + k] = inv[3 * r + k];
      t -= inv[3 * r + k] * m[4 * k + 3];
    }
    out.inverse[4 * r + 3] = t;
  }
  return true;
}

Vec3 Affine3::point(const Vec3& p) const
{
  Vec3 w;
  for (int r = 0; r < 3; ++r)
  {
    w[r] = forward[4 * r] * p[0] + forward[4 * r + 1] * p[1] + forward[4 * r + 2] * p[2] +
           forward[4 * r + 3];
  }
  return w;
}

Vec3 Affine3::to_model(const Vec3& w) const
{
  Vec3 p;
  for (int r = 0; r < 3; ++r)
  {
    p[r] = inverse[4 * r] * w[0] + inverse[4 * r + 1] * w[1] + inverse[4 * r + 2] * w[2] +
           inverse[4 * r + 3];
  }
  return p;
}

Vec3 Affine3::vector_to_model(const Vec3& w) const
{
  Vec3 p;
  for (int r = 0; r < 3; ++r)
  {
    p[r] = inverse[4 * r] * w[0] + inverse[4 * r + 1] * w[1] + inverse[4 * r + 2] * w[2];
  }
  return p;
}

Vec3 Affine3::gradient_to_world(const Vec3& g) const
{
  // grad_w F = M^-T grad_m F
  Vec3 w;
  for (int c = 0; c < 3; ++c)
  {
    w[c] = inverse[c] * g[0] + inverse[4 + c] * g[1] + inverse[8 + c] * g[2];
  }
  return w;
}

void ViewRays::ray(double sx, double sy, Vec3& o, Vec3& d) const
{
  const double a = (sx - cx) / focal, b = (cy - sy) / focal;
  for (int k = 0; k < 3; ++k)
  {
    if (orthographic)
    {
      o[k] = e[k] + a * r[k] + b * u[k];
      d[k] = f[k];
    }
    else
    {
      o[k] = e[k];
      d[k] = f[k] + a * r[k] + b * u[k];
    }
  }
}

Vec3 ViewRays::world_origin(double sx, double sy) const
{
  if (!orthographic)
  {
    return eye;
  }
  const double a = (sx - cx) / focal, b = (cy - sy) / focal;
  return { eye[0] + a * right[0] + b * up[0],
    eye[1] + a * right[1] + b * up[1],
    eye[2] + a * right[2] + b * up[2] };
}

Vec3 ViewRays::world_direction(double sx, double sy) const
{
  if (orthographic)
  {
    return forward;
  }
  const double a = (sx - cx) / focal, b = (cy - sy) / focal;
  return { forward[0] + a * right[0] + b * up[0],
    forward[1] + a * right[1] + b * up[1],
    forward[2] + a * right[2] + b * up[2] };
}

ViewRays make_view_rays(const imaging::Camera& camera, int width, int height, const Affine3& map)
{
  ViewRays v;
  const imaging::CameraFrame frame = imaging::camera_frame(camera);
  v.orthographic = camera.orthographic;
  v.cx = 0.5 * width;
  v.cy = 0.5 * height;
  // The mesh renderer's projection (Render/mesh_setup.cpp), so both draw the same picture.
  if (camera.orthographic)
  {
    const double scale = camera.parallel_scale > 0.0 && std::isfinite(camera.parallel_scale)
                           ? camera.parallel_scale
                           : 1.0;
    v.focal = 0.5 * height / scale;
  }
  else
  {
    const double angle = std::clamp(camera.view_angle_deg, 1e-3, 179.0);
    v.focal = 0.5 * height / std::tan(0.5 * angle * std::numbers::pi / 180.0);
  }
  v.near = camera.near_distance > 0.0 ? camera.near_distance : 1e-6;
  v.eye = camera.position;
  v.right = frame.right;
  v.up = frame.up;
  v.forward = frame.forward;
  v.e = map.to_model(v.eye);
  v.r = map.vector_to_model(v.right);
  v.u = map.vector_to_model(v.up);
  v.f = map.vector_to_model(v.forward);
  return v;
}

std::array<double, 2> clip_to_box(const Vec3& o, const Vec3& d, const std::array<Interval, 3>& box,
  double from)
{
  double lo = from, hi = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
  {
    if (d[k] == 0.0)
    {
      if (o[k] < box[k].lo || o[k] > box[k].hi)
      {
        return { 1.0, 0.0 };
      }
      continue;
    }
    double t0 = (box[k].lo - o[k]) / d[k], t1 = (box[k].hi - o[k]) / d[k];
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
  }
  if (!(lo <= hi))
  {
    return { 1.0, 0.0 };
  }
  return { lo, hi };
}

int entry_face(const Vec3& o, const Vec3& d, double lambda, const std::array<Interval, 3>& box)
{
  int best = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
  {
    const double p = o[k] + lambda * d[k];
    const double extent = std::max(box[k].hi - box[k].lo, 1e-300);
    const double to_lo = std::abs(p - box[k].lo) / extent, to_hi = std::abs(p - box[k].hi) / extent;
    if (to_lo < nearest)
    {
      nearest = to_lo;
      best = 2 * k;
    }
    if (to_hi < nearest)
    {
      nearest = to_hi;
      best = 2 * k + 1;
    }
  }
  return best;
}

bool piece_box(const ViewRays& view, double x0, double x1, double y0, double y1, double l0,
  double l1, const std::array<Interval, 3>& box, std::array<Interval, 3>& out)
{
  Vec3 lo{ std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  Vec3 hi{ -lo[0], -lo[1], -lo[2] };
  for (int c = 0; c < 4; ++c)
  {
    Vec3 o, d;
    view.ray(c & 1 ? x1 : x0, c & 2 ? y1 : y0, o, d);
    for (const double l : { l0, l1 })
    {
      for (int k = 0; k < 3; ++k)
      {
        const double p = o[k] + l * d[k];
        lo[k] = std::min(lo[k], p);
        hi[k] = std::max(hi[k], p);
      }
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    // Widen by a few ulps of the extent: the corners are computed with rounding, and the box
    // must contain every sample point computed the same way.
    const double pad = 1e-12 * (std::abs(lo[k]) + std::abs(hi[k]) + (hi[k] - lo[k]));
    out[k].lo = std::max(lo[k] - pad, box[k].lo);
    out[k].hi = std::min(hi[k] + pad, box[k].hi);
    if (!(out[k].lo <= out[k].hi))
    {
      return false;
    }
  }
  return true;
}

} // namespace frep::raycast::detail
