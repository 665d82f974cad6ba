#include "Mapping/mapping_json.h"
#include "Mapping/mapping_plan.h"

#include "example_mapping.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frep::mapping
{
namespace
{

using testing::example_mapping;

ModelCoordinates model(int n)
{
  ModelCoordinates m;
  for (int i = 1; i <= n; ++i)
  {
    m.names.push_back("x" + std::to_string(i));
    m.intervals.push_back({ -1, 1 });
  }
  return m;
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

PlanResult plan_of(const std::string& json, int dimension)
{
  const LoadResult loaded = load_mapping(json);
  EXPECT_TRUE(loaded.ok()) << format_errors(loaded.errors);
  return make_plan(loaded.spec, model(dimension));
}

bool has_error(const PlanResult& r, const std::string& place, const std::string& fragment)
{
  for (const PlanError& e : r.errors)
  {
    if (e.place == place && e.message.find(fragment) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

// The example maps x1..x6: the brief's 5-D model plus the fixed x6.
class ExamplePlan : public ::testing::Test
{
protected:
  void SetUp() override
  {
    result = plan_of(example_mapping, 6);
    ASSERT_TRUE(result.ok()) << format_errors(result.errors);
  }
  PlanResult result;
};

TEST_F(ExamplePlan, World)
{
  const Plan& p = result.plan;
  EXPECT_EQ(p.world_coordinates, (std::array<int, 3>{ 0, 1, 2 }));
  EXPECT_EQ(p.samples, (std::array<int, 3>{ 128, 128, 128 }));
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_EQ(p.model_box[k].lo, -1);
    EXPECT_EQ(p.world_box[k].hi, 1);
  }
  EXPECT_EQ(p.vertex_colouring.source, VertexColouring::Source::WorldCoordinate);
  EXPECT_EQ(p.vertex_colouring.coordinate, 2);
  EXPECT_EQ(p.vertex_colouring.colormap, "viridis");
  EXPECT_EQ(p.voice_count, 1);
}

TEST_F(ExamplePlan, CellsColumnFastest)
{
  const Plan& p = result.plan;
  EXPECT_EQ(p.grid_shape, (std::array<int, 3>{ 5, 5, 0 }));
  EXPECT_EQ(p.grid_coordinates, (std::vector<std::string>{ "x4", "x5", "" }));
  ASSERT_EQ(p.cells.size(), 25u);
  for (int row = 0; row < 5; ++row)
  {
    for (int column = 0; column < 5; ++column)
    {
      const Sample& s = p.cells[static_cast<std::size_t>(row * 5 + column)];
      EXPECT_EQ(s.cell, (std::array<int, 3>{ column, row, -1 }));
      EXPECT_DOUBLE_EQ(s.values[3], column * 0.25);
      EXPECT_DOUBLE_EQ(s.values[4], row * 0.25);
      EXPECT_EQ(s.values[5], 0.5);
      EXPECT_TRUE(std::isnan(s.values[0]) && std::isnan(s.values[1]) && std::isnan(s.values[2]));
    }
  }
  EXPECT_EQ(p.cells[0].label, "x4 = 0, x5 = 0");
  EXPECT_EQ(p.cells[1].label, "x4 = 0.25, x5 = 0");
  EXPECT_EQ(p.cells[7].label, "x4 = 0.5, x5 = 0.25");
  EXPECT_EQ(p.cells[24].label, "x4 = 1, x5 = 1");
}

TEST_F(ExamplePlan, ChannelValuesPerCell)
{
  const Plan& p = result.plan;
  const Sample& last = p.cells[24]; // x4 = 1, x5 = 1
  ASSERT_EQ(last.voices.size(), 1u);
  EXPECT_DOUBLE_EQ(last.voices[0].pitch, 440);
  EXPECT_DOUBLE_EQ(last.voices[0].loudness, 0.8);
  EXPECT_DOUBLE_EQ(last.voices[0].timbre, 0);
  EXPECT_DOUBLE_EQ(last.opacity, 0.3);
  const Sample& mid = p.cells[2 * 5 + 2]; // x4 = 0.5: pitch 220 + 0.25 * 220 (power 2)
  EXPECT_DOUBLE_EQ(mid.voices[0].pitch, 275);
  EXPECT_DOUBLE_EQ(mid.opacity, 0.65);
  EXPECT_EQ(p.cells[0].colour, (std::array<double, 3>{ 0.85, 0.62, 0.38 }));
  // x5 = 1 rotates by 90 degrees about z through the box centre (the origin here).
  const auto& m = last.transform;
  EXPECT_NEAR(m[0], 0, 1e-12);
  EXPECT_NEAR(m[1], -1, 1e-12);
  EXPECT_NEAR(m[4], 1, 1e-12);
  EXPECT_NEAR(m[10], 1, 1e-12);
  EXPECT_NEAR(m[3], 0, 1e-12);
  EXPECT_EQ(p.cells[0].transform,
    (std::array<double, 16>{ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 }));
}

TEST_F(ExamplePlan, FramesFollowTheClosedPath)
{
  const Plan& p = result.plan;
  ASSERT_EQ(p.frames.size(), 240u);
  EXPECT_EQ(p.dynamic_coordinates, (std::vector<std::string>{ "x4", "x5" }));
  const Sample& first = p.frames.front();
  EXPECT_EQ(first.values[3], 0.0);
  EXPECT_EQ(first.values[4], 0.0);
  EXPECT_EQ(first.path_point, (std::vector<double>{ 0, 0 }));
  EXPECT_EQ(first.time, 0.0);
  EXPECT_EQ(first.label, "x4 = 0, x5 = 0");
  EXPECT_EQ(first.cell, (std::array<int, 3>{ -1, -1, -1 }));
  EXPECT_DOUBLE_EQ(p.frames[24].time, 1.0);
  EXPECT_DOUBLE_EQ(p.frames[60].path_parameter, 0.25);
  // A closed loop: the last frame is one step short of the start, not on it again.
  const Sample& last = p.frames.back();
  EXPECT_NEAR(last.time, 239.0 / 24, 1e-12);
  EXPECT_LT(last.path_parameter, 1.0);
  EXPECT_GT(std::hypot(last.values[3], last.values[4]), 0.0);
  EXPECT_LT(std::hypot(last.values[3], last.values[4]), 0.05);
  for (const Sample& s : p.frames)
  {
    EXPECT_EQ(s.values[5], 0.5);
    EXPECT_TRUE(std::isnan(s.values[0]));
    ASSERT_EQ(s.voices.size(), 1u);
  }
  ASSERT_FALSE(p.path_polyline.empty());
  EXPECT_EQ(p.path_polyline.front(), (std::vector<double>{ 0, 0 }));
  EXPECT_EQ(p.path_polyline.back(), (std::vector<double>{ 0, 0 }));
  EXPECT_EQ(p.path_plane[0].lo, 0);
  EXPECT_EQ(p.path_plane[0].hi, 1);
  // x5's range comes from its spreadsheet values (0..1): the channels follow it.
  EXPECT_EQ(p.path_plane[1].hi, 1);
}

TEST(MappingPlan, OneDynamicCoordinateWithoutPath)
{
  std::string json = R"({ "animation": { "duration": 2, "fps": 10 }, "coordinates": {
    "x1": [{ "type": "world", "axis": "x" }], "x2": [{ "type": "world", "axis": "y", "range": [0, 4] }],
    "x3": [{ "type": "dynamic", "range": [0, 1], "curve": { "kind": "power", "exponent": 2 } },
           { "type": "colour", "colormap": "grey" }, { "type": "colour", "colormap": "red", "applies_to": "background" }] } })";
  const PlanResult r = plan_of(json, 3);
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  const Plan& p = r.plan;
  EXPECT_EQ(p.world_coordinates, (std::array<int, 3>{ 0, 1, -1 }));
  EXPECT_EQ(p.samples, (std::array<int, 3>{ 64, 128, 0 }));
  EXPECT_EQ(p.world_box[2].lo, 0);
  EXPECT_EQ(p.world_box[2].hi, 0);
  EXPECT_TRUE(p.cells.empty());
  ASSERT_EQ(p.frames.size(), 20u);
  // Time t = u^2 * 2 s, so x3 = sqrt(t / 2).
  EXPECT_NEAR(p.frames[5].values[2], std::sqrt(0.5 / 2), 1e-9);
  EXPECT_NEAR(p.frames[5].colour[0], std::sqrt(0.25), 1e-9);
  EXPECT_NEAR(p.frames[5].background[0], std::sqrt(0.25), 1e-9);
  EXPECT_EQ(p.frames[5].background[1], 1.0);
  EXPECT_EQ(p.frames[5].label, "x3 = " + std::to_string(std::sqrt(0.25)).substr(0, 3));
  EXPECT_EQ(p.voice_count, 0);
  EXPECT_TRUE(p.frames[5].voices.empty());
}

TEST(MappingPlan, OpenPathEndsOnItsLastPointAndKeyTimesPlaceFrames)
{
  std::string json = R"({ "animation": { "duration": 3, "fps": 2, "path": { "coordinates": ["x3"],
    "points": [[0], [1], [3]], "interpolation": "polyline" } }, "coordinates": {
    "x1": [{ "type": "world", "axis": "x" }], "x2": [{ "type": "world", "axis": "y" }],
    "x3": [{ "type": "dynamic" }] } })";
  PlanResult r = plan_of(json, 3);
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  ASSERT_EQ(r.plan.frames.size(), 6u);
  EXPECT_EQ(r.plan.frames.front().values[2], 0);
  EXPECT_EQ(r.plan.frames.back().values[2], 3);
  EXPECT_NEAR(r.plan.frames[1].values[2], 0.6, 1e-12);

  json = replaced(json,
    "\"interpolation\": \"polyline\"",
    "\"interpolation\": \"polyline\", \"timing\": \"keys\", \"key_times\": [0, 2, 2.5]");
  r = plan_of(json, 3);
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  EXPECT_NEAR(r.plan.frames[1].values[2], 0.25, 1e-12); // t = 0.5: a quarter of the way to 1
  EXPECT_NEAR(r.plan.frames[4].values[2], 1.0, 1e-12);  // t = 2
  EXPECT_NEAR(r.plan.frames[5].values[2], 3.0, 1e-12);  // t = 2.5
}

