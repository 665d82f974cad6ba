// The ray caster against analytic shapes: a sphere's silhouette (orthographic and perspective)
// and its Lambert shading against the exact projection; a shell thinner than a mesher's grid
// cell is found; an object behind the camera or outside the box leaves the picture empty; the
// box's cut faces are drawn as caps; the depth of the nearest point; the same picture for 1
// and 2 threads (floor and shadows included); bad input refused; the solid's bounds (two passes,
// to 1/256 of the box) and bounds given in the shape draw the same picture; the silhouette a
// camera must see (a ball's outline along any view).
#include "Raycast/raycast.h"

#include "Compiler/model.h"
#include "Language/ast.h"
#include "Language/parser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace
{

using frep::Interval;
using frep::RunControl;
namespace rc = frep::raycast;
namespace imaging = frep::imaging;

std::shared_ptr<const frep::Tape> tape_of(const std::string& body, int dimension = 3)
{
  const std::string text = "my_model(x[" + std::to_string(dimension) + "], a[1]) { my_model = " +
                           body + "; }";
  const frep::ParseResult parsed = frep::parse_program(text, "<test>");
  EXPECT_TRUE(parsed.ok());
  const int object = frep::ast::select_default_object(*parsed.program);
  return frep::Model::compile(parsed.program, object).model->tape();
}

rc::Shape sphere_shape(double radius = 1.0)
{
  rc::Shape s;
  s.tape = tape_of(std::to_string(radius * radius) + " - x[1]^2 - x[2]^2 - x[3]^2");
  s.box = { Interval{ -2, 2 }, Interval{ -2, 2 }, Interval{ -2, 2 } };
  s.colour = { 1.0F, 1.0F, 1.0F };
  return s;
}

// One light from the camera, no ambient, no highlight: a pixel's value is n . l.
rc::Style lambert_style(int supersample = 1, int threads = 1)
{
  rc::Style style;
  style.render.lights = { imaging::Light{ { 0.0, 0.0, 1.0 }, 1.0, 0.0 } };
  style.render.ambient = 0.0;
  style.render.specular = 0.0;
  style.render.supersample = supersample;
  style.render.threads = threads;
  return style;
}

imaging::Camera ortho_camera(double scale)
{
  imaging::Camera camera;
  camera.position = { 0.0, -10.0, 0.0 };
  camera.focal_point = { 0.0, 0.0, 0.0 };
  camera.view_up = { 0.0, 0.0, 1.0 };
  camera.orthographic = true;
  camera.parallel_scale = scale;
  return camera;
}

int covered(const imaging::Image& image)
{
  int n = 0;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      n += image.at(x, y).a > 0.5F ? 1 : 0;
    }
  }
  return n;
}

TEST(Raycast, OrthographicSphereSilhouetteAndShading)
{
  imaging::Image image(200, 200);
  const rc::Result r = rc::render(image, ortho_camera(2.0), sphere_shape(), nullptr, lambert_style());
  ASSERT_TRUE(r.ok()) << r.error;
  // Radius 1 world unit = 50 pixels (100 pixels per 2 units of parallel scale).
  const double expected = std::numbers::pi * 50.0 * 50.0;
  EXPECT_NEAR(covered(image), expected, 0.01 * expected);
  // Lambert: n . v = sqrt(1 - rho^2) at distance rho (in radii) from the centre.
  for (const int px : { 100, 120, 130, 140 })
  {
    const double rho = (px + 0.5 - 100.0) / 50.0;
    EXPECT_NEAR(image.at(px, 100).r, std::sqrt(1.0 - rho * rho), 2e-3) << "pixel " << px;
  }
  EXPECT_EQ(image.at(5, 5).a, 0.0F);
  EXPECT_EQ(r.statistics.rays, 200u * 200u);
  EXPECT_GT(r.statistics.hits, 7000u);
}

TEST(Raycast, PerspectiveSilhouetteIsTheExactProjection)
{
  imaging::Camera camera;
  camera.position = { 0.0, -6.0, 0.0 };
  camera.view_angle_deg = 30.0;
  imaging::Image image(301, 301);
  const rc::Result r = rc::render(image, camera, sphere_shape(), nullptr, lambert_style());
  ASSERT_TRUE(r.ok()) << r.error;
  // The silhouette's half angle is asin(r / d); in pixels, focal * tan(asin(1/6)).
  const double focal = 0.5 * 301 / std::tan(15.0 * std::numbers::pi / 180.0);
  const double radius_px = focal * std::tan(std::asin(1.0 / 6.0));
  int row = 0;
  for (int x = 0; x < image.width; ++x)
  {
    row += image.at(x, 150).a > 0.5F ? 1 : 0;
  }
  EXPECT_NEAR(row, 2.0 * radius_px, 2.0);
}

