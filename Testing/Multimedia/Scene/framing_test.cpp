// What the mapping's pictures frame (Scene/framing.h): a unit ball in the model box [-10, 10]^3
// is bounded to about +-1 (not the box); frame_solids frames that for every cell and frame, and
// then a spreadsheet cell and an animation frame, meshed or ray-cast, show the ball over at
// least half of the picture's width or height (the model box's camera left it a few pixels
// wide, and its box's corners about half: both checked too, so the measure can fail); a user's
// view_box wins; no solid leaves the world box; a translation channel widens the box to every
// place the shape goes; a cylindrical world (no rays) is framed by its solid's box; a 2-D
// section's contour is framed too; the floor scene's board is sized by the ball, which stands
// on it in the picture.
#include "Mapping/mapping_json.h"
#include "Mapping/mapping_plan.h"
#include "Scene/floor_scene.h"
#include "Scene/framing.h"
#include "Scene/pictures.h"
#include "Scene/section_mesh.h"
#include "Scene/section_raycast.h"

#include "Eval/thread_pool.h"
#include "Compiler/model.h"
#include "Language/ast.h"
#include "Language/parser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace
{

namespace mapping = frep::mapping;

std::shared_ptr<const frep::Model> compile(const std::string& text)
{
  const frep::ParseResult parsed = frep::parse_program(text, "<test>");
  EXPECT_TRUE(parsed.ok());
  return frep::Model::compile(parsed.program, frep::ast::select_default_object(*parsed.program))
    .model;
}

// A unit ball whatever x4 is.
const char* const Ball4 = "my_model(x[4], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }";

// x1..x3 on the world's axes over -10..10 (the default box of a model), x4 on the columns and
// in time. `extra` goes into x4's channels.
std::string ball_mapping(const std::string& extra = "", const std::string& render = "")
{
  return R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-10, 10] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-10, 10] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-10, 10] }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.5 },
           { "type": "dynamic", "range": [0, 1] })" +
         extra + R"(] },
  "world": { "resolution": 48 },
  "animation": { "duration": 1, "fps": 3 },
  "render": { "width": 160, "height": 120, "inset": false)" +
         render + " } }";
}

struct Mapped
{
  std::shared_ptr<const frep::Model> model;
  mapping::Spec spec;
  mapping::Plan plan;
};

Mapped map(const char* model, const std::string& json, int dimension = 4)
{
  Mapped m;
  m.model = compile(model);
  const mapping::LoadResult loaded = mapping::load_mapping(json);
  EXPECT_TRUE(loaded.errors.empty()) << mapping::format_errors(loaded.errors);
  m.spec = loaded.spec;
  mapping::ModelCoordinates coordinates;
  for (int i = 0; i < dimension; ++i)
  {
    coordinates.names.push_back("x" + std::to_string(i + 1));
    coordinates.intervals.push_back({ -10.0, 10.0 });
  }
  mapping::PlanResult planned = mapping::make_plan(m.spec, coordinates);
  EXPECT_TRUE(planned.ok()) << mapping::format_errors(planned.errors);
  m.plan = planned.plan;
  return m;
}

