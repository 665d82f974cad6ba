// The key shapes of "Homotopic Fun in 5D Space" (Examples/homotopic/*.hf) have the topology their
// headers state, and the 5-D blend meta5d.hf reproduces them exactly at its four corners.
//
// Resolution: every shape is extracted with the engine's mesher (as `frepkit mesh`) on a grid of
// 160 samples per axis over the common box [-10, 10]^3 (cell 0.1258). The topology of each
// connected component is measured on the mesh: its Euler characteristic V - E + F, and for a
// closed orientable surface the genus g = 1 - chi / 2.
#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Eval/gradient_evaluator.h"
#include "Compiler/load_model.h"
#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{

constexpr int kGrid = 160;  // samples per axis over the common box
constexpr double kBox = 10; // the common box [-kBox, kBox]^3

std::string model_path(const std::string& file)
{
  return std::string(FREPKIT_SOURCE_DIR) + "/Examples/homotopic/" + file;
}

/// The object `name` of `file` ("" = the default object: my_model, else the first), compiled,
/// with `libraries` (files of Examples/homotopic) it may call.
std::shared_ptr<const frep::Model> load(const std::string& file, const std::string& name = "",
  const std::vector<std::string>& libraries = {})
{
  frep::LoadOptions options;
  options.object = name;
  for (const std::string& library : libraries)
  {
    options.libraries.push_back(model_path(library));
  }
  const frep::LoadedModel loaded = frep::load_model(frep::ModelSource::file(model_path(file)), options);
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  if (loaded.model)
  {
    EXPECT_TRUE(loaded.model->is_compiled()) << loaded.model->fallback_reason();
  }
  return loaded.model;
}

frep::mesh::Surface extract(std::shared_ptr<const frep::Tape> tape, int samples = kGrid)
{
  const frep::GridSpec grid{
    { { -kBox, kBox, samples }, { -kBox, kBox, samples }, { -kBox, kBox, samples } }
  };
  frep::mesh::ExtractOptions options;
  options.normals = false;
  options.attributes = false;
  frep::mesh::ExtractResult result = frep::mesh::extract_surface(std::move(tape), grid, options);
  EXPECT_TRUE(result.ok()) << result.error;
  EXPECT_EQ(result.statistics.failed_samples, 0u);
  return std::move(result.surface);
}