TEST(Raycast, DepthIsTheNearestPoint)
{
  imaging::Image image(101, 101);
  std::vector<float> depth;
  const rc::Result r =
    rc::render(image, ortho_camera(2.0), sphere_shape(), nullptr, lambert_style(), &depth);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(depth.size(), 101u * 101u);
  // The eye is 10 units from the centre: the nearest point is at depth 9.
  EXPECT_NEAR(depth[50 * 101 + 50], 9.0, 1e-3);
  EXPECT_TRUE(std::isinf(depth[0]));
}

TEST(Raycast, ThinShellBelowTheMeshGridIsFound)
{
  // A shell 0.02 thick: thinner than a cell of a 128^3 grid over the box (0.031), and than a
  // picture sample (0.04 at this size), is found on every ray that crosses it.
  rc::Shape shell;
  shell.tape = tape_of("0.01 - abs(sqrt(x[1]^2 + x[2]^2 + x[3]^2) - 1)");
  shell.box = { Interval{ -2, 2 }, Interval{ -2, 2 }, Interval{ -2, 2 } };
  imaging::Image image(100, 100);
  const rc::Result r = rc::render(image, ortho_camera(2.0), shell, nullptr, lambert_style());
  ASSERT_TRUE(r.ok()) << r.error;
  const double expected = std::numbers::pi * 25.25 * 25.25;
  EXPECT_NEAR(covered(image), expected, 0.02 * expected);
}

TEST(Raycast, BehindTheCameraOrOutsideTheBoxIsEmpty)
{
  imaging::Camera away;
  away.position = { 0.0, -6.0, 0.0 };
  away.focal_point = { 0.0, -12.0, 0.0 }; // looking away from the sphere
  imaging::Image image(64, 64);
  rc::Result r = rc::render(image, away, sphere_shape(), nullptr, lambert_style());
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(covered(image), 0);
  EXPECT_EQ(r.statistics.hits, 0u);

  rc::Shape outside = sphere_shape();
  outside.tape = tape_of("1 - (x[1] - 5)^2 - x[2]^2 - x[3]^2"); // centred outside the box
  imaging::Image image2(64, 64);
  r = rc::render(image2, ortho_camera(8.0), outside, nullptr, lambert_style());
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(covered(image2), 0);
}

TEST(Raycast, TheBoxCutsTheSolidWithCaps)
{
  // Everything is inside: the picture is the box itself, its front face lit head-on.
  rc::Shape all;
  all.tape = tape_of("1 + 0 * x[1]");
  all.box = { Interval{ -1, 1 }, Interval{ -1, 1 }, Interval{ -1, 1 } };
  all.colour = { 1.0F, 1.0F, 1.0F };
  imaging::Image image(100, 100);
  const rc::Result r = rc::render(image, ortho_camera(2.0), all, nullptr, lambert_style());
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(covered(image), 50 * 50);
  EXPECT_NEAR(image.at(50, 50).r, 1.0F, 1e-6);
}

TEST(Raycast, SameImageForOneAndTwoThreads)
{
  imaging::Camera camera;
  camera.position = { 4.0, -6.0, 3.0 };
  rc::Shape shape;
  shape.tape = tape_of("max(1 - x[1]^2 - x[2]^2 - x[3]^2, 0.3 - (x[1] - 1)^2 - x[2]^2 - x[3]^2)");
  shape.box = { Interval{ -2, 2 }, Interval{ -2, 2 }, Interval{ -1, 2 } };
  rc::Floor floor;
  floor.height = -1.0;
  floor.origin = { -3.0, -3.0 };
  floor.square = 1.0;
  floor.columns = floor.rows = 6;
  floor.path = { -2.0, -2.0, 2.0, 1.0, 2.0, 2.0 };
  imaging::Image one(160, 120), two(160, 120);
  rc::Style style;
  style.self_shadows = true;
  RunControl run;
  run.threads = 1;
  const rc::Result r1 = rc::render(one, camera, shape, &floor, style, nullptr, run);
  run.threads = 2;
  const rc::Result r2 = rc::render(two, camera, shape, &floor, style, nullptr, run);
  ASSERT_TRUE(r1.ok() && r2.ok()) << r1.error << r2.error;
  EXPECT_EQ(one.rgba, two.rgba);
  EXPECT_GT(r1.statistics.shadow_rays, 0u);
  // The floor is drawn (opaque pixels far from the shape) and the shadow darkens part of it.
  EXPECT_GT(covered(one), 160 * 120 / 4);
}