// The bounding box of the pixels unlike the top-left one (the background), as fractions of the
// picture's width and height.
std::array<double, 2> foreground_extent(const frep::imaging::Image& image)
{
  const float* bg = image.pixel(0, 0);
  int x0 = image.width, x1 = -1, y0 = image.height, y1 = -1;
  for (int y = 0; y < image.height; ++y)
  {
    for (int x = 0; x < image.width; ++x)
    {
      const float* p = image.pixel(x, y);
      if (std::max({ std::abs(p[0] - bg[0]), std::abs(p[1] - bg[1]), std::abs(p[2] - bg[2]) }) >
          0.03F)
      {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
    }
  }
  if (x1 < 0)
  {
    return { 0.0, 0.0 };
  }
  return { (x1 - x0 + 1.0) / image.width, (y1 - y0 + 1.0) / image.height };
}

// The issue's measure of a well-framed picture.
bool fills_half(const std::array<double, 2>& extent)
{
  return extent[0] >= 0.5 || extent[1] >= 0.5;
}

// A cell's picture (plan_camera) or, with `frame`, an animation frame's (frame_camera).
frep::imaging::Image meshed(const Mapped& m,
  const mapping::Framing& framing,
  const mapping::Sample& sample,
  int width,
  int height,
  const mapping::RenderSettings* settings = nullptr,
  bool frame = false)
{
  const mapping::RenderSettings& rs = settings ? *settings : m.spec.render;
  const mapping::Section s = mapping::make_section(*m.model, {}, m.plan, sample);
  EXPECT_TRUE(s.ok()) << s.error;
  const frep::imaging::Camera camera =
    frame ? mapping::frame_camera(m.plan, rs, width, height, framing)
          : mapping::plan_camera(m.plan, rs, static_cast<double>(width) / height, framing);
  return mapping::render_sample(m.plan, s, sample, camera, width, height, rs, 1, nullptr, framing);
}

void expect_near_box(const std::array<mapping::Interval, 3>& box,
  const std::array<double, 6>& expected,
  double tolerance)
{
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(box[k].lo, expected[k], tolerance) << "axis " << k;
    EXPECT_NEAR(box[k].hi, expected[k + 3], tolerance) << "axis " << k;
  }
}

} // namespace

TEST(Framing, UnitBallIsBoundedNotTheModelBox)
{
  const Mapped m = map(Ball4, ball_mapping());
  ASSERT_TRUE(m.model);
  const auto box = mapping::solid_world_box(*m.model, {}, m.plan, m.plan.cells[0]);
  ASSERT_TRUE(box);
  for (int k = 0; k < 3; ++k)
  {
    // raycast::solid_bounds: to 1/256 of the box's 20 on each side, never inside the ball.
    EXPECT_LE((*box)[k].lo, -1.0);
    EXPECT_GE((*box)[k].lo, -1.0 - 2 * 20.0 / 256);
    EXPECT_GE((*box)[k].hi, 1.0);
    EXPECT_LE((*box)[k].hi, 1.0 + 2 * 20.0 / 256);
  }
}

TEST(Framing, FrameSolidsUnlessTheUserGaveAViewBox)
{
  const Mapped m = map(Ball4, ball_mapping());
  const mapping::Framing framing = mapping::frame_solids(m.spec.render, *m.model, {}, m.plan);
  ASSERT_TRUE(framing.box);
  expect_near_box(*framing.box, { -1, -1, -1, 1, 1, 1 }, 0.2);
  EXPECT_EQ(framing.outline.size(), 8u);
  for (const frep::imaging::Vec3& p : framing.outline) // the ball's extent across the view
  {
    EXPECT_LT(std::hypot(p[0], p[1], p[2]), 2.0);
  }
  expect_near_box(mapping::shown_box(m.plan, m.spec.render, framing), { -1, -1, -1, 1, 1, 1 }, 0.2);
  // The user's view_box wins: nothing framed, and it is the shown box.
  const Mapped given = map(Ball4, ball_mapping("", R"(, "view_box": [-3, -3, -3, 3, 3, 3])"));
  const mapping::Framing none =
    mapping::frame_solids(given.spec.render, *given.model, {}, given.plan);
  EXPECT_TRUE(none.empty() && none.outline.empty());
  expect_near_box(
    mapping::shown_box(given.plan, given.spec.render, framing), { -3, -3, -3, 3, 3, 3 }, 0);
  // Nothing in the box: the world box stays.
  const Mapped empty = map("my_model(x[4], a[1]) { my_model = -1; }", ball_mapping());
  const mapping::Framing nothing =
    mapping::frame_solids(empty.spec.render, *empty.model, {}, empty.plan);
  EXPECT_TRUE(nothing.empty());
  expect_near_box(
    mapping::shown_box(empty.plan, empty.spec.render, nothing), { -10, -10, -10, 10, 10, 10 }, 0);
}

