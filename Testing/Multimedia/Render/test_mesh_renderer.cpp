// The mesh renderer: coverage against the analytic projection, shading, clipping, the depth
// buffer, transparency, determinism across thread counts, and bad input that must not crash.
#include "Imaging/camera.h"
#include "Render/mesh_renderer.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace frep::render
{
namespace
{

using test::TestMesh;
using test::uv_sphere;

MeshInput input_of(const TestMesh& m)
{
  MeshInput in;
  in.points = m.points;
  in.triangles = m.triangles;
  in.normals = m.normals;
  return in;
}

double alpha_sum(const imaging::Image& image)
{
  double sum = 0.0;
  for (std::size_t i = 3; i < image.rgba.size(); i += 4)
  {
    sum += image.rgba[i];
  }
  return sum;
}

double luminance(const imaging::Image& image, int x, int y)
{
  const imaging::Rgba c = image.at(x, y);
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

// The projected radius (pixels) of a sphere of radius r whose centre is on the view axis at
// distance d: its outline subtends asin(r / d).
double projected_radius(const imaging::Camera& camera, int height, double r, double d)
{
  const double f = 0.5 * height / std::tan(0.5 * camera.view_angle_deg * std::numbers::pi / 180.0);
  return f * std::tan(std::asin(r / d));
}

double distance(const imaging::Vec3& a, const imaging::Vec3& b)
{
  return std::sqrt(
    (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(MeshRenderer, SphereCoversItsProjectedDisc)
{
  const TestMesh sphere = uv_sphere(160, 80);
  for (const int supersample : { 1, 2, 3 })
  {
    imaging::Image image(320, 240);
    const imaging::Camera camera =
      imaging::fit_box({ -1, -1, -1 }, { 1, 1, 1 }, 320.0 / 240.0, 30.0, 20.0);
    imaging::RenderStyle style;
    style.supersample = supersample;
    const RenderReport report = render_mesh(image, camera, input_of(sphere), style);
    ASSERT_TRUE(report.ok()) << report.error;
    EXPECT_EQ(report.triangles_skipped, 0U);
    const double r =
      projected_radius(camera, 240, 1.0, distance(camera.position, camera.focal_point));
    const double expected = std::numbers::pi * r * r;
    EXPECT_NEAR(alpha_sum(image) / expected, 1.0, 0.015) << "supersample " << supersample;
    // Centred: the coverage's centroid is the picture's centre.
    double mx = 0, my = 0, m = 0;
    for (int y = 0; y < 240; ++y)
    {
      for (int x = 0; x < 320; ++x)
      {
        const double a = image.at(x, y).a;
        mx += a * (x + 0.5), my += a * (y + 0.5), m += a;
      }
    }
    EXPECT_NEAR(mx / m, 160.0, 0.5);
    EXPECT_NEAR(my / m, 120.0, 0.5);
  }
}

TEST(MeshRenderer, OrthographicSphereArea)
{
  const TestMesh sphere = uv_sphere(160, 80);
  imaging::Image image(300, 200);
  imaging::FitOptions fit;
  fit.orthographic = true;
  const imaging::Camera camera =
    imaging::fit_box({ -1, -1, -1 }, { 1, 1, 1 }, 1.5, -40.0, 35.0, fit);
  ASSERT_TRUE(render_mesh(image, camera, input_of(sphere)).ok());
  const double r = 1.0 / camera.parallel_scale * 100.0; // world units -> pixels
  EXPECT_NEAR(alpha_sum(image) / (std::numbers::pi * r * r), 1.0, 0.015);
}

TEST(MeshRenderer, SphereCentreIsBrighterThanItsLimb)
{
  const TestMesh sphere = uv_sphere(96, 48);
  imaging::Image image(200, 200);
  const imaging::Camera camera = imaging::fit_box({ -1, -1, -1 }, { 1, 1, 1 }, 1.0, 0.0, 0.0);
  ASSERT_TRUE(render_mesh(image, camera, input_of(sphere)).ok());
  const double r =
    projected_radius(camera, 200, 1.0, distance(camera.position, camera.focal_point));
  double centre = 0, limb = 0;
  int nc = 0, nl = 0;
  for (int y = 0; y < 200; ++y)
  {
    for (int x = 0; x < 200; ++x)
    {
      const double d = std::hypot(x + 0.5 - 100, y + 0.5 - 100) / r;
      if (d < 0.25)
      {
        centre += luminance(image, x, y), ++nc;
      }
      else if (d > 0.85 && d < 0.95)
      {
        limb += luminance(image, x, y), ++nl;
      }
    }
  }
  ASSERT_GT(nc, 50);
  ASSERT_GT(nl, 50);
  EXPECT_GT(centre / nc, 1.3 * (limb / nl));
  // The key light is at the upper left: that side of the disc is brighter than the lower right.
  const int o = static_cast<int>(0.6 * r / std::sqrt(2.0));
  EXPECT_GT(luminance(image, 100 - o, 100 - o), luminance(image, 100 + o, 100 + o));
}

TEST(MeshRenderer, NoNormalsGivesSmoothShadingToo)
{
  // Computed area-weighted normals approximate the analytic ones: the pictures nearly agree.
  const TestMesh with = uv_sphere(96, 48);
  TestMesh without = with;
  without.normals.clear();
  const imaging::Camera camera = imaging::fit_box({ -1, -1, -1 }, { 1, 1, 1 }, 1.0, 10.0, 10.0);
  imaging::Image a(160, 160), b(160, 160);
  ASSERT_TRUE(render_mesh(a, camera, input_of(with)).ok());
  ASSERT_TRUE(render_mesh(b, camera, input_of(without)).ok());
  double worst = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
  {
    worst = std::max(worst, static_cast<double>(std::abs(a.rgba[i] - b.rgba[i])));
  }
  EXPECT_LT(worst, 0.03);
}

TEST(MeshRenderer, TriangleBehindTheCameraDrawsNothing)
{
  imaging::Camera camera; // at (0, -5, 0) looking along +y
  MeshInput in;
  const std::vector<double> behind = { -1, -8, -1, 1, -8, -1, 0, -8, 1 };
  const std::vector<std::uint32_t> tri = { 0, 1, 2 };
  in.points = behind;
  in.triangles = tri;
  imaging::Image image(64, 64);
  const RenderReport report = render_mesh(image, camera, in);
  EXPECT_TRUE(report.ok());
  EXPECT_EQ(alpha_sum(image), 0.0);

  // One crossing the eye's plane: clipped, what is in front is drawn, no crash.
  const std::vector<double> crossing = { -1, -8, -0.2, 1, -8, -0.2, 0, 3, 0.2 };
  in.points = crossing;
  imaging::Image clipped(64, 64);
  const RenderReport r2 = render_mesh(clipped, camera, in);
  EXPECT_TRUE(r2.ok());
  EXPECT_EQ(r2.triangles_clipped, 1U);
  EXPECT_GT(alpha_sum(clipped), 10.0);
}

TEST(MeshRenderer, DepthBufferHidesTheFartherSquare)
{
  const imaging::Camera camera; // looks along +y from y = -5
  const TestMesh red = test::square_y(0.0, 0.0, 0.0, 0.5);
  const TestMesh blue = test::square_y(1.0, 0.4, 0.0, 0.8); // bigger, farther, to the right
  for (const bool red_first : { true, false })
  {
    imaging::Image image(120, 120, { 0, 0, 0, 1 });
    imaging::RenderStyle matte; // no white highlight: colours stay pure
    matte.specular = 0.0;
    Renderer renderer(120, 120, camera, matte);
    MeshInput r = input_of(red), b = input_of(blue);
    r.colour = { 1, 0, 0 };
    b.colour = { 0, 0, 1 };
    if (red_first)
    {
      renderer.add(r);
      renderer.add(b);
    }
    else
    {
      renderer.add(b);
      renderer.add(r);
    }
    ASSERT_EQ(renderer.resolve(image), "");
    const imaging::Rgba centre = image.at(60, 60);
    EXPECT_GT(centre.r, 0.2F);
    EXPECT_EQ(centre.b, 0.0F) << "red first: " << red_first;
    // Right of the red square only the blue one is there.
    const imaging::Rgba right = image.at(95, 60);
    EXPECT_GT(right.b, 0.2F);
    EXPECT_EQ(right.r, 0.0F);
  }
}

TEST(MeshRenderer, TransparentMeshBlendsOverOpaqueOnly)
{
  const imaging::Camera camera;
  const TestMesh front = test::square_y(0.0, 0.0, 0.0, 0.5);
  const TestMesh back = test::square_y(1.0, 0.0, 0.0, 0.5);
  MeshInput f = input_of(front), b = input_of(back);
  f.colour = { 1, 0, 0 };
  f.opacity = 0.5;
  b.colour = { 0, 0, 1 };
  imaging::Image image(100, 100, { 0, 0, 0, 1 });
  Renderer renderer(100, 100, camera);
  renderer.add(f);
  renderer.add(b);
  ASSERT_EQ(renderer.resolve(image), "");
  const imaging::Rgba c = image.at(50, 50);
  EXPECT_GT(c.r, 0.1F);
  EXPECT_GT(c.b, 0.1F);
  EXPECT_NEAR(c.r / c.b, 1.0, 0.05); // same shading, half each
  // A transparent square behind an opaque one is hidden.
  f.opacity = 1.0;
  b.opacity = 0.5;
  imaging::Image hidden(100, 100, { 0, 0, 0, 1 });
  imaging::RenderStyle matte;
  matte.specular = 0.0;
  Renderer r2(100, 100, camera, matte);
  r2.add(b);
  r2.add(f);
  ASSERT_EQ(r2.resolve(hidden), "");
  EXPECT_EQ(hidden.at(50, 50).b, 0.0F);
}

TEST(MeshRenderer, SamePictureWithOneOrTwoThreads)
{
  const TestMesh sphere = uv_sphere(200, 100, 1.0, 0, 0, 0, 0.08, false);
  const TestMesh shell = uv_sphere(64, 32, 1.4, 0.3, 0, 0);
  const imaging::Camera camera =
    imaging::fit_box({ -1.5, -1.5, -1.5 }, { 1.5, 1.5, 1.5 }, 1.5, 35.0, 25.0);
  imaging::Image pictures[2];
  for (const int threads : { 1, 2 })
  {
    imaging::RenderStyle style;
    style.threads = threads;
    style.supersample = 3;
    imaging::Image image(240, 160, { 1, 1, 1, 1 });
    Renderer renderer(240, 160, camera, style);
    MeshInput a = input_of(sphere);
    a.colours = sphere.colours;
    MeshInput b = input_of(shell);
    b.opacity = 0.35;
    renderer.add(a);
    renderer.add(b);
    ASSERT_EQ(renderer.resolve(image), "");
    pictures[threads - 1] = std::move(image);
  }
  EXPECT_TRUE(pictures[0].rgba == pictures[1].rgba);
}

TEST(MeshRenderer, TransformMovesPointsAndNormals)
{
  const TestMesh sphere = uv_sphere(64, 32);
  const imaging::Camera camera; // looks along +y from y = -5; the picture's right is +x
  MeshInput in = input_of(sphere);
  // Scale by 0.5 and move 0.5 to the right: the disc's centroid moves right, its area shrinks
  // about 4x (perspective: (0.5 / sqrt(24.75))^2 / (1 / sqrt(24))^2 = 0.2424 on the axis).
  in.transform = std::array<double, 16>{ 0.5, 0, 0, 0.5, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1 };
  imaging::Image moved(200, 200), plain(200, 200);
  ASSERT_TRUE(render_mesh(moved, camera, in).ok());
  ASSERT_TRUE(render_mesh(plain, camera, input_of(sphere)).ok());
  double mx = 0, m = 0;
  for (int y = 0; y < 200; ++y)
  {
    for (int x = 0; x < 200; ++x)
    {
      mx += moved.at(x, y).a * (x + 0.5), m += moved.at(x, y).a;
    }
  }
  EXPECT_NEAR(mx / m, 100.0 + 0.5 / 5.0 * 100.0 / std::tan(std::numbers::pi / 12.0), 1.0);
  EXPECT_NEAR(alpha_sum(moved) / alpha_sum(plain), 0.2424, 0.01);
  // A mirror (det < 0) keeps normals outward: the picture is still lit like a sphere.
  in.transform = std::array<double, 16>{ -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  imaging::Image mirrored(200, 200);
  ASSERT_TRUE(render_mesh(mirrored, camera, in).ok());
  EXPECT_GT(luminance(mirrored, 100, 100), luminance(mirrored, 100, 100 + 40) * 0.9);
  EXPECT_GT(luminance(mirrored, 100, 100), 0.3);
}

TEST(MeshRenderer, InsideOutMeshIsStillShaded)
{
  // Flipped winding and flipped normals: seen from outside these are back faces, shaded with the
  // flipped normal (a little darker), not black.
  TestMesh sphere = uv_sphere(64, 32);
  for (std::size_t t = 0; t < sphere.triangles.size(); t += 3)
  {
    std::swap(sphere.triangles[t + 1], sphere.triangles[t + 2]);
  }
  for (float& n : sphere.normals)
  {
    n = -n;
  }
  const imaging::Camera camera = imaging::fit_box({ -1, -1, -1 }, { 1, 1, 1 }, 1.0, 0.0, 0.0);
  imaging::Image inverted(100, 100), normal(100, 100);
  ASSERT_TRUE(render_mesh(inverted, camera, input_of(sphere)).ok());
  ASSERT_TRUE(render_mesh(normal, camera, input_of(uv_sphere(64, 32))).ok());
  const double li = luminance(inverted, 50, 50), ln = luminance(normal, 50, 50);
  EXPECT_GT(li, 0.5 * ln);
  EXPECT_LT(li, ln);
}

TEST(MeshRenderer, BadInputNeverCrashes)
{
  const imaging::Camera camera;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> points = {
    -1, 0, -1, 1, 0, -1, 0, 0, 1, nan, 0, 0, inf, 0, 0, 0, 0, 0
  };
  // A good triangle, ones with a NaN or infinite point, a degenerate one, bad ids.
  const std::vector<std::uint32_t> triangles = {
    0, 1, 2, 0, 1, 3, 4, 1, 2, 0, 0, 1, 0, 1, 99, 7, 8, 9
  };
  MeshInput in;
  in.points = points;
  in.triangles = triangles;
  imaging::Image image(50, 50);
  const RenderReport report = render_mesh(image, camera, in);
  EXPECT_TRUE(report.ok()) << report.error;
  EXPECT_EQ(report.triangles, 6U);
  EXPECT_EQ(report.triangles_skipped, 5U);
  EXPECT_GT(alpha_sum(image), 10.0);

  // Empty meshes and a wrong-sized array: no picture change, an error for the latter.
  imaging::Image untouched(50, 50);
  EXPECT_TRUE(render_mesh(untouched, camera, MeshInput{}).ok());
  const std::vector<double> ragged = { 0, 0 };
  MeshInput bad;
  bad.points = ragged;
  EXPECT_FALSE(render_mesh(untouched, camera, bad).ok());
  const std::vector<float> short_normals = { 0, 0, 1 };
  in.normals = short_normals;
  EXPECT_FALSE(render_mesh(untouched, camera, in).ok());
  EXPECT_EQ(alpha_sum(untouched), 0.0);

  // A zero-sized target and a mismatched resolve.
  imaging::Image none;
  in.normals = {};
  EXPECT_TRUE(render_mesh(none, camera, in).ok());
  Renderer renderer(10, 10, camera);
  imaging::Image wrong(11, 10);
  EXPECT_NE(renderer.resolve(wrong), "");

  // Points far beyond the view (guard band clipping) and a camera inside the mesh.
  const std::vector<double> huge = { -1e12, 1, -1e12, 1e12, 1, -1e12, 0, 1, 1e12 };
  in.points = huge;
  in.triangles = std::span<const std::uint32_t>(triangles.data(), 3);
  imaging::Image big(64, 64);
  const RenderReport r3 = render_mesh(big, camera, in);
  EXPECT_TRUE(r3.ok());
  EXPECT_NEAR(alpha_sum(big), 64.0 * 64.0, 1.0); // it fills the view
}

TEST(MeshRenderer, NoCracksBetweenTriangles)
{
  // A finely tessellated square facing the camera: every sample inside it is covered exactly
  // (opaque), none blended twice (a fan of long thin triangles is the hard case).
  std::vector<double> points = { 0.0, 0.0, 0.0 };
  std::vector<std::uint32_t> triangles;
  const int n = 257;
  for (int i = 0; i <= n; ++i)
  {
    const double a = 2.0 * std::numbers::pi * i / n;
    points.insert(points.end(), { std::cos(a) * 3.0, 0.0, std::sin(a) * 3.0 });
    if (i > 0)
    {
      triangles.insert(
        triangles.end(), { 0, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1) });
    }
  }
  triangles.resize(triangles.size() - 3);
  triangles.insert(triangles.end(), { 0, static_cast<std::uint32_t>(n), 1 });
  MeshInput in;
  in.points = points;
  in.triangles = triangles;
  const imaging::Camera camera;
  imaging::RenderStyle style;
  style.supersample = 1;
  imaging::Image image(64, 64);
  ASSERT_TRUE(render_mesh(image, camera, in, style).ok());
  for (int y = 8; y < 56; ++y)
  {
    for (int x = 8; x < 56; ++x)
    {
      ASSERT_EQ(image.at(x, y).a, 1.0F) << x << ", " << y;
    }
  }
}

} // namespace
} // namespace frep::render
