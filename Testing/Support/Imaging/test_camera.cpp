// fit_box: the documented directions, and a box's corners inside the picture from any view.
// fit_points: every point inside `fill` of the picture and the outline touching it, from any
// view, perspective and parallel; a box's corners reach the fill on both sides of the limiting
// axis, framed tighter than by fit_box; a free band at the bottom stays free; a margin widens;
// no points is usable.
#include "Imaging/camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace frep::imaging
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

// Where a point is on the picture: its offsets right and up over the picture's half height.
std::array<double, 2> on_picture(const Camera& c, const Vec3& p)
{
  const CameraFrame f = camera_frame(c);
  const Vec3 d{ p[0] - c.position[0], p[1] - c.position[1], p[2] - c.position[2] };
  if (c.orthographic)
  {
    return { dot(d, f.right) / c.parallel_scale, dot(d, f.up) / c.parallel_scale };
  }
  const double t = std::tan(0.5 * c.view_angle_deg * std::numbers::pi / 180.0);
  const double z = dot(d, f.forward);
  EXPECT_GT(z, c.near_distance);
  return { dot(d, f.right) / (z * t), dot(d, f.up) / (z * t) };
}

TEST(Camera, FitPointsFramesTheirOutline)
{
  // Points on a unit sphere around (1, 2, 3).
  std::vector<Vec3> ball;
  for (int i = 0; i < 40; ++i)
  {
    for (int j = 0; j <= 20; ++j)
    {
      const double phi = 2 * std::numbers::pi * i / 40, theta = std::numbers::pi * j / 20;
      ball.push_back({ 1 + std::sin(theta) * std::cos(phi),
        2 + std::sin(theta) * std::sin(phi),
        3 + std::cos(theta) });
    }
  }
  for (const bool orthographic : { false, true })
  {
    for (const double aspect : { 0.5, 1.0, 16.0 / 9.0 })
    {
      for (double az = -180; az < 180; az += 60)
      {
        for (double el = -90; el <= 90; el += 45)
        {
          FitOptions fit;
          fit.orthographic = orthographic;
          fit.fill = 0.8;
          const Camera c = fit_points(ball, aspect, az, el, fit);
          // The direction is fit_box's.
          const CameraFrame want = view_frame(az, el), got = camera_frame(c);
          EXPECT_NEAR(dot(want.forward, got.forward), 1.0, 1e-9);
          EXPECT_NEAR(dot(want.up, got.up), 1.0, 1e-9);
          double widest = 0.0;
          for (const Vec3& p : ball)
          {
            const std::array<double, 2> xy = on_picture(c, p);
            EXPECT_LE(std::abs(xy[0]), 0.8 * aspect * 1.0001);
            EXPECT_LE(std::abs(xy[1]), 0.8 * 1.0001);
            widest = std::max({ widest, std::abs(xy[0]) / aspect, std::abs(xy[1]) });
          }
          EXPECT_GT(widest, 0.8 * 0.999); // the outline reaches the fill: tight
        }
      }
    }
  }
}

TEST(Camera, FitPointsAlongAGivenViewIsTheSameFit)
{
  // The direction given as a camera (FRepStudio's turned view) fits as the azimuth and elevation
  // that give that direction do (to rounding: the frame is computed from other numbers), with
  // the options' projection, and frames a box's corners tightly.
  std::vector<Vec3> corners;
  for (int corner = 0; corner < 8; ++corner)
    corners.push_back({ corner & 1 ? 3.0 : -1.0, corner & 2 ? 1.5 : -0.5, corner & 4 ? 2.0 : 0.0 });
  for (const bool orthographic : { false, true })
  {
    for (double az = -150; az < 180; az += 75)
    {
      for (double el = -60; el <= 60; el += 40)
      {
        FitOptions fit;
        fit.orthographic = orthographic;
        fit.fill = 0.85;
        const Camera by_angles = fit_points(corners, 1.25, az, el, fit);
        Camera direction = by_angles;
        direction.position = { 7.0, -3.0, 2.0 }; // anywhere along another distance...
        const CameraFrame f = view_frame(az, el);
        for (int k = 0; k < 3; ++k) // ...on the same view direction
          direction.focal_point[k] = direction.position[k] + 4.0 * f.forward[k];
        direction.view_angle_deg = 50; // the options' projection wins
        direction.orthographic = !orthographic;
        const Camera by_camera = fit_points(corners, 1.25, direction, fit);
        for (int k = 0; k < 3; ++k)
        {
          EXPECT_NEAR(by_camera.position[k], by_angles.position[k], 1e-9);
          EXPECT_NEAR(by_camera.focal_point[k], by_angles.focal_point[k], 1e-9);
        }
        EXPECT_EQ(by_camera.view_angle_deg, 30.0);
        EXPECT_EQ(by_camera.orthographic, orthographic);
        EXPECT_NEAR(by_camera.parallel_scale, by_angles.parallel_scale, 1e-9);
        // The corners within the fill, the outline reaching it (the tight fit).
        double widest = 0.0;
        for (const Vec3& p : corners)
        {
          const std::array<double, 2> xy = on_picture(by_camera, p);
          EXPECT_LE(std::abs(xy[0]), 0.85 * 1.25 * 1.0001);
          EXPECT_LE(std::abs(xy[1]), 0.85 * 1.0001);
          widest = std::max({ widest, std::abs(xy[0]) / 1.25, std::abs(xy[1]) });
        }
        EXPECT_GT(widest, 0.85 * 0.999);
      }
    }
  }
  // All at one place: the same view, looking at it.
  Camera direction;
  const std::vector<Vec3> one(3, Vec3{ 2.0, 2.0, 2.0 });
  const Camera at = fit_points(one, 1.0, direction, FitOptions{});
  EXPECT_EQ(at.focal_point, (Vec3{ 2.0, 2.0, 2.0 }));
}