TEST(MappingPlan, TransformsComposeInFileOrder)
{
  std::string json = R"({ "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [0, 2] }], "x2": [{ "type": "world", "axis": "y", "range": [0, 2] }],
    "x3": [{ "type": "spreadsheet", "axis": "columns", "values": [1] },
           { "type": "transformation", "transform": "scale", "range": [0, 1], "target": [1, 3] },
           { "type": "transformation", "transform": "translate", "vector": [0, 2, 0], "range": [0, 1], "target": [0, 5] }] } })";
  const PlanResult r = plan_of(json, 3);
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  ASSERT_EQ(r.plan.cells.size(), 1u);
  EXPECT_TRUE(r.plan.frames.empty());
  const auto& m = r.plan.cells[0].transform;
  // Scale 3 about the centre (1, 1, 0), then move 5 along y: (x, y) -> (3x - 2, 3y - 2 + 5).
  EXPECT_NEAR(m[0], 3, 1e-12);
  EXPECT_NEAR(m[5], 3, 1e-12);
  EXPECT_NEAR(m[3], -2, 1e-12);
  EXPECT_NEAR(m[7], 3, 1e-12);
  EXPECT_EQ(r.plan.cells[0].label, "x3 = 1");
}

TEST(MappingPlan, CylindricalWorldBox)
{
  const std::string json =
    R"({ "world": { "system": "cylindrical", "resolution": 100 }, "coordinates": {
    "x1": [{ "type": "world", "axis": "r", "range": [0, 2] }],
    "x2": [{ "type": "world", "axis": "phi", "range": [0, 3.14159265358979] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-1, 1], "target": [0, 10] }] } })";
  const PlanResult r = plan_of(json, 3);
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  const auto& b = r.plan.world_box;
  EXPECT_NEAR(b[0].lo, -2, 1e-9);
  EXPECT_NEAR(b[0].hi, 2, 1e-9);
  EXPECT_NEAR(b[1].lo, 0, 1e-9);
  EXPECT_NEAR(b[1].hi, 2, 1e-9);
  EXPECT_EQ(b[2].lo, 0);
  EXPECT_EQ(b[2].hi, 10);
  EXPECT_EQ(r.plan.samples[0], 64); // 2 / 3.14 of 100
  EXPECT_EQ(r.plan.samples[1], 100);
}