/// Euler characteristic V - E + F of each connected component (triangles sharing a point are
/// connected; the mesher's output is manifold, so this equals connection through edges).
std::vector<long long> component_euler_characteristics(const frep::mesh::Surface& surface)
{
  const std::size_t points = surface.point_count();
  std::vector<std::uint32_t> parent(points);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t p) {
    while (parent[p] != p)
    {
      parent[p] = parent[parent[p]];
      p = parent[p];
    }
    return p;
  };
  const std::size_t triangles = surface.cells.size() / 3;
  for (std::size_t t = 0; t < triangles; ++t)
  {
    const std::uint32_t* c = &surface.cells[3 * t];
    parent[find(c[1])] = find(c[0]);
    parent[find(c[2])] = find(c[0]);
  }
  struct Counts
  {
    long long vertices = 0, edges = 0, faces = 0;
  };
  std::map<std::uint32_t, Counts> components;
  std::vector<char> used(points, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * triangles);
  for (std::size_t t = 0; t < triangles; ++t)
  {
    const std::uint32_t* c = &surface.cells[3 * t];
    ++components[find(c[0])].faces;
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = c[k], b = c[(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
      if (!used[a])
      {
        used[a] = 1;
        ++components[find(a)].vertices;
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& e : edges)
  {
    ++components[find(e.first)].edges;
  }
  std::vector<long long> chi;
  for (const auto& [root, n] : components)
  {
    chi.push_back(n.vertices - n.edges + n.faces);
  }
  std::sort(chi.begin(), chi.end());
  return chi;
}

/// Genus of each component (sorted), from its Euler characteristic.
std::vector<long long> genera(const std::vector<long long>& chi)
{
  std::vector<long long> g;
  for (long long c : chi)
  {
    EXPECT_EQ(c % 2, 0) << "odd Euler characteristic: not a closed surface";
    g.push_back(1 - c / 2);
  }
  std::sort(g.begin(), g.end());
  return g;
}

std::string list(const std::vector<long long>& v)
{
  std::string s;
  for (long long x : v)
  {
    s += (s.empty() ? "" : " ") + std::to_string(x);
  }
  return "[" + s + "]";
}

/// Meshes `file` at the stated grid and checks: closed, oriented, positive volume, and the
/// genera of its components.
void expect_topology(const std::string& file, const std::vector<long long>& expected_genera)
{
  const auto model = load(file);
  ASSERT_TRUE(model);
  ASSERT_EQ(model->x_dim(), 3);
  const frep::mesh::Surface surface = extract(model->tape());
  ASSERT_GT(surface.cell_count(), 0u) << file << ": no surface";
  const frep::mesh::MeshTopology topology = frep::mesh::analyse_topology(surface);
  EXPECT_TRUE(topology.watertight_and_oriented())
    << file << ": boundary " << topology.boundary_edges << " nonmanifold "
    << topology.nonmanifold_edges << " misoriented " << topology.misoriented_edges
    << " degenerate " << topology.degenerate_triangles;
  EXPECT_GT(topology.signed_volume, 0) << file;
  const std::vector<long long> chi = component_euler_characteristics(surface);
  EXPECT_EQ(topology.components, chi.size());
  EXPECT_EQ(std::accumulate(chi.begin(), chi.end(), 0LL), topology.euler_characteristic);
  const std::vector<long long> g = genera(chi);
  EXPECT_EQ(g, expected_genera) << file << " at grid " << kGrid << ": " << chi.size()
                                << " components, Euler characteristics " << list(chi);
  std::printf("%s: %zu triangles, %zu components, Euler characteristics %s, genera %s, "
              "volume %.1f\n",
    file.c_str(), surface.cell_count(), chi.size(), list(chi).c_str(), list(g).c_str(),
    topology.signed_volume);
  // No part may touch the box: the shapes lie inside it with a margin (>= 1.3).
  double extent = 0;
  for (double c : surface.points)
  {
    extent = std::max(extent, std::abs(c));
  }
  EXPECT_LT(extent, kBox - 1.3) << file << " reaches the box's margin";
}

std::vector<double> evaluate(std::shared_ptr<const frep::Tape> tape,
  const std::vector<std::vector<double>>& columns)
{
  std::vector<const double*> inputs;
  for (const auto& c : columns)
  {
    inputs.push_back(c.data());
  }
  const std::size_t count = columns.front().size();
  std::vector<double> values(count);
  frep::BatchEvaluator batch(std::move(tape));
  EXPECT_EQ(batch.evaluate(inputs, count, values.data()), 0u);
  return values;
}

/// Points to compare the blend on: random in the box, and the surface points of the shape
/// (where the sign matters most).
std::vector<std::vector<double>> test_points(const frep::Model& model, std::size_t random_count)
{
  std::vector<std::vector<double>> xyz(3);
  std::mt19937_64 random(20000115); // the IRTC entry's date
  for (std::size_t i = 0; i < random_count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      xyz[k].push_back(-kBox + 2 * kBox * static_cast<double>(random() >> 11) * 0x1p-53);
    }
  }
  const frep::mesh::Surface surface = extract(model.tape(), 48);
  const std::size_t step = std::max<std::size_t>(1, surface.point_count() / 200);
  for (std::size_t p = 0; p < surface.point_count(); p += step)
  {
    for (int k = 0; k < 3; ++k)
    {
      xyz[k].push_back(surface.points[3 * p + k]);
    }
  }
  return xyz;
}

struct Corner
{
  const char* file;
  const char* object;
  double x4, x5;
};
constexpr Corner kCorners[] = {
  { "cat.hf", "cat", 0, 0 },
  { "robot.hf", "robot", 1, 0 },
  { "nihon.hf", "nihon", 0, 1 },
  { "roblet.hf", "roblet", 1, 1 },
};

} // namespace

TEST(HomotopicModels, CatIsOneSolidOfGenus0)
{
  expect_topology("cat.hf", { 0 });
}

TEST(HomotopicModels, RobotIsOneSolidOfGenus0)
{
  expect_topology("robot.hf", { 0 });
}

TEST(HomotopicModels, NiHonIsOneSolidOfGenus2)
{
  expect_topology("nihon.hf", { 2 });
}

TEST(HomotopicModels, RobLetIsTwoSpheresAndThreeTori)
{
  expect_topology("roblet.hf", { 0, 0, 1, 1, 1 });
}