// frame_solids is long work (a second for Meta5D's 25 cells): it reports the fraction of
// solids seen, on the calling thread, and stops when asked, framing nothing.
TEST(Framing, ReportsProgressAndStopsWhenAsked)
{
  const Mapped m = map(Ball4, ball_mapping());
  const std::size_t samples = 1 + m.plan.cells.size() + m.plan.frames.size();
  ASSERT_GT(samples, 3u);
  std::vector<double> fractions;
  frep::RunControl run;
  run.threads = 1;
  run.progress = [&](double f) { fractions.push_back(f); return true; };
  const mapping::Framing framing = mapping::frame_solids(m.spec.render, *m.model, {}, m.plan, run);
  EXPECT_FALSE(framing.cancelled);
  ASSERT_TRUE(framing.box);
  ASSERT_EQ(fractions.size(), samples);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);

  int polls = 0;
  run.progress = nullptr;
  run.cancel = [&] { return ++polls > 2; }; // stop at the third sample
  const mapping::Framing cancelled = mapping::frame_solids(m.spec.render, *m.model, {}, m.plan, run);
  EXPECT_TRUE(cancelled.cancelled);
  EXPECT_TRUE(cancelled.empty() && cancelled.outline.empty() && cancelled.solids.empty());

  run.cancel = nullptr;
  run.progress = [](double) { return false; }; // progress may stop it too
  run.pool = std::make_shared<frep::ThreadPool>(2);
  EXPECT_TRUE(mapping::frame_solids(m.spec.render, *m.model, {}, m.plan, run).cancelled);
}

TEST(Framing, CellAndFrameShowTheBallOverHalfThePicture)
{
  const Mapped m = map(Ball4, ball_mapping());
  const mapping::Framing framing = mapping::frame_solids(m.spec.render, *m.model, {}, m.plan);
  ASSERT_FALSE(m.plan.cells.empty());
  ASSERT_FALSE(m.plan.frames.empty());

  // A spreadsheet cell (square, meshed) and an animation frame (160 x 120, meshed and ray-cast).
  const auto cell = foreground_extent(meshed(m, framing, m.plan.cells[1], 96, 96));
  const frep::imaging::Image frame_picture =
    meshed(m, framing, m.plan.frames[1], 160, 120, nullptr, true);
  const auto frame = foreground_extent(frame_picture);
  const frep::imaging::Camera camera =
    mapping::frame_camera(m.plan, m.spec.render, 160, 120, framing);
  const mapping::RaycastPicture rays =
    mapping::raycast_sample(*m.model, {}, m.plan, m.plan.frames[1], camera, 160, 120);
  ASSERT_TRUE(rays.ok()) << rays.error;
  const auto raycast = foreground_extent(rays.image);
  // The model box's camera (no framing): the same ball a few pixels wide; the corners of the
  // solids' box (a view_box of it) leave it smaller than its outline does, seen obliquely.
  const auto unframed = foreground_extent(meshed(m, {}, m.plan.cells[1], 96, 96));
  mapping::RenderSettings boxed = m.spec.render;
  ASSERT_TRUE(framing.box);
  const std::array<mapping::Interval, 3>& b = *framing.box;
  boxed.view_box = std::array<double, 6>{ b[0].lo, b[1].lo, b[2].lo, b[0].hi, b[1].hi, b[2].hi };
  const auto corners = foreground_extent(meshed(m, {}, m.plan.cells[1], 96, 96, &boxed));
  std::cout << "ball's extent: cell " << cell[0] << " x " << cell[1] << ", frame " << frame[0]
            << " x " << frame[1] << ", ray-cast frame " << raycast[0] << " x " << raycast[1]
            << "; the model box's camera " << unframed[0] << " x " << unframed[1]
            << ", the solids' box's corners " << corners[0] << " x " << corners[1] << "\n";
  EXPECT_TRUE(fills_half(cell));
  EXPECT_TRUE(fills_half(frame));
  EXPECT_TRUE(fills_half(raycast));
  EXPECT_FALSE(fills_half(unframed));
  EXPECT_GT(unframed[0], 0.0);           // drawn, only small
  EXPECT_GT(cell[1], corners[1] + 0.05); // the outline frames tighter than the box's corners
  // The frame's caption band stays free (decorate_frame writes there).
  const int band = static_cast<int>(std::ceil(mapping::caption_band(120) * 120));
  for (const frep::imaging::Image* picture : { &frame_picture, &rays.image })
  {
    for (int y = 120 - band; y < 120; ++y)
    {
      for (int x = 0; x < 160; ++x)
      {
        ASSERT_EQ(picture->pixel(x, y)[0], picture->pixel(0, 0)[0]) << x << ", " << y;
      }
    }
  }
}