TEST(MappingPlan, AttributesAsColours)
{
  const std::string json = R"({ "render": { "colour_source": "attributes" }, "coordinates": {
    "x1": [{ "type": "world", "axis": "x" }], "x2": [{ "type": "world", "axis": "y" }],
    "x3": [{ "type": "world", "axis": "z" }] } })";
  const PlanResult r = plan_of(json, 3);
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  EXPECT_EQ(r.plan.vertex_colouring.source, VertexColouring::Source::Attributes);
  EXPECT_TRUE(r.plan.cells.empty());
  EXPECT_TRUE(r.plan.frames.empty());
}

// A projected coordinate is eliminated: listed with its range and tolerance, its samples' value
// the range's middle (read by nothing once the model is projected); the file says so back.
TEST(MappingPlan, ProjectedCoordinateIsListedAndSavedBack)
{
  const std::string json = R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x" }], "x2": [{ "type": "world", "axis": "y" }],
      "x3": [{ "type": "world", "axis": "z" }],
      "x4": [{ "type": "projected", "range": [0, 0.5], "tolerance": 0.001 }],
      "x5": [{ "type": "dynamic", "range": [0, 1] }] },
    "animation": { "duration": 1, "fps": 3 } })";
  const PlanResult r = plan_of(json, 5);
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  ASSERT_EQ(r.plan.projected.size(), 1u);
  EXPECT_EQ(r.plan.projected[0].coordinate, 3);
  EXPECT_EQ(r.plan.projected[0].range, (Interval{ 0, 0.5 }));
  EXPECT_EQ(r.plan.projected[0].tolerance, 0.001);
  ASSERT_EQ(r.plan.frames.size(), 3u);
  for (const Sample& f : r.plan.frames)
  {
    EXPECT_EQ(f.values[3], 0.25);
    EXPECT_EQ(f.label.find("x4"), std::string::npos) << f.label; // not a varying coordinate
  }
  const LoadResult loaded = load_mapping(json);
  const LoadResult again = load_mapping(save_mapping(loaded.spec));
  ASSERT_TRUE(again.ok()) << format_errors(again.errors);
  EXPECT_EQ(again.spec, loaded.spec);
  EXPECT_TRUE(plan_of(replaced(json, R"(, "tolerance": 0.001)", ""), 5).plan.projected[0].tolerance == 1e-4);
}