// Meta5D(x, y, z, x4, x5) at the corners (0,0), (1,0), (0,1), (1,1) equals Cat, Robot, NiHon,
// Rob_let as written in their own files, bit for bit (the weights are exactly 0 and 1): through
// the full 5-D tape, through the 3-D slice tape, for `meta5d`, for the default object and for
// blend.hf, which calls the four files as HyperFun libraries instead of pasting them.
TEST(HomotopicModels, Meta5DCornersEqualTheKeyShapes)
{
  const auto meta5d = load("meta5d.hf", "meta5d");
  const auto main_object = load("meta5d.hf");
  const auto blend =
    load("blend.hf", "", { "cat.hf", "robot.hf", "nihon.hf", "roblet.hf" });
  ASSERT_TRUE(meta5d && main_object && blend);
  EXPECT_EQ(blend->name(), "my_model");
  EXPECT_EQ(main_object->name(), "my_model");
  ASSERT_EQ(meta5d->x_dim(), 5);
  ASSERT_EQ(main_object->x_dim(), 5);
  for (const Corner& corner : kCorners)
  {
    SCOPED_TRACE(corner.file);
    const auto single = load(corner.file);
    ASSERT_TRUE(single);
    EXPECT_EQ(single->name(), corner.object);
    const auto inside_meta = load("meta5d.hf", corner.object);
    ASSERT_TRUE(inside_meta);
    const std::vector<std::vector<double>> xyz = test_points(*single, 300);
    const std::size_t count = xyz[0].size();
    ASSERT_GE(count, 400u);
    const std::vector<double> expected = evaluate(single->tape(), xyz);
    std::vector<std::vector<double>> xyzw = xyz;
    xyzw.emplace_back(count, corner.x4);
    xyzw.emplace_back(count, corner.x5);
    frep::Specialisation slice;
    slice.fixed = { std::nullopt, std::nullopt, std::nullopt, corner.x4, corner.x5 };
    const std::vector<std::vector<double>> results = {
      evaluate(meta5d->tape(), xyzw),            // the 5-D object, x4 and x5 as inputs
      evaluate(main_object->tape(), xyzw),       // the default object my_model
      evaluate(meta5d->specialise(slice), xyz),  // the 3-D slice tape of the corner
      evaluate(inside_meta->tape(), xyz),        // the copy of the shape inside meta5d.hf
      evaluate(blend->tape(), xyzw),             // blend.hf calling the four files as libraries
    };
    std::size_t inside = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
      inside += expected[i] >= 0 ? 1 : 0;
      for (const auto& r : results)
      {
        ASSERT_EQ(r[i], expected[i]) << "point " << xyz[0][i] << " " << xyz[1][i] << " "
                                        << xyz[2][i];
      }
    }
    EXPECT_GT(inside, 0u); // the comparison covers both signs
    EXPECT_LT(inside, count);
  }
}

// blend.hf with the four key-shape files as HyperFun libraries is meta5d.hf everywhere, not only
// at the corners: the same values, bit for bit, at mixed (x4, x5).
TEST(HomotopicModels, BlendWithLibrariesIsMeta5DBitForBit)
{
  const auto meta5d = load("meta5d.hf");
  const auto blend = load("blend.hf", "", { "cat.hf", "robot.hf", "nihon.hf", "roblet.hf" });
  ASSERT_TRUE(meta5d && blend);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> space(-kBox, kBox);
  std::uniform_real_distribution<double> time(0.0, 1.0);
  std::vector<std::vector<double>> points(5);
  for (int i = 0; i < 4000; ++i)
  {
    for (int k = 0; k < 5; ++k)
    {
      points[static_cast<std::size_t>(k)].push_back(k < 3 ? space(random) : time(random));
    }
  }
  const std::vector<double> expected = evaluate(meta5d->tape(), points);
  const std::vector<double> got = evaluate(blend->tape(), points);
  for (std::size_t i = 0; i < expected.size(); ++i)
  {
    ASSERT_EQ(std::memcmp(&got[i], &expected[i], sizeof(double)), 0) << "point " << i;
  }
}

// The four shapes share one scale: the median |grad F| over their surface points is about 1 per
// unit (the blend would otherwise follow the steepest shape).
TEST(HomotopicModels, KeyShapesHaveComparableGradients)
{
  for (const Corner& corner : kCorners)
  {
    const auto model = load(corner.file);
    ASSERT_TRUE(model);
    const frep::mesh::Surface surface = extract(model->tape(), 96);
    frep::GradientEvaluator gradient(model->tape());
    std::vector<double> norms;
    const std::size_t step = std::max<std::size_t>(1, surface.point_count() / 2000);
    for (std::size_t p = 0; p < surface.point_count(); p += step)
    {
      double g[3];
      gradient.evaluate(std::span<const double>(&surface.points[3 * p], 3), g);
      norms.push_back(std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]));
    }
    std::sort(norms.begin(), norms.end());
    const double median = norms[norms.size() / 2];
    std::printf("%s: median |grad F| on the surface %.3f\n", corner.file, median);
    EXPECT_GT(median, 0.85) << corner.file;
    EXPECT_LT(median, 1.2) << corner.file;
  }
}

