#include "Imaging/camera.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace frep::imaging
{

namespace
{

Vec3 sub(const Vec3& a, const Vec3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec3 cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

bool normalise(Vec3& v)
{
  const double n = std::sqrt(dot(v, v));
  if (!(n > 1e-300) || !std::isfinite(n))
  {
    return false;
  }
  v = { v[0] / n, v[1] / n, v[2] / n };
  return true;
}

constexpr double kDegree = std::numbers::pi / 180.0;

} // namespace

CameraFrame camera_frame(const Camera& camera)
{
  CameraFrame f;
  f.forward = sub(camera.focal_point, camera.position);
  if (!normalise(f.forward))
  {
    f.forward = { 0.0, 1.0, 0.0 };
  }
  f.right = cross(f.forward, camera.view_up);
  if (!normalise(f.right))
  {
    // Up parallel to the view: any perpendicular will do, prefer one in the xy plane.
    f.right = cross(f.forward, Vec3{ 0.0, 0.0, 1.0 });
    if (!normalise(f.right))
    {
      f.right = cross(f.forward, Vec3{ 0.0, 1.0, 0.0 });
      normalise(f.right);
    }
  }
  f.up = cross(f.right, f.forward);
  return f;
}

Camera fit_box(const Vec3& lo,
  const Vec3& hi,
  double aspect,
  double azimuth_deg,
  double elevation_deg,
  const FitOptions& options)
{
  const Vec3 centre{ 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]) };
  const Vec3 half = sub(hi, centre);
  double radius = std::sqrt(dot(half, half));
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    radius = 1.0; // an empty or point box: frame a unit sphere there
  }
  if (!(aspect > 0.0) || !std::isfinite(aspect))
  {
    aspect = 1.0;
  }
  const double fill = std::clamp(options.fill, 0.05, 1.0);
  const double az = azimuth_deg * kDegree;
  const double el = elevation_deg * kDegree;
  // From the centre towards the eye, and its derivative in elevation (the view up): the pair
  // stays orthonormal at the poles, where z itself would be parallel to the view.
  const Vec3 out{ std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el), std::sin(el) };
  const Vec3 up{ -std::sin(az) * std::sin(el), std::cos(az) * std::sin(el), std::cos(el) };
  // The corners' depths towards the eye and distances from the view axis (fit_corners).
  std::array<double, 8> along{}, across{};
  for (int c = 0; options.fit_corners && c < 8; ++c)
  {
    const Vec3 d{ (c & 1 ? half[0] : -half[0]), (c & 2 ? half[1] : -half[1]),
      (c & 4 ? half[2] : -half[2]) };
    along[c] = dot(d, out);
    across[c] = std::sqrt(std::max(dot(d, d) - along[c] * along[c], 0.0));
  }
  const double widest = *std::max_element(across.begin(), across.end());
  const bool corners = options.fit_corners && widest > 0.0 && std::isfinite(widest);

  Camera camera;
  camera.focal_point = centre;
  camera.view_up = up;
  camera.orthographic = options.orthographic;
  camera.view_angle_deg = std::clamp(options.view_angle_deg, 1.0, 170.0);
  double distance = 0.0;
  if (options.orthographic)
  {
    // The sphere's radius is fill/2 of the shorter side: of the height when aspect >= 1.
    camera.parallel_scale = (corners ? widest : radius) / (fill * std::min(1.0, aspect));
    distance = 4.0 * radius;
  }
  else
  {
    // The sphere subtends a half-angle asin(r / d); its outline's radius on the picture is
    // f tan(asin(r / d)) with f = (height / 2) / tan(half view angle). Solve for d so that
    // radius = fill * (shorter side) / 2.
    const double tan_half = std::tan(0.5 * camera.view_angle_deg * kDegree);
    const double target = fill * std::min(1.0, aspect) * tan_half; // tan of the outline angle
    distance = radius * std::sqrt(1.0 + 1.0 / (target * target));
    // Each corner, `along` nearer the eye, is seen within the outline angle when
    // across / (distance - along) <= target: the box's picture (the hull of the corners') too.
    for (int c = 0; corners && c < 8; ++c)
    {
      distance = c == 0 ? 0.0 : distance;
      distance = std::max(distance, along[c] + across[c] / target);
    }
  }
  camera.position = {
    centre[0] + distance * out[0], centre[1] + distance * out[1], centre[2] + distance * out[2]
  };
  // Far in front of the bounding sphere (the depth buffer holds 1 / depth in floats, so a small
  // near distance costs no precision): meshes that stray outside the box are still drawn.
  camera.near_distance = 0.01 * distance;
  return camera;
}