TEST(MappingPlanErrors, ProjectedCoordinateTakesNoOtherChannel)
{
  const std::string json = R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x" }], "x2": [{ "type": "world", "axis": "y" }],
      "x3": [{ "type": "world", "axis": "z" }],
      "x4": [{ "type": "projected", "range": [0, 1] }, { "type": "colour" }] } })";
  EXPECT_TRUE(has_error(plan_of(json, 4), "coordinates.x4", "takes no other channel"));
  const std::string fixed = replaced(json, R"({ "type": "colour" })", R"({ "type": "fixed", "value": 0 })");
  EXPECT_TRUE(has_error(plan_of(fixed, 4), "coordinates.x4", "takes no other channel"));
  const LoadResult bad = load_mapping(replaced(json, R"("range": [0, 1] })", R"("tolerance": 0 })"));
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(format_errors(bad.errors), "coordinates.x4[0].tolerance: must be > 0\n");
  const LoadResult curve = load_mapping(replaced(json, R"("range": [0, 1] })", R"("curve": "linear" })"));
  EXPECT_FALSE(curve.ok()); // nothing is mapped, so no curve (nor target)
}

// --- bad mappings: each error names its place --------------------------------------------

TEST(MappingPlanErrors, MissingCoordinate)
{
  const PlanResult r = plan_of(example_mapping, 7);
  EXPECT_TRUE(has_error(r, "coordinates.x7", "missing")) << format_errors(r.errors);
  EXPECT_EQ(r.errors.size(), 1u) << format_errors(r.errors);
}

TEST(MappingPlanErrors, CoordinateNotInTheModel)
{
  const PlanResult r = plan_of(example_mapping, 5);
  EXPECT_TRUE(has_error(r, "coordinates.x6", "not a coordinate of the model"))
    << format_errors(r.errors);
}

TEST(MappingPlanErrors, OverlappingWorldAxes)
{
  const PlanResult r = plan_of(replaced(example_mapping, "\"axis\": \"y\"", "\"axis\": \"x\""), 6);
  EXPECT_TRUE(has_error(r, "coordinates.x2[0].axis", "axis x is already used by x1"))
    << format_errors(r.errors);
}

