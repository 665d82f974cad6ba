// Pictures for a human to look at (FREPKIT_RENDER_CHECK_DIR=dir writes dir/*.ppm): a shaded
// sphere, an animation-like frame with the path inset, the standalone path picture, and text.
// The assertions here are only that each picture was made and has content where expected.
#include "Imaging/camera.h"
#include "Render/mesh_renderer.h"
#include "Render/plot2d.h"
#include "test_meshes.h"
#include "Render/text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace frep::render
{
namespace
{

using test::save_picture;

// The path of a made-up animation through the (x4, x5) plane: a Lissajous-like loop.
std::vector<Point2> demo_path(int frames)
{
  std::vector<Point2> path;
  for (int i = 0; i < frames; ++i)
  {
    const double t = 2.0 * std::numbers::pi * i / (frames - 1);
    path.push_back({ 0.5 + 0.38 * std::sin(t), 0.5 + 0.3 * std::sin(2.0 * t + 0.4) });
  }
  return path;
}

TEST(Pictures, SphereAndFrame)
{
  Font::LoadResult font = Font::load_default();
  ASSERT_TRUE(font.ok()) << font.error;

  const test::TestMesh smooth = test::uv_sphere(256, 128, 1.0, 0, 0, 0);
  imaging::Image sphere(480, 360, imaging::srgb_hex(0xffffff));
  const imaging::Camera camera =
    imaging::fit_box({ -1, -1, -1 }, { 1, 1, 1 }, 480.0 / 360.0, 30.0, 20.0);
  MeshInput in;
  in.points = smooth.points;
  in.triangles = smooth.triangles;
  in.normals = smooth.normals;
  in.colour = {
    imaging::srgb_hex(0x8fb3d9).r, imaging::srgb_hex(0x8fb3d9).g, imaging::srgb_hex(0x8fb3d9).b
  };
  ASSERT_TRUE(render_mesh(sphere, camera, in).ok());
  EXPECT_EQ(save_picture(sphere, "sphere"), "");

  // A 1280 x 720 frame: a bumpy coloured shape in a translucent shell, caption, inset.
  const test::TestMesh bumpy = test::uv_sphere(400, 200, 1.0, 0, 0, 0, 0.12, false);
  const test::TestMesh shell = test::uv_sphere(128, 64, 1.45, 0, 0, 0);
  imaging::Image frame(1280, 720, imaging::srgb_hex(0xf7f7f5));
  const imaging::Camera wide =
    imaging::fit_box({ -1.5, -1.5, -1.5 }, { 1.5, 1.5, 1.5 }, 1280.0 / 720.0, 35.0, 25.0);
  Renderer renderer(1280, 720, wide);
  MeshInput shape;
  shape.points = bumpy.points;
  shape.triangles = bumpy.triangles;
  shape.colours = bumpy.colours;
  ASSERT_TRUE(renderer.add(shape).ok());
  MeshInput glass;
  glass.points = shell.points;
  glass.triangles = shell.triangles;
  glass.normals = shell.normals;
  glass.colour = { 0.9F, 0.9F, 1.0F };
  glass.opacity = 0.25;
  ASSERT_TRUE(renderer.add(glass).ok());
  ASSERT_EQ(renderer.resolve(frame), "");
  const std::vector<Point2> path = demo_path(60);
  CheckerboardInset inset;
  inset.rect = { 1280 - 24 - 240, 720 - 24 - 240, 1280 - 24, 720 - 24 };
  inset.path = path;
  inset.past_points = 23;
  inset.current = path[23];
  draw_checkerboard_inset(frame, inset, &*font.font);
  font.font->draw(frame,
    24,
    24,
    "x\xE2\x82\x84 = 0.412   x\xE2\x82\x85 = 0.773   frame 23 / 59",
    22,
    imaging::srgb_hex(0x222222),
    { HAlign::Left, VAlign::Top });
  EXPECT_EQ(save_picture(frame, "frame"), "");
  // The shape is in the middle, the inset at the bottom right.
  EXPECT_NE(frame.at(640, 360).r, imaging::srgb_hex(0xf7f7f5).r);
  EXPECT_NEAR(frame.at(1280 - 24 - 120, 720 - 24 - 4).r,
    inset.background.r * inset.background.a +
      imaging::srgb_hex(0xf7f7f5).r * (1 - inset.background.a),
    0.02);

  // The standalone path picture: every frame's point marked.
  imaging::Image big(800, 800, { 1, 1, 1, 1 });
  CheckerboardInset whole;
  whole.rect = { 0, 0, 800, 800 };
  whole.path = path;
  whole.markers = path;
  whole.squares_u = whole.squares_v = 5;
  whole.background = { 1, 1, 1, 1 };
  draw_checkerboard_inset(big, whole, &*font.font);
  EXPECT_EQ(save_picture(big, "path"), "");
}

TEST(Pictures, OpenSurfaceShowsItsInside)
{
  // A sphere cut open at the top, seen from above: the inside (back faces) is shaded with the
  // flipped normal, a little darker, and nothing is black.
  test::TestMesh bowl = test::uv_sphere(192, 96);
  std::vector<std::uint32_t> kept;
  for (std::size_t t = 0; t < bowl.triangles.size(); t += 3)
  {
    const double z = bowl.points[3 * bowl.triangles[t] + 2];
    if (z < 0.35)
    {
      kept.insert(kept.end(), bowl.triangles.begin() + t, bowl.triangles.begin() + t + 3);
    }
  }
  MeshInput in;
  in.points = bowl.points;
  in.triangles = kept;
  in.normals = bowl.normals;
  in.colour = {
    imaging::srgb_hex(0xe0b070).r, imaging::srgb_hex(0xe0b070).g, imaging::srgb_hex(0xe0b070).b
  };
  imaging::Image image(480, 360, { 1, 1, 1, 1 });
  const imaging::Camera camera =
    imaging::fit_box({ -1, -1, -1 }, { 1, 1, 1 }, 480.0 / 360.0, 20.0, 55.0);
  imaging::RenderStyle style;
  style.supersample = 3;
  ASSERT_TRUE(render_mesh(image, camera, in, style).ok());
  EXPECT_EQ(save_picture(image, "open_bowl"), "");
  // The centre of the picture looks into the bowl: lit, not black.
  const imaging::Rgba c = image.at(240, 180);
  EXPECT_GT(c.r, 0.15F);
}

TEST(Pictures, Text)
{
  Font::LoadResult font = Font::load_default();
  ASSERT_TRUE(font.ok()) << font.error;
  imaging::Image image(640, 260, { 1, 1, 1, 1 });
  const imaging::Rgba ink = imaging::srgb_hex(0x1a1a1a);
  double y = 16;
  for (const double px : { 11.0, 14.0, 18.0, 24.0, 36.0 })
  {
    const TextLayout l = font.font->draw(image,
      16,
      y,
      "x\xE2\x82\x84 \xE2\x88\x88 [\xE2\x88\x92"
      "1, 1] \xC3\x97 x\xE2\x82\x85 \xE2\x89\xA4 0.25\xE2\x80\xA6 Caf\xC3\xA9",
      px,
      ink,
      { HAlign::Left, VAlign::Top });
    EXPECT_FALSE(l.ink.empty());
    y = l.box.y1 + 8;
  }
  imaging::Image dark(640, 80, imaging::srgb_hex(0x202124));
  font.font->draw(dark,
    320,
    40,
    "Centred, middle: light on dark",
    24,
    { 1, 1, 1, 1 },
    { HAlign::Centre, VAlign::Middle });
  imaging::composite_over(image, dark, 0, 180);
  EXPECT_EQ(save_picture(image, "text"), "");
}

} // namespace
} // namespace frep::render
