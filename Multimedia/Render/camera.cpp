#include "Render/camera.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace frep::render
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

} // namespace frep::render