CameraFrame view_frame(double azimuth_deg, double elevation_deg)
{
  return camera_frame(
    fit_box({ -1.0, -1.0, -1.0 }, { 1.0, 1.0, 1.0 }, 1.0, azimuth_deg, elevation_deg));
}

namespace
{

/// What fit_oriented found: the fitted camera, or that there was no finite point, or that the
/// points were all at one place (`at`), which has no size to fit.
struct OrientedFit
{
  enum class Kind
  {
    Fitted,
    NoPoint,
    OnePlace
  } kind;
  Camera camera;
  Vec3 at;
};

/// fit_points' work for a camera already oriented (its frame, view angle and projection): the
/// nearest eye along its view direction that sees every point within the fill.
OrientedFit fit_oriented(Camera camera,
  std::span<const Vec3> points,
  double aspect,
  const FitOptions& options,
  double margin)
{
  const CameraFrame f = camera_frame(camera);
  // The points in the view's coordinates (right, up, forward), and their extent.
  std::vector<Vec3> view;
  view.reserve(points.size());
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{ inf, inf, inf }, hi{ -inf, -inf, -inf };
  for (const Vec3& p : points)
  {
    const Vec3 v{ dot(p, f.right), dot(p, f.up), dot(p, f.forward) };
    if (std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]))
    {
      view.push_back(v);
      for (int k = 0; k < 3; ++k)
      {
        lo[k] = std::min(lo[k], v[k]);
        hi[k] = std::max(hi[k], v[k]);
      }
    }
  }
  if (!(lo[0] <= hi[0]))
  {
    return { OrientedFit::Kind::NoPoint, camera, {} };
  }
  margin = std::isfinite(margin) ? std::max(margin, 0.0) : 0.0;
  aspect = aspect > 0.0 && std::isfinite(aspect) ? aspect : 1.0;
  const double fill = std::clamp(options.fill, 0.05, 1.0);
  const Vec3 c{ 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]) };
  const Vec3 half{
    0.5 * (hi[0] - lo[0]) + margin, 0.5 * (hi[1] - lo[1]) + margin, 0.5 * (hi[2] - lo[2])
  };
  const double size = std::max({ half[0], half[1], half[2] });
  if (!(size > 1e-12 * std::max({ std::abs(c[0]), std::abs(c[1]), std::abs(c[2]), 1.0 })))
  {
    const Vec3 at{ c[0] * f.right[0] + c[1] * f.up[0] + c[2] * f.forward[0],
      c[0] * f.right[1] + c[1] * f.up[1] + c[2] * f.forward[1],
      c[0] * f.right[2] + c[1] * f.up[2] + c[2] * f.forward[2] };
    return { OrientedFit::Kind::OnePlace, camera, at };
  }
  // The eye at (sx, sy, e) in the view's coordinates, looking along +forward. The picture spans
  // -1..1 of its half height up; the points go into the window over the free bottom band,
  // shrunk by the fill about its centre: from -lower to upper.
  const double band = std::clamp(options.free_bottom, 0.0, 0.5);
  const double upper = band + fill * (1.0 - band), lower = fill * (1.0 - band) - band;
  double sx = c[0], sy = c[1], e = 0.0;
  if (camera.orthographic)
  {
    camera.parallel_scale = std::max(half[1] / (fill * (1.0 - band)), half[0] / (fill * aspect));
    sy = c[1] - band * camera.parallel_scale; // the points' middle at the window's middle
    e = lo[2] - 2.0 * size;
  }
  else
  {
    // A point is seen when v - s + margin <= up (z - e) and s - v + margin <= down (z - e) on
    // each axis (up, down: the window's sides over the focal length): s between
    // max(v + margin - up z) + up e and min(v - margin + down z) - down e. The nearest eye has
    // the two meet on one axis, where the points nearer the eye and those farther away both
    // reach the window (perspective: the axis does not go through the middle of the extent).
    const double tan_v = std::tan(0.5 * camera.view_angle_deg * kDegree);
    const std::array<double, 2> up{ fill * tan_v * aspect, upper * tan_v };
    const std::array<double, 2> down{ fill * tan_v * aspect, lower * tan_v };
    std::array<double, 2> most{}, least{};
    e = lo[2] - 1e-6 * size; // every point in front of the eye
    for (int a = 0; a < 2; ++a)
    {
      most[a] = -inf;
      least[a] = inf;
      for (const Vec3& v : view)
      {
        most[a] = std::max(most[a], v[a] + margin - up[a] * v[2]);
        least[a] = std::min(least[a], v[a] - margin + down[a] * v[2]);
      }
      e = std::min(e, (least[a] - most[a]) / (up[a] + down[a]));
    }
    sx = 0.5 * (most[0] + up[0] * e + least[0] - down[0] * e);
    sy = 0.5 * (most[1] + up[1] * e + least[1] - down[1] * e);
  }
  const double distance = c[2] - e;
  const Vec3 focus{ sx, sy, c[2] };
  for (int k = 0; k < 3; ++k)
  {
    camera.focal_point[k] = focus[0] * f.right[k] + focus[1] * f.up[k] + focus[2] * f.forward[k];
    camera.position[k] = camera.focal_point[k] - distance * f.forward[k];
  }
  camera.near_distance = 0.01 * distance;
  return { OrientedFit::Kind::Fitted, camera, {} };
}

} // namespace