TEST(MappingPlanErrors, ZeroFrames)
{
  Spec spec = load_mapping(example_mapping).spec;
  spec.animation.fps = 0;
  const PlanResult r = make_plan(spec, model(6));
  EXPECT_TRUE(has_error(r, "animation.fps", "zero frames")) << format_errors(r.errors);
  spec.animation.fps = 24;
  spec.animation.duration = 1e9;
  EXPECT_TRUE(has_error(make_plan(spec, model(6)), "animation", "more than"));
}

TEST(MappingPlanErrors, ZeroWidthRange)
{
  Spec spec = load_mapping(example_mapping).spec;
  spec.coordinates[0].channels[0].range = Interval{ 0.5, 0.5 };
  const PlanResult r = make_plan(spec, model(6));
  EXPECT_TRUE(has_error(r, "coordinates.x1[0].range", "zero width")) << format_errors(r.errors);
}

TEST(MappingPlanErrors, OnePointPath)
{
  Spec spec = load_mapping(example_mapping).spec;
  spec.animation.path->points.resize(1);
  const PlanResult r = make_plan(spec, model(6));
  EXPECT_TRUE(has_error(r, "animation.path.points", "at least 2 points"))
    << format_errors(r.errors);
}

TEST(MappingPlanErrors, PathMustRunThroughTheDynamicCoordinates)
{
  Spec spec = load_mapping(example_mapping).spec;
  spec.animation.path->coordinates = { "x4", "x6" };
  PlanResult r = make_plan(spec, model(6));
  EXPECT_TRUE(
    has_error(r, "animation.path.coordinates", "must be the dynamic coordinates (x4, x5)"))
    << format_errors(r.errors);
  spec.animation.path.reset();
  r = make_plan(spec, model(6));
  EXPECT_TRUE(has_error(r, "animation.path", "missing: 2 dynamic coordinates"))
    << format_errors(r.errors);
}

TEST(MappingPlanErrors, PerFrameChannelsOnWorldCoordinates)
{
  const PlanResult r = plan_of(replaced(example_mapping,
                                 "{ \"type\": \"colour\", \"colormap\": \"viridis\" }",
                                 "{ \"type\": \"audio\" }, { \"type\": \"transformation\" }"),
    6);
  EXPECT_TRUE(has_error(r, "coordinates.x3[1]", "audio on a world coordinate"))
    << format_errors(r.errors);
  EXPECT_TRUE(has_error(r, "coordinates.x3[2]", "transformation on a world coordinate"));
}

TEST(MappingPlanErrors, WorldCountAndConflicts)
{
  PlanResult r = plan_of(R"({ "coordinates": { "x1": [{ "type": "world", "axis": "x" }],
    "x2": [{ "type": "fixed", "value": 0 }, { "type": "spreadsheet", "axis": "rows", "values": [1, 2] }] } })",
    2);
  EXPECT_TRUE(has_error(r, "coordinates", "1 world coordinates; 2 or 3"))
    << format_errors(r.errors);
  EXPECT_TRUE(has_error(r, "coordinates.x2", "a fixed coordinate cannot also be"));
  r = plan_of(
    R"({ "coordinates": { "x1": [{ "type": "world", "axis": "x" }], "x2": [{ "type": "world", "axis": "y" }],
    "x3": [{ "type": "spreadsheet", "axis": "rows", "values": [1, 2] }],
    "x4": [{ "type": "spreadsheet", "axis": "rows", "values": [1, 2] }, { "type": "dynamic" }, { "type": "dynamic" }] } })",
    4);
  EXPECT_TRUE(has_error(r, "coordinates.x4[0].axis", "the rows are already driven by x3"))
    << format_errors(r.errors);
  EXPECT_TRUE(has_error(r, "coordinates.x4[2].type", "a second dynamic channel"));
}

TEST(MappingPlanErrors, NonMonotoneDynamicCurve)
{
  const PlanResult r = plan_of(R"json({ "coordinates": { "x1": [{ "type": "world", "axis": "x" }],
    "x2": [{ "type": "world", "axis": "y" }],
    "x3": [{ "type": "dynamic", "curve": { "kind": "expression", "expression": "4*t*(1-t)" } }] } })json",
    3);
  EXPECT_TRUE(has_error(r, "coordinates.x3[0].curve", "monotone")) << format_errors(r.errors);
}

TEST(MappingPlan, FormatErrors)
{
  EXPECT_EQ(format_errors({ { "animation.fps", "must be > 0" }, { "", "duplicate key" } }),
    "animation.fps: must be > 0\nduplicate key\n");
}

} // namespace
} // namespace frep::mapping