TEST(Framing, TheBoxFollowsTheShapesTransform)
{
  // x4 moves the ball 0..5 along x in the frames: the one camera sees it at both ends.
  const Mapped m = map(Ball4,
    ball_mapping(R"(, { "type": "transformation", "transform": "translate", "vector": [1, 0, 0],
                       "range": [0, 1], "target": [0, 5] })"));
  const mapping::Framing framing = mapping::frame_solids(m.spec.render, *m.model, {}, m.plan);
  ASSERT_TRUE(framing.box);
  expect_near_box(*framing.box, { -1, -1, -1, 6, 1, 1 }, 0.2);
  const frep::imaging::Image first = meshed(m, framing, m.plan.frames.front(), 160, 120);
  const frep::imaging::Image last = meshed(m, framing, m.plan.frames.back(), 160, 120);
  for (const frep::imaging::Image* picture : { &first, &last })
  {
    const auto extent = foreground_extent(*picture);
    EXPECT_GT(extent[0], 0.15);
    // Nothing at the picture's edges: the ball is inside at both ends of its way.
    for (int y = 0; y < 120; ++y)
    {
      EXPECT_EQ(picture->pixel(0, y)[0], picture->pixel(0, 0)[0]);
      EXPECT_EQ(picture->pixel(159, y)[0], picture->pixel(0, 0)[0]);
    }
  }
}

TEST(Framing, CylindricalWorldIsFramedByTheSolidsBox)
{
  // A slab r in [1.2, 1.8], |z| < 0.5, phi in [0.3, 2.8] in the model box r 0..10, phi 0..3.1:
  // no rays (the world bends), the box of its world image frames it.
  const char* slab = "my_model(x[3], a[1]) { my_model = ((x[1] - 1.2) & (1.8 - x[1])) & "
                     "((x[2] - 0.3) & (2.8 - x[2])) & (0.5 - abs(x[3])); }";
  const Mapped m = map(slab,
    R"({ "coordinates": {
      "x1": [{ "type": "world", "axis": "r", "range": [0, 10] }],
      "x2": [{ "type": "world", "axis": "phi", "range": [0, 3.1] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-10, 10] }] },
      "world": { "system": "cylindrical", "resolution": 64 } })",
    3);
  const mapping::Framing framing = mapping::frame_solids(m.spec.render, *m.model, {}, m.plan);
  ASSERT_TRUE(framing.box);
  // x from 1.8 cos 2.8 to 1.8 cos 0.3, y from 1.2 sin 0.3 to 1.8, z +-0.5 (to the bounds' cells).
  expect_near_box(*framing.box,
    { 1.8 * std::cos(2.8), 1.2 * std::sin(0.3), -0.5, 1.8 * std::cos(0.3), 1.8, 0.5 },
    0.15);
  const auto extent = foreground_extent(meshed(m, framing, m.plan.still, 160, 120));
  std::cout << "slab's extent: " << extent[0] << " x " << extent[1] << "\n";
  EXPECT_TRUE(fills_half(extent));
}

