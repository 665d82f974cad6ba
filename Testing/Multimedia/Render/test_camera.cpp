// fit_box: the documented directions, and a box's corners inside the picture from any view.
#include "Render/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace frep::render
{
namespace
{

double dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void expect_direction(const Camera& c, const Vec3& out)
{
  Vec3 d{ c.position[0] - c.focal_point[0],
    c.position[1] - c.focal_point[1],
    c.position[2] - c.focal_point[2] };
  const double n = std::sqrt(dot(d, d));
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(d[i] / n, out[i], 1e-12);
  }
}

TEST(Camera, FitBoxDirections)
{
  const Vec3 lo{ 0, 0, 0 }, hi{ 2, 4, 6 };
  const Camera front = fit_box(lo, hi, 1.0, 0.0, 0.0);
  EXPECT_EQ(front.focal_point, (Vec3{ 1, 2, 3 }));
  expect_direction(front, { 0, -1, 0 });
  EXPECT_NEAR(camera_frame(front).right[0], 1.0, 1e-12); // x to the right
  expect_direction(fit_box(lo, hi, 1.0, 90.0, 0.0), { 1, 0, 0 });
  EXPECT_NEAR(camera_frame(fit_box(lo, hi, 1.0, 90.0, 0.0)).right[1], 1.0, 1e-12);
  // Straight down: a valid frame (up continues the azimuth's forward direction).
  const Camera top = fit_box(lo, hi, 1.0, 0.0, 90.0);
  expect_direction(top, { 0, 0, 1 });
  const CameraFrame f = camera_frame(top);
  EXPECT_NEAR(f.up[1], 1.0, 1e-12);
  EXPECT_NEAR(dot(f.right, f.forward), 0.0, 1e-12);
}

// Every corner of the box projects inside the picture, and the bounding sphere spans `fill`.
TEST(Camera, FitBoxFramesTheBox)
{
  const Vec3 lo{ -1, -2, 0.5 }, hi{ 3, 1, 2 };
  for (const double aspect : { 0.5, 1.0, 16.0 / 9.0 })
  {
    for (double az = -180; az < 180; az += 45)
    {
      for (double el = -90; el <= 90; el += 30)
      {
        const Camera c = fit_box(lo, hi, aspect, az, el);
        const CameraFrame f = camera_frame(c);
        const double t = std::tan(0.5 * c.view_angle_deg * std::numbers::pi / 180.0);
        for (int k = 0; k < 8; ++k)
        {
          const Vec3 p{ k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2] };
          const Vec3 d{ p[0] - c.position[0], p[1] - c.position[1], p[2] - c.position[2] };
          const double z = dot(d, f.forward);
          ASSERT_GT(z, c.near_distance);
          EXPECT_LE(std::abs(dot(d, f.up) / z), t * 1.0001);
          EXPECT_LE(std::abs(dot(d, f.right) / z), t * aspect * 1.0001);
        }
      }
    }
  }
}

TEST(Camera, DegenerateInputsStayUsable)
{
  const Camera c = fit_box({ 1, 1, 1 }, { 1, 1, 1 }, 0.0, 0.0, 0.0);
  EXPECT_TRUE(std::isfinite(c.position[1]));
  EXPECT_LT(c.position[1], 1.0);
  Camera same;
  same.focal_point = same.position;
  same.view_up = { 0, 0, 0 };
  const CameraFrame f = camera_frame(same);
  EXPECT_NEAR(dot(f.right, f.right), 1.0, 1e-12);
  EXPECT_NEAR(dot(f.up, f.up), 1.0, 1e-12);
}

} // namespace
} // namespace frep::render