Camera fit_points(std::span<const Vec3> points,
  double aspect,
  double azimuth_deg,
  double elevation_deg,
  const FitOptions& options,
  double margin)
{
  FitOptions oriented = options;
  oriented.fit_corners = false;
  // fit_box orients the camera (view up continuous through the poles) and sets the projection.
  const Camera camera =
    fit_box({ -1.0, -1.0, -1.0 }, { 1.0, 1.0, 1.0 }, aspect, azimuth_deg, elevation_deg, oriented);
  const OrientedFit fit = fit_oriented(camera, points, aspect, options, margin);
  switch (fit.kind)
  {
    case OrientedFit::Kind::NoPoint:
      return camera; // the unit sphere at the origin
    case OrientedFit::Kind::OnePlace:
      return fit_box(fit.at, fit.at, aspect, azimuth_deg, elevation_deg, oriented);
    case OrientedFit::Kind::Fitted:
      break;
  }
  return fit.camera;
}

Camera fit_points(std::span<const Vec3> points,
  double aspect,
  const Camera& direction,
  const FitOptions& options,
  double margin)
{
  Camera camera = direction;
  camera.view_angle_deg = options.view_angle_deg;
  camera.orthographic = options.orthographic;
  const OrientedFit fit = fit_oriented(camera, points, aspect, options, margin);
  if (fit.kind == OrientedFit::Kind::OnePlace)
  {
    // Nothing to fit: the same view, moved to look at that place.
    for (int k = 0; k < 3; ++k)
    {
      camera.position[k] += fit.at[k] - camera.focal_point[k];
      camera.focal_point[k] = fit.at[k];
    }
    return camera;
  }
  return fit.camera;
}

} // namespace frep::imaging