TEST(Framing, ContourOfATwoDimensionalSection)
{
  const char* disc = "my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2; }";
  const Mapped m = map(disc,
    R"({ "coordinates": {
      "x1": [{ "type": "world", "axis": "x", "range": [-10, 10] }],
      "x2": [{ "type": "world", "axis": "y", "range": [-10, 10] }],
      "x3": [{ "type": "spreadsheet", "axis": "columns", "values": [0, 1] }] },
      "world": { "resolution": 64 } })",
    3);
  const mapping::Framing framing = mapping::frame_solids(m.spec.render, *m.model, {}, m.plan);
  ASSERT_TRUE(framing.box);
  EXPECT_EQ((*framing.box)[2].lo, 0.0); // flat
  EXPECT_EQ((*framing.box)[2].hi, 0.0);
  const auto extent = foreground_extent(meshed(m, framing, m.plan.cells[0], 96, 96));
  const auto unframed = foreground_extent(meshed(m, {}, m.plan.cells[0], 96, 96));
  std::cout << "disc's extent: " << extent[0] << " x " << extent[1] << " (the model box's "
            << unframed[0] << " x " << unframed[1] << ")\n";
  EXPECT_TRUE(fills_half(extent));
  EXPECT_FALSE(fills_half(unframed));
}

TEST(Framing, FloorSceneBoardIsSizedByTheBallThatStandsOnIt)
{
  const Mapped m = map("my_model(x[5], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }",
    R"({ "coordinates": {
      "x1": [{ "type": "world", "axis": "x", "range": [-10, 10] }],
      "x2": [{ "type": "world", "axis": "y", "range": [-10, 10] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-10, 10] }],
      "x4": [{ "type": "dynamic", "range": [0, 1] }],
      "x5": [{ "type": "dynamic", "range": [0, 1] }] },
      "world": { "resolution": 48 },
      "animation": { "duration": 1, "fps": 3,
                     "path": { "coordinates": ["x4", "x5"], "points": [[0, 0], [1, 1]] } },
      "render": { "width": 160, "height": 120, "scene": "floor" } })",
    5);
  const mapping::Framing framing = mapping::frame_solids(m.spec.render, *m.model, {}, m.plan);
  const mapping::FloorScene scene =
    mapping::make_floor_scene(m.plan, m.spec, 160.0 / 120.0, framing);
  ASSERT_TRUE(scene.ok);
  // A square is 0.55 of the ball's box (about 2), not of the model box (20); the board is at
  // the bottom of the ball's box.
  EXPECT_NEAR(scene.floor.square, 0.55 * 2.0, 0.2);
  EXPECT_NEAR(scene.floor.height, -1.0, 0.1);
  const mapping::Sample frame = mapping::on_floor(scene, m.plan.frames[1]);
  mapping::Section s = mapping::make_section(*m.model, {}, m.plan, frame);
  ASSERT_TRUE(s.ok()) << s.error;
  mapping::stand_on_floor(s, scene.floor);
  const frep::imaging::Image picture = mapping::render_sample(
    m.plan, s, frame, scene.camera, 160, 120, m.spec.render, 1, &scene.floor);
  // The ball: the pixels of its colour (linear 0.69, 0.34, 0.12 shaded: not the grey board, nor
  // the red path blended with it), well inside the picture.
  int x0 = 160, x1 = -1, y0 = 120, y1 = -1;
  for (int y = 0; y < 120; ++y)
  {
    for (int x = 0; x < 160; ++x)
    {
      const float* p = picture.pixel(x, y);
      if (p[0] > 0.05F && p[1] >= 0.4F * p[0] && p[1] <= 0.7F * p[0] && p[2] <= 0.3F * p[0])
      {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    }
  }
  std::cout << "ball on the floor: x " << x0 << ".." << x1 << ", y " << y0 << ".." << y1 << "\n";
  ASSERT_GE(x1, 0);
  EXPECT_GT(x0, 0);
  EXPECT_LT(x1, 159);
  EXPECT_GT(y0, 0);
  EXPECT_LT(y1, 119);
  EXPECT_GE(y1 - y0 + 1, 120 / 10); // not a dot on a huge board (8 x 8 squares of 0.55 x 2)
}
