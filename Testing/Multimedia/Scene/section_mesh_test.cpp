// make_section: a sample's section in world space. Checked by volume and orientation: a box in
// (r, phi, z) mapped cylindrically is an annulus sector of the right volume; a reversed world
// target mirrors the shape and the triangles are turned so it stays outward (positive volume);
// a scale transformation multiplies the volume by the cube; a world-coordinate colour channel
// colours the points by their coordinate; bad samples are errors, not crashes.
#include "Mapping/mapping_json.h"
#include "Mapping/mapping_plan.h"
#include "Scene/section_mesh.h"
#include "Scene/section_model.h"

#include "Compiler/model.h"
#include "Language/ast.h"
#include "Language/parser.h"
#include "Mesh/mesh_topology.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace
{

constexpr double pi = 3.14159265358979323846;

std::shared_ptr<const frep::Model> compile(const std::string& text)
{
  const frep::ParseResult parsed = frep::parse_program(text, "<test>");
  EXPECT_TRUE(parsed.ok());
  const int object = frep::ast::select_default_object(*parsed.program);
  return frep::Model::compile(parsed.program, object).model;
}

frep::mapping::Plan plan_of(const std::string& json, int dimension)
{
  const frep::mapping::LoadResult loaded = frep::mapping::load_mapping(json);
  EXPECT_TRUE(loaded.errors.empty()) << frep::mapping::format_errors(loaded.errors);
  frep::mapping::ModelCoordinates coordinates;
  for (int i = 0; i < dimension; ++i)
  {
    coordinates.names.push_back("x" + std::to_string(i + 1));
    coordinates.intervals.push_back({ -10, 10 });
  }
  frep::mapping::PlanResult planned = frep::mapping::make_plan(loaded.spec, coordinates);
  EXPECT_TRUE(planned.ok()) << frep::mapping::format_errors(planned.errors);
  return planned.plan;
}

frep::mesh::MeshTopology topology(const frep::mapping::Section& s)
{
  return frep::mesh::analyse_topology(s.surface);
}

// A slab r in [1.2, 1.8], |z| < 0.5, phi in [0.3, 2.8]: boxes in the model coordinates.
const char* const Slab = R"(
my_model(x[3], a[1])
{
  my_model = ((x[1] - 1.2) & (1.8 - x[1])) & ((x[2] - 0.3) & (2.8 - x[2])) & (0.5 - abs(x[3]));
}
)";

} // namespace

TEST(SectionMesh, CylindricalBoxIsAnAnnulusSector)
{
  const auto model = compile(Slab);
  ASSERT_TRUE(model);
  const frep::mapping::Plan plan = plan_of(R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "r", "range": [1, 2] }],
      "x2": [{ "type": "world", "axis": "phi", "range": [0, 3.1] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-1, 1] }] },
    "world": { "system": "cylindrical", "resolution": 96 } })",
    3);
  const frep::mapping::Section s = frep::mapping::make_section(*model, {}, plan, plan.still);
  ASSERT_TRUE(s.ok()) << s.error;
  const auto t = topology(s);
  EXPECT_TRUE(t.watertight_and_oriented());
  // (phi range / 2) (r2^2 - r1^2) h
  const double expected = 0.5 * 2.5 * (1.8 * 1.8 - 1.2 * 1.2) * 1.0;
  EXPECT_NEAR(t.signed_volume, expected, 0.02 * expected);
  // every point at radius 1.2..1.8 from the z axis
  for (std::size_t i = 0; i < s.surface.point_count(); ++i)
  {
    const double r = std::hypot(s.surface.points[3 * i], s.surface.points[3 * i + 1]);
    EXPECT_GT(r, 1.19);
    EXPECT_LT(r, 1.81);
  }
}

TEST(SectionMesh, ReversedTargetMirrorsAndStaysOutward)
{
  const auto model =
    compile(R"(my_model(x[3], a[1]) { my_model = 1 - (x[1] - 0.5)^2 - x[2]^2 - x[3]^2; })");
  ASSERT_TRUE(model);
  const frep::mapping::Plan plan = plan_of(R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x", "range": [-2, 2], "target": [2, -2] }],
      "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }] },
    "world": { "resolution": 64 } })",
    3);
  const frep::mapping::Section s = frep::mapping::make_section(*model, {}, plan, plan.still);
  ASSERT_TRUE(s.ok()) << s.error;
  const auto t = topology(s);
  EXPECT_TRUE(t.watertight_and_oriented());
  EXPECT_NEAR(t.signed_volume, 4.0 / 3.0 * pi, 0.02 * 4.0 / 3.0 * pi); // positive: outward
  // the ball centred at x = 0.5 lands at world x = -0.5
  double sum = 0;
  for (std::size_t i = 0; i < s.surface.point_count(); ++i)
  {
    sum += s.surface.points[3 * i];
  }
  EXPECT_NEAR(sum / s.surface.point_count(), -0.5, 0.02);
  // normals still point outward: away from the centre (-0.5, 0, 0)
  for (std::size_t i = 0; i < s.surface.point_count(); i += 97)
  {
    const double d = (s.surface.points[3 * i] + 0.5) * s.surface.normals[3 * i] +
                     s.surface.points[3 * i + 1] * s.surface.normals[3 * i + 1] +
                     s.surface.points[3 * i + 2] * s.surface.normals[3 * i + 2];
    EXPECT_GT(d, 0.0);
  }
}

