// The floor scene (Fig. 8): every frame's section stands on the board. A 5-D ball whose radius
// grows with the two dynamic coordinates, in a box larger than the ball: on_floor alone leaves
// the ball (2 - r) above the board (the box's bottom is on it); stand_on_floor puts the lowest
// point of the meshed section (its lowest vertex) and of the ray-cast solid (raycast::lowest_z)
// on the board, the gap left well under a pixel of the scene's camera at the contact point.
#include "Mapping/mapping_json.h"
#include "Mapping/mapping_plan.h"
#include "Scene/floor_scene.h"
#include "Scene/section_mesh.h"
#include "Scene/section_raycast.h"

#include "Compiler/model.h"
#include "Language/ast.h"
#include "Language/parser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

namespace
{

namespace mapping = frep::mapping;

const char* const Ball5 = R"(
my_model(x[5], a[1])
{
  r = 0.6 + 0.5 * x[4] + 0.3 * x[5];
  my_model = r * r - x[1] * x[1] - x[2] * x[2] - x[3] * x[3];
}
)";

// The mapping of Testing/Apps/frepkit_render_test.sh's floor scene: world box [-2, 2]^3.
const char* const FloorMapping = R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.5 },
           { "type": "dynamic", "range": [0, 1] }],
    "x5": [{ "type": "spreadsheet", "axis": "rows", "range": [0, 1], "step": 0.5 },
           { "type": "dynamic", "range": [0, 1] }] },
  "world": { "system": "cartesian", "resolution": 64 },
  "animation": { "duration": 1, "fps": 3,
                 "path": { "coordinates": ["x4", "x5"], "points": [[0, 0], [1, 0], [1, 1]] } },
  "render": { "width": 320, "height": 180, "scene": "floor" } })";

struct Fixture
{
  std::shared_ptr<const frep::Model> model;
  mapping::Spec spec;
  mapping::Plan plan;
};

Fixture make_fixture()
{
  Fixture f;
  const frep::ParseResult parsed = frep::parse_program(Ball5, "<test>");
  EXPECT_TRUE(parsed.ok());
  f.model = frep::Model::compile(parsed.program, frep::ast::select_default_object(*parsed.program))
              .model;
  const mapping::LoadResult loaded = mapping::load_mapping(FloorMapping);
  EXPECT_TRUE(loaded.errors.empty()) << mapping::format_errors(loaded.errors);
  f.spec = loaded.spec;
  mapping::ModelCoordinates coordinates;
  for (int i = 0; i < 5; ++i)
  {
    coordinates.names.push_back("x" + std::to_string(i + 1));
    coordinates.intervals.push_back({ i < 3 ? -2.0 : 0.0, i < 3 ? 2.0 : 1.0 });
  }
  mapping::PlanResult planned = mapping::make_plan(f.spec, coordinates);
  EXPECT_TRUE(planned.ok()) << mapping::format_errors(planned.errors);
  f.plan = planned.plan;
  return f;
}

double radius_of(const mapping::Sample& frame)
{
  return 0.6 + 0.5 * frame.values[3] + 0.3 * frame.values[4];
}

double lowest_vertex(const mapping::Section& s)
{
  double z = std::numeric_limits<double>::infinity();
  for (std::size_t i = 2; i < s.surface.points.size(); i += 3)
  {
    z = std::min(z, s.surface.points[i]);
  }
  return z;
}

// The world size of one picture row at distance `d` along the scene camera's view.
double pixel_at(const mapping::FloorScene& scene, double d, int height)
{
  return 2.0 * d * std::tan(0.5 * scene.camera.view_angle_deg * std::numbers::pi / 180.0) / height;
}

double distance_to(const mapping::FloorScene& scene, const std::array<double, 3>& p)
{
  return std::hypot(p[0] - scene.camera.position[0], p[1] - scene.camera.position[1],
    p[2] - scene.camera.position[2]);
}

} // namespace

TEST(FloorScene, MeshedSectionStandsOnTheBoard)
{
  const Fixture f = make_fixture();
  ASSERT_TRUE(f.model);
  const mapping::FloorScene scene = mapping::make_floor_scene(f.plan, f.spec, 320.0 / 180.0);
  ASSERT_TRUE(scene.ok);
  ASSERT_EQ(f.plan.frames.size(), 3u);
  for (const mapping::Sample& frame : f.plan.frames)
  {
    const mapping::Sample placed = mapping::on_floor(scene, frame);
    mapping::Section s = mapping::make_section(*f.model, {}, f.plan, placed);
    ASSERT_TRUE(s.ok()) << s.error;
    const double r = radius_of(frame);
    // Before: the box's bottom is on the board, the ball's bottom 2 - r above it (to a cell).
    const double gap_before = lowest_vertex(s) - scene.floor.height;
    EXPECT_NEAR(gap_before, 2.0 - r, 4.0 / 63) << frame.label;
    const double moved = mapping::stand_on_floor(s, scene.floor);
    EXPECT_DOUBLE_EQ(moved, -gap_before);
    EXPECT_NEAR(lowest_vertex(s), scene.floor.height, 1e-12) << frame.label;
  }
}

TEST(FloorScene, RayCastSolidStandsOnTheBoardWithinAPixel)
{
  const Fixture f = make_fixture();
  ASSERT_TRUE(f.model);
  const int height = f.spec.render.height;
  const mapping::FloorScene scene =
    mapping::make_floor_scene(f.plan, f.spec, static_cast<double>(f.spec.render.width) / height);
  ASSERT_TRUE(scene.ok);
  for (const mapping::Sample& frame : f.plan.frames)
  {
    const mapping::Sample placed = mapping::on_floor(scene, frame);
    const mapping::Sample standing =
      mapping::stand_on_floor(*f.model, {}, f.plan, placed, scene.floor, 2);
    const double r = radius_of(frame);
    // The translation added: down by the ball's height above the box's bottom.
    EXPECT_NEAR(standing.transform[11] - placed.transform[11], -(2.0 - r), 1e-4) << frame.label;
    // The solid as raycast_sample draws it: its lowest point against the board, in pixels.
    frep::raycast::Shape shape;
    shape.tape = f.model->specialise(mapping::section_specialisation(f.plan, standing, {}));
    for (int k = 0; k < 3; ++k)
    {
      shape.box[k] = frep::Interval{ f.plan.model_box[k].lo, f.plan.model_box[k].hi };
    }
    shape.to_world = mapping::raycast_world_map(f.plan, standing);
    const std::optional<double> lowest = frep::raycast::lowest_z(shape);
    ASSERT_TRUE(lowest);
    const std::array<double, 3> contact{ shape.to_world[3], shape.to_world[7], *lowest };
    const double pixel = pixel_at(scene, distance_to(scene, contact), height);
    const double gap = *lowest - scene.floor.height;
    std::cout << frame.label << ": r = " << r << ", gap " << gap << " (a pixel there: " << pixel
              << ")\n";
    EXPECT_LE(std::abs(gap), 0.01 * pixel) << frame.label;
  }
}