TEST(Camera, FitPointsOfABoxsCornersAndMargin)
{
  const Vec3 lo{ -1, -1, -1 }, hi{ 1, 1, 1 };
  std::vector<Vec3> corners;
  for (int k = 0; k < 8; ++k)
  {
    corners.push_back({ k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2] });
  }
  FitOptions fit;
  fit.fill = 0.9;
  const Camera points = fit_points(corners, 1.0, 35.0, 25.0, fit);
  const Camera box = fit_box(lo, hi, 1.0, 35.0, 25.0, fit);
  const Camera corner_box = [&]
  {
    FitOptions c = fit;
    c.fit_corners = true;
    return fit_box(lo, hi, 1.0, 35.0, 25.0, c);
  }();
  // Every corner inside the fill; on the axis that limits the eye, both sides reach it (the
  // nearer corners project larger: the view axis is shifted, not through the box's centre).
  std::array<double, 2> low{ 1e9, 1e9 }, high{ -1e9, -1e9 };
  for (const Vec3& p : corners)
  {
    const std::array<double, 2> xy = on_picture(points, p);
    for (int a = 0; a < 2; ++a)
    {
      EXPECT_LE(std::abs(xy[a]), 0.9 * 1.0001);
      low[a] = std::min(low[a], xy[a]);
      high[a] = std::max(high[a], xy[a]);
    }
  }
  EXPECT_TRUE((std::abs(low[0] + 0.9) < 1e-9 && std::abs(high[0] - 0.9) < 1e-9) ||
              (std::abs(low[1] + 0.9) < 1e-9 && std::abs(high[1] - 0.9) < 1e-9))
    << low[0] << " " << high[0] << " " << low[1] << " " << high[1];
  const auto distance = [](const Camera& c)
  {
    return std::hypot(c.position[0] - c.focal_point[0],
      c.position[1] - c.focal_point[1],
      c.position[2] - c.focal_point[2]);
  };
  EXPECT_LT(distance(points), distance(corner_box)); // a rectangle, not the shorter side's circle
  EXPECT_LT(distance(corner_box), distance(box));
  // A free band at the bottom: every corner above it, perspective and parallel.
  for (const bool orthographic : { false, true })
  {
    FitOptions banded = fit;
    banded.free_bottom = 0.25;
    banded.orthographic = orthographic;
    const Camera c = fit_points(corners, 16.0 / 9.0, 35.0, 25.0, banded);
    double lowest = 1e9;
    for (const Vec3& p : corners)
    {
      const std::array<double, 2> xy = on_picture(c, p);
      EXPECT_LE(xy[1], 1.0);
      lowest = std::min(lowest, xy[1]);
    }
    EXPECT_GE(lowest, -1.0 + 2 * 0.25 - 1e-9); // the band: a quarter of the height, 0.5 of 2
    EXPECT_LE(lowest, -1.0 + 2 * 0.25 + 0.1);  // and near it
  }
  // A margin keeps every corner that far inside across the view: the eye moves back.
  const Camera wider = fit_points(corners, 1.0, 35.0, 25.0, fit, 0.5);
  EXPECT_GT(distance(wider), distance(points));
  // No finite point, or one place only: a usable camera (fit_box's unit sphere).
  const Camera none = fit_points(std::vector<Vec3>{ { NAN, 0, 0 } }, 1.0, 0.0, 0.0);
  EXPECT_TRUE(std::isfinite(none.position[0]) && std::isfinite(none.position[1]));
  const Camera one = fit_points(std::vector<Vec3>{ { 5, 5, 5 }, { 5, 5, 5 } }, 1.0, 0.0, 0.0);
  EXPECT_NEAR(one.focal_point[0], 5.0, 1e-12);
  EXPECT_LT(one.position[1], 4.0); // back from the point along -y, by the unit sphere's distance
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
} // namespace frep::imaging