TEST(SectionMesh, ScaleTransformationAndDynamicValues)
{
  // a 4-D ball of radius x4, scaled by 1 + x4 (transformation channel on the dynamic x4)
  const auto model =
    compile(R"(my_model(x[4], a[1]) { my_model = x[4]^2 - x[1]^2 - x[2]^2 - x[3]^2; })");
  ASSERT_TRUE(model);
  const frep::mapping::Plan plan = plan_of(R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x", "range": [-1.2, 1.2] }],
      "x2": [{ "type": "world", "axis": "y", "range": [-1.2, 1.2] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-1.2, 1.2] }],
      "x4": [{ "type": "dynamic", "range": [0.5, 1] },
             { "type": "transformation", "transform": "scale", "range": [0.5, 1], "target": [1, 2] }] },
    "animation": { "duration": 1, "fps": 2 },
    "world": { "resolution": 64 } })",
    4);
  ASSERT_EQ(plan.frames.size(), 2u);
  for (const auto& frame : plan.frames)
  {
    const double r = frame.values[3];
    const double scale = 1 + (r - 0.5) / 0.5;
    const frep::mapping::Section s = frep::mapping::make_section(*model, {}, plan, frame);
    ASSERT_TRUE(s.ok()) << s.error;
    const double expected = 4.0 / 3.0 * pi * std::pow(r * scale, 3);
    EXPECT_NEAR(topology(s).signed_volume, expected, 0.03 * expected) << "x4 = " << r;
  }
}

TEST(SectionMesh, WorldCoordinateColoursThePoints)
{
  const auto model =
    compile(R"(my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; })");
  ASSERT_TRUE(model);
  const frep::mapping::Plan plan = plan_of(R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x", "range": [-1.5, 1.5] }],
      "x2": [{ "type": "world", "axis": "y", "range": [-1.5, 1.5] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-1.5, 1.5] },
             { "type": "colour", "colormap": "red", "range": [-1, 1] }] },
    "world": { "resolution": 32 } })",
    3);
  const frep::mapping::Section s = frep::mapping::make_section(*model, {}, plan, plan.still);
  ASSERT_TRUE(s.ok()) << s.error;
  ASSERT_EQ(s.colours.size(), 3 * s.surface.point_count());
  for (std::size_t i = 0; i < s.surface.point_count(); i += 13)
  {
    const double z = s.surface.points[3 * i + 2];
    EXPECT_NEAR(s.colours[3 * i], (z + 1) / 2, 1e-5);              // red = the unit value of x3
    EXPECT_NEAR(s.colours[3 * i + 1], plan.still.colour[1], 1e-6); // the others unchanged
  }
}

// A sphere of radius 0.5 moving from x = -1 to 1 as x4 goes 0 -> 1, x4 projected: the section
// is the capsule it sweeps (volume pi r^2 2 + 4/3 pi r^3), not the ball at x4's middle.
TEST(SectionMesh, ProjectedCoordinateGivesTheSweptVolume)
{
  const auto model = compile(
    R"(my_model(x[4], a[1]) { my_model = 0.25 - ((x[1] + 1 - 2*x[4])^2 + x[2]^2 + x[3]^2); })");
  ASSERT_TRUE(model);
  const frep::mapping::Plan plan = plan_of(R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x", "range": [-1.6, 1.6] }],
      "x2": [{ "type": "world", "axis": "y", "range": [-0.6, 0.6] }],
      "x3": [{ "type": "world", "axis": "z", "range": [-0.6, 0.6] }],
      "x4": [{ "type": "projected", "range": [0, 1] }] },
    "world": { "resolution": 64 } })",
    4);
  const frep::mapping::SectionModel projected = frep::mapping::section_model(model, plan, {});
  ASSERT_TRUE(projected.ok()) << projected.error;
  EXPECT_EQ(projected.model->x_dim(), 4); // the coordinates keep their numbers
  const frep::mapping::Section s =
    frep::mapping::make_section(*projected.model, {}, plan, plan.still);
  ASSERT_TRUE(s.ok()) << s.error;
  const double capsule = pi * 0.25 * 2 + 4.0 / 3.0 * pi * 0.125;
  EXPECT_NEAR(topology(s).signed_volume, capsule, 0.02 * capsule);
  EXPECT_EQ(topology(s).components, 1u);
  // Without the projection the same sample is the ball at x4 = 0.5.
  const frep::mapping::Section ball = frep::mapping::make_section(*model, {}, plan, plan.still);
  EXPECT_NEAR(topology(ball).signed_volume, 4.0 / 3.0 * pi * 0.125, 0.03 * 0.5236);
  // Nothing projected: the model itself.
  frep::mapping::Plan plain = plan;
  plain.projected.clear();
  EXPECT_EQ(frep::mapping::section_model(model, plain, {}).model, model);
}

TEST(SectionMesh, BadSampleIsAnError)
{
  const auto model = compile(Slab);
  ASSERT_TRUE(model);
  const frep::mapping::Plan plan = plan_of(R"({
    "coordinates": {
      "x1": [{ "type": "world", "axis": "x" }], "x2": [{ "type": "world", "axis": "y" }],
      "x3": [{ "type": "world", "axis": "z" }] } })",
    3);
  frep::mapping::Sample wrong = plan.still;
  wrong.values.push_back(1.0); // 4 values for a 3-D model
  const frep::mapping::Section s = frep::mapping::make_section(*model, {}, plan, wrong);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.error.find("4 coordinate values"), std::string::npos) << s.error;
}