TEST(Raycast, BadInputIsRefused)
{
  imaging::Image image(8, 8);
  rc::Shape flat;
  flat.tape = tape_of("1 - x[1]^2 - x[2]^2", 2);
  flat.box = { Interval{ -1, 1 }, Interval{ -1, 1 }, Interval{ -1, 1 } };
  EXPECT_NE(rc::render(image, ortho_camera(1.0), flat).error.find("3 inputs"), std::string::npos);
  rc::Shape singular = sphere_shape();
  singular.to_world = { 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0 };
  EXPECT_NE(rc::render(image, ortho_camera(1.0), singular).error.find("singular"), std::string::npos);
  rc::Shape bad_box = sphere_shape();
  bad_box.box[1] = Interval{ 1, -1 };
  EXPECT_FALSE(rc::render(image, ortho_camera(1.0), bad_box).ok());
  imaging::Image empty;
  EXPECT_FALSE(rc::render(empty, ortho_camera(1.0), sphere_shape()).ok());
}

TEST(Raycast, CancelStopsTheWork)
{
  imaging::Image image(64, 64);
  RunControl run;
  run.cancel = [] { return true; };
  const rc::Result r =
    rc::render(image, ortho_camera(2.0), sphere_shape(), nullptr, lambert_style(), nullptr, run);
  EXPECT_EQ(r.error, "cancelled");
}

// RunControl's progress returning false stops the picture too (as it stops the sampler and the
// mesher), after the first report.
TEST(Raycast, ProgressReturningFalseStopsTheWork)
{
  imaging::Image image(160, 160);
  RunControl run;
  run.threads = 1;
  int reports = 0;
  run.progress = [&reports](double) { return ++reports < 2; };
  const rc::Result r =
    rc::render(image, ortho_camera(2.0), sphere_shape(), nullptr, lambert_style(), nullptr, run);
  EXPECT_EQ(r.error, "cancelled");
  EXPECT_EQ(reports, 2);
}

TEST(Raycast, ProgressRisesToOneOnTheCallingThread)
{
  imaging::Image image(160, 160);
  rc::Style style = lambert_style();
  style.render.supersample = 2;
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<double> values;
  bool elsewhere = false;
  RunControl run;
  run.threads = 2;
  run.progress = [&](double f)
  {
    elsewhere = elsewhere || std::this_thread::get_id() != caller;
    values.push_back(f);
    return true;
  };
  const rc::Result r =
    rc::render(image, ortho_camera(2.0), sphere_shape(), nullptr, style, nullptr, run);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_FALSE(elsewhere);
  ASSERT_GE(values.size(), 3u); // 100 tiles: the caller finishes some of them
  EXPECT_TRUE(std::is_sorted(values.begin(), values.end()));
  EXPECT_GT(values.front(), 0.0);
  EXPECT_LT(values.front(), 1.0);
  EXPECT_EQ(values.back(), 1.0);
}


// lowest_z: where a floor under the solid must be for the solid to stand on it (the floor scene
// and `frepkit render --floor`). A ball's lowest point, also through a rotation and scale; a
// flat bottom; the box's cap when the solid runs out of the box; a downward cone's tip; nothing
// for an empty solid.
TEST(Raycast, LowestPointOfTheSolid)
{
  rc::Shape ball;
  ball.tape = tape_of("2.25 - (x[1] - 0.5)^2 - (x[2] + 0.25)^2 - (x[3] - 0.75)^2");
  ball.box = { Interval{ -2, 2 }, Interval{ -2, 2 }, Interval{ -2, 2 } };
  const std::optional<double> z = rc::lowest_z(ball);
  ASSERT_TRUE(z);
  EXPECT_NEAR(*z, 0.75 - 1.5, 1e-4);
  // World = R (2 m) + (0, 0, -3), R a quarter turn about x: world z = 2 y - 3.
  ball.to_world = { 2, 0, 0, 0, 0, 0, -2, 0, 0, 2, 0, -3 };
  const std::optional<double> turned = rc::lowest_z(ball, 128, 2);
  ASSERT_TRUE(turned);
  EXPECT_NEAR(*turned, 2.0 * (-0.25 - 1.5) - 3.0, 2e-4);

  rc::Shape slab = sphere_shape();
  slab.tape = tape_of("x[3] + 0.5"); // z >= -0.5, cut by the box: a flat bottom
  ASSERT_TRUE(rc::lowest_z(slab));
  EXPECT_NEAR(*rc::lowest_z(slab), -0.5, 1e-6);
  slab.tape = tape_of("1 - x[3]"); // z <= 1: the box's bottom cap
  ASSERT_TRUE(rc::lowest_z(slab));
  EXPECT_NEAR(*rc::lowest_z(slab), -2.0, 1e-6);

  rc::Shape cone = sphere_shape();
  cone.tape = tape_of("x[3] + 1 - sqrt(x[1]^2 + x[2]^2)"); // tip at (0, 0, -1), opening up
  const std::optional<double> tip = rc::lowest_z(cone);
  ASSERT_TRUE(tip);
  EXPECT_GE(*tip, -1.0 - 1e-6);
  EXPECT_LE(*tip, -1.0 + 4.0 * 4.0 / 128 / 128 * 4.0); // within a few of the fine rays' spacing

  rc::Shape empty = sphere_shape();
  empty.tape = tape_of("-1 - x[1]^2");
  EXPECT_FALSE(rc::lowest_z(empty));
}