// The mid cells of the blend are solids inside the box: not empty, not filling it, closed.
TEST(HomotopicModels, Meta5DMidCellsAreSolidsInsideTheBox)
{
  const auto meta5d = load("meta5d.hf", "meta5d");
  ASSERT_TRUE(meta5d);
  const double box_volume = 8 * kBox * kBox * kBox;
  for (double x4 : { 0.25, 0.5, 0.75 })
  {
    for (double x5 : { 0.25, 0.5, 0.75 })
    {
      frep::Specialisation slice;
      slice.fixed = { std::nullopt, std::nullopt, std::nullopt, x4, x5 };
      const frep::mesh::Surface surface = extract(meta5d->specialise(slice), 64);
      const frep::mesh::MeshTopology topology = frep::mesh::analyse_topology(surface);
      std::printf("meta5d at x4 = %.2f, x5 = %.2f: %zu triangles, %zu components, volume %.1f\n",
        x4, x5, surface.cell_count(), topology.components, topology.signed_volume);
      EXPECT_TRUE(topology.watertight_and_oriented());
      EXPECT_GT(topology.signed_volume, 20.0) << x4 << " " << x5;
      EXPECT_LT(topology.signed_volume, 0.1 * box_volume) << x4 << " " << x5;
      double extent = 0;
      for (double c : surface.points)
      {
        extent = std::max(extent, std::abs(c));
      }
      EXPECT_LT(extent, kBox - 0.5) << "touches the box at " << x4 << " " << x5;
    }
  }
}

// The key shapes are normalised alike (their headers): F in [-0.15, 0.3] everywhere in the box
// (up to rounding: tanh reaches 1 in floating point), so that no shape's large values outweigh the others' in
// the blend.
TEST(HomotopicModels, KeyShapesAreBoundedAlike)
{
  for (const Corner& corner : kCorners)
  {
    const auto model = load(corner.file);
    ASSERT_TRUE(model);
    const std::vector<std::vector<double>> xyz = test_points(*model, 20000);
    const std::vector<double> values = evaluate(model->tape(), xyz);
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    std::printf("%s: F in [%.4f, %.4f] at %zu points\n", corner.file, *lo, *hi, values.size());
    EXPECT_GE(*lo, -0.15 - 1e-12) << corner.file;
    EXPECT_LT(*lo, -0.14) << corner.file << ": saturates outside";
    EXPECT_LE(*hi, 0.3 + 1e-12) << corner.file;
  }
}

// Every cell of the 5 x 5 spreadsheet (x4, x5 in 0, 0.25, .., 1) is a substantial solid: at least
// half the volume of the smallest key shape (NiHon). Before the key shapes were normalised, the
// NiHon-Rob_let edge (x5 = 1, x4 = 0.25..0.75) kept a fifth of it (a few slivers).
TEST(HomotopicModels, Meta5DEveryCellIsASubstantialSolid)
{
  const auto meta5d = load("meta5d.hf", "meta5d");
  ASSERT_TRUE(meta5d);
  double smallest = 1e300;
  for (const Corner& corner : kCorners)
  {
    const auto model = load(corner.file);
    ASSERT_TRUE(model);
    smallest = std::min(smallest,
      frep::mesh::analyse_topology(extract(model->tape(), 64)).signed_volume);
  }
  for (double x5 : { 0.0, 0.25, 0.5, 0.75, 1.0 })
  {
    for (double x4 : { 0.0, 0.25, 0.5, 0.75, 1.0 })
    {
      frep::Specialisation slice;
      slice.fixed = { std::nullopt, std::nullopt, std::nullopt, x4, x5 };
      const frep::mesh::MeshTopology topology =
        frep::mesh::analyse_topology(extract(meta5d->specialise(slice), 64));
      std::printf("meta5d at x4 = %.2f, x5 = %.2f: volume %.1f (%.2f of the smallest key shape)\n",
        x4, x5, topology.signed_volume, topology.signed_volume / smallest);
      EXPECT_TRUE(topology.watertight_and_oriented()) << x4 << " " << x5;
      EXPECT_GT(topology.signed_volume, 0.5 * smallest) << x4 << " " << x5;
    }
  }
}
