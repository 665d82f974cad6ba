// External shapes inside HyperFun programs: a mesh and a volume registered as name(x), blended
// with library primitives, meshed closed with culling (their enclosures at work), and the same
// surface as the shape's own wrapper model.
#include "Compiler/model.h"
#include "Eval/point_evaluator.h"
#include "Language/parser.h"
#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"
#include "Shapes/shape_functions.h"

#include "shape_test_meshes.h"

#include <gtest/gtest.h>

namespace frep::shapes
{
namespace
{

std::shared_ptr<const Model> compile(const std::string& text, std::shared_ptr<const UserFunctionRegistry> users)
{
  ParseOptions o;
  o.user_functions = std::move(users);
  ParseResult p = parse_program(text, "<test>", o);
  EXPECT_TRUE(p.ok()) << format_diagnostics(p.diagnostics);
  if (!p.ok())
  {
    return nullptr;
  }
  auto r = Model::compile(p.program, ast::select_default_object(*p.program));
  return r.model;
}

TEST(ShapeModels, AMeshBlendedWithASphereMeshesClosedAndCulls)
{
  auto mesh = MeshDistance::build(testing::sphere_mesh(1.0, 20, 40), true);
  ASSERT_TRUE(mesh.distance);
  auto users = std::make_shared<UserFunctionRegistry>();
  ASSERT_EQ(users->add(mesh_function("blob", mesh.distance)), "");
  const auto model = compile(
    "my_model(x[3], a[1]) { array c[3]; c = [1.5, 0, 0]; my_model = hfBlendUni(blob(x), hfSphere(x, c, 0.7), 0.3, 1, 1); }",
    users);
  ASSERT_TRUE(model);
  const GridSpec grid{ { { -2, 3, 64 }, { -2, 2, 52 }, { -2, 2, 52 } } };
  const mesh::ExtractResult r = mesh::extract_surface(model->tape(), grid);
  ASSERT_TRUE(r.ok()) << r.error;
  const mesh::MeshTopology t = mesh::analyse_topology(r.surface);
  EXPECT_GT(t.triangles, 1000u);
  EXPECT_EQ(t.boundary_edges, 0u);
  EXPECT_EQ(t.euler_characteristic, 2) << "one blob: genus 0";
  EXPECT_GT(r.statistics.boxes_culled, r.statistics.boxes_tested / 4)
    << r.statistics.boxes_culled << " of " << r.statistics.boxes_tested;
  EXPECT_LT(r.statistics.samples, r.statistics.dense_samples / 2);
}

TEST(ShapeModels, AVolumeAndTheWrapperModel)
{
  VolumeGrid g;
  const int n = 24;
  g.dims = { n, n, n };
  g.origin = { -1.5, -1.5, -1.5 };
  g.spacing = { 3.0 / (n - 1), 3.0 / (n - 1), 3.0 / (n - 1) };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = g.origin[0] + i * g.spacing[0], y = g.origin[1] + j * g.spacing[1],
                     z = g.origin[2] + k * g.spacing[2];
        g.values.push_back(x * x + y * y + z * z); // iso 1: F = r^2 - 1 ... inside where >= 1?
      }
  // F >= 0 where value >= iso: with value = r^2 that is outside the ball, so negate for a ball.
  for (double& v : g.values)
  {
    v = -v;
  }
  auto field = VolumeField::build(g, -1.0);
  ASSERT_TRUE(field.field) << field.error;
  auto users = std::make_shared<UserFunctionRegistry>();
  ASSERT_EQ(users->add(volume_function("ct", field.field)), "");
  const auto model = compile(wrapper_program("ct"), users);
  ASSERT_TRUE(model);
  EXPECT_EQ(model->name(), "ct_model");
  PointEvaluator p(model->tape());
  const double centre[3] = { 0, 0, 0 };
  EXPECT_GT(p.value(centre), 0.9);
  const double out[3] = { 1.4, 0, 0 };
  EXPECT_LT(p.value(out), 0);
  const GridSpec grid{ { { -2, 2, 48 }, { -2, 2, 48 }, { -2, 2, 48 } } };
  const mesh::ExtractResult r = mesh::extract_surface(model->tape(), grid);
  ASSERT_TRUE(r.ok()) << r.error;
  const mesh::MeshTopology t = mesh::analyse_topology(r.surface);
  EXPECT_EQ(t.boundary_edges, 0u);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_NEAR(t.signed_volume, 4.18879, 0.15) << "the unit ball's volume";
  EXPECT_GT(r.statistics.boxes_culled, 0u);
}

} // namespace
} // namespace frep::shapes