// solid_bounds: what the ray caster clips to and cameras frame. A ball of radius 1 in [-10, 10]^3
// to 1/256 of the box; none for an empty solid; bounds given in the shape draw the same picture.
TEST(Raycast, SolidBoundsAndGivenBounds)
{
  rc::Shape ball = sphere_shape();
  ball.box = { Interval{ -10, 10 }, Interval{ -10, 10 }, Interval{ -10, 10 } };
  const frep::mesh::SolidBounds b = rc::solid_bounds(ball.tape, ball.box);
  ASSERT_TRUE(b.bounded());
  for (const Interval& i : b.box)
  {
    EXPECT_LE(i.lo, -1.0);
    EXPECT_GE(i.lo, -1.0 - 2 * 20.0 / 256);
    EXPECT_GE(i.hi, 1.0);
    EXPECT_LE(i.hi, 1.0 + 2 * 20.0 / 256);
  }
  rc::Shape empty = sphere_shape();
  empty.tape = tape_of("-1 - x[1]^2");
  EXPECT_EQ(rc::solid_bounds(empty.tape, empty.box).status, frep::mesh::SolidBounds::Status::Empty);

  const imaging::Camera camera = ortho_camera(1.2);
  imaging::Image searched(64, 64), given(64, 64);
  ASSERT_TRUE(rc::render(searched, camera, ball, nullptr, lambert_style()).ok());
  ball.bounds = b;
  ASSERT_TRUE(rc::render(given, camera, ball, nullptr, lambert_style()).ok());
  EXPECT_EQ(searched.rgba, given.rgba);
}

// silhouette: the first hits of rays along the view. A ball's points lie on it, on its front
// (towards the eye), and their outline across the view is its radius to a ray's spacing.
TEST(Raycast, SilhouetteOfABall)
{
  rc::Shape ball = sphere_shape(1.5);
  ball.box = { Interval{ -10, 10 }, Interval{ -10, 10 }, Interval{ -10, 10 } };
  ball.to_world = { 1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3 }; // moved to (1, 2, 3)
  for (const double az : { 0.0, 35.0, 120.0 })
  {
    const imaging::CameraFrame view = imaging::view_frame(az, 25.0);
    const rc::Silhouette s = rc::silhouette(ball, view, 48, 2);
    // The picture covers the bounds' cube (side 3 to 1/256 of the box) seen along the view.
    ASSERT_GT(s.points.size(), 48u * 48 / 5);
    EXPECT_GT(s.spacing, 3.0 / 48);
    EXPECT_LT(s.spacing, 3.2 * std::sqrt(3.0) / 48);
    double right_lo = 1e9, right_hi = -1e9;
    for (const imaging::Vec3& p : s.points)
    {
      const imaging::Vec3 d{ p[0] - 1, p[1] - 2, p[2] - 3 };
      EXPECT_NEAR(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), 1.5, 1e-3);
      EXPECT_LE(d[0] * view.forward[0] + d[1] * view.forward[1] + d[2] * view.forward[2], 1e-3);
      const double r = d[0] * view.right[0] + d[1] * view.right[1] + d[2] * view.right[2];
      right_lo = std::min(right_lo, r);
      right_hi = std::max(right_hi, r);
    }
    EXPECT_NEAR(right_lo, -1.5, s.spacing);
    EXPECT_NEAR(right_hi, 1.5, s.spacing);
  }
  rc::Shape empty = sphere_shape();
  empty.tape = tape_of("-1 - x[1]^2");
  EXPECT_TRUE(rc::silhouette(empty, imaging::view_frame(0.0, 0.0)).points.empty());
}

} // namespace
