// Surface and contour extraction: closed, manifold, outward-oriented meshes with the right
// volume, area and topology; culling and tape simplification change nothing but the work; bad
// requests are errors.
#include "conformance_case.h"

#include "Compiler/model.h"
#include "Eval/point_evaluator.h"
#include "Eval/thread_pool.h"
#include "Language/parser.h"
#include "Mesh/detail/cube_topology.h"
#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <mutex>
#include <set>
#include <thread>
#include <tuple>

namespace frep::mesh
{
namespace
{

std::shared_ptr<const Tape> compile(const std::string& text, std::vector<double> a = {},
  std::vector<std::optional<double>> fixed = {})
{
  const ParseResult parsed = parse_program(text, "<test>");
  EXPECT_TRUE(parsed.ok()) << (parsed.diagnostics.empty() ? "" : parsed.diagnostics[0].message);
  if (!parsed.ok())
  {
    return nullptr;
  }
  const int object = ast::select_default_object(*parsed.program);
  auto compiled = Model::compile(parsed.program, object);
  EXPECT_TRUE(compiled.model);
  Specialisation spec;
  spec.parameters = std::move(a);
  spec.fixed = std::move(fixed);
  return compiled.model->specialise(spec);
}

GridSpec cube_grid(double half, std::int64_t n, int axes = 3)
{
  GridSpec g;
  g.axes.assign(static_cast<std::size_t>(axes), GridAxis{ -half, half, n });
  return g;
}

const char* sphere_model = "my_model(x[3], a[1]) { my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2; }";

void expect_closed(const Surface& s, const char* what)
{
  const MeshTopology t = analyse_topology(s);
  EXPECT_EQ(t.boundary_edges, 0u) << what;
  EXPECT_EQ(t.nonmanifold_edges, 0u) << what;
  EXPECT_EQ(t.misoriented_edges, 0u) << what;
  EXPECT_EQ(t.degenerate_triangles, 0u) << what;
  EXPECT_EQ(t.points, s.point_count()) << what << ": every point is used";
  if (t.triangles > 0)
  {
    EXPECT_GT(t.signed_volume, 0.0) << what;
  }
}

TEST(CubeTopology, EveryCaseGivesClosedLoopsAndConsistentFaces)
{
  // Every edge crossing of a case is in exactly one loop, whatever the face decisions.
  for (int in = 0; in < 256; ++in)
  {
    for (int connected = 0; connected < 64; ++connected)
    {
      const CellPolygons& cell = cell_polygons(std::uint8_t(in), std::uint8_t(connected));
      int crossings = 0;
      for (int e = 0; e < 12; ++e)
      {
        crossings += ((in >> edge_start(e)) & 1) != ((in >> edge_end(e)) & 1) ? 1 : 0;
      }
      int total = 0;
      for (int l = 0; l < cell.loop_count; ++l)
      {
        EXPECT_GE(cell.loop_size[l], 3);
        total += cell.loop_size[l];
      }
      ASSERT_EQ(total, crossings) << "case " << in;
    }
  }
}

TEST(SurfaceExtraction, SphereVolumeAreaAndTopologyAt128)
{
  const auto tape = compile(sphere_model);
  const ExtractResult r = extract_surface(tape, cube_grid(6, 128));
  ASSERT_TRUE(r.ok()) << r.error;
  expect_closed(r.surface, "sphere");
  const MeshTopology t = analyse_topology(r.surface);
  const double pi = std::numbers::pi;
  EXPECT_NEAR(t.signed_volume, 4.0 / 3.0 * pi * 125.0, 0.01 * 4.0 / 3.0 * pi * 125.0);
  EXPECT_NEAR(t.area, 4.0 * pi * 25.0, 0.01 * 4.0 * pi * 25.0);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.components, 1u);
  // Culling skipped most of the volume.
  EXPECT_LT(r.statistics.samples, r.statistics.dense_samples / 3);
  // Normals are unit and outward: along the position for a sphere at the origin.
  ASSERT_EQ(r.surface.normals.size(), 3 * r.surface.point_count());
  for (std::size_t p = 0; p < r.surface.point_count(); p += 97)
  {
    const double* x = &r.surface.points[3 * p];
    const float* n = &r.surface.normals[3 * p];
    const double r0 = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    EXPECT_GT((x[0] * n[0] + x[1] * n[1] + x[2] * n[2]) / r0, 0.999);
    EXPECT_NEAR(r0, 5.0, 0.01);
  }
}

TEST(SurfaceExtraction, TorusHasEulerCharacteristicZero)
{
  const auto tape = compile("my_model(x[3], a[1]) { q = sqrt(x[1]^2 + x[2]^2) - 5; "
                            "my_model = 4 - q^2 - x[3]^2; }");
  const ExtractResult r = extract_surface(tape, cube_grid(8, 96));
  ASSERT_TRUE(r.ok()) << r.error;
  expect_closed(r.surface, "torus");
  const MeshTopology t = analyse_topology(r.surface);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.components, 1u);
  const double volume = 2 * std::numbers::pi * std::numbers::pi * 5 * 4; // 2 pi^2 R r^2
  EXPECT_NEAR(t.signed_volume, volume, 0.01 * volume);
}

// shape_topology: a ball of radius 4 and one of radius 0.6 beside it (0.34% of its volume) are
// two pieces, one a sliver; two balls of radius 4 none. Each piece's volume is its own (the
// volumes sum to the mesh's), and in 2-D the loops' areas decide alike.
TEST(SurfaceExtraction, ShapeTopologyCountsPiecesGenusAndSlivers)
{
  const auto pair = [](double small)
  {
    return "my_model(x[3], a[1]) { s1 = 16 - (x[1]-3)^2 - x[2]^2 - x[3]^2;"
           " s2 = " + std::to_string(small * small) + " - (x[1]+5)^2 - x[2]^2 - x[3]^2;"
           " my_model = max(s1, s2); }";
  };
  const ExtractResult speck = extract_surface(compile(pair(0.6).c_str()), cube_grid(8, 97));
  ASSERT_TRUE(speck.ok()) << speck.error;
  const frep::mesh::ShapeTopology s = frep::mesh::shape_topology(speck.surface);
  EXPECT_EQ(s.components, 2u);
  EXPECT_EQ(s.genus, 0);
  EXPECT_EQ(s.slivers, 1u);
  const MeshTopology t = analyse_topology(speck.surface);
  ASSERT_EQ(t.component_volumes.size(), 2u);
  const auto [lo, hi] = std::minmax(t.component_volumes[0], t.component_volumes[1]);
  EXPECT_NEAR(hi, 4.0 / 3 * std::numbers::pi * 64, 0.02 * hi);
  EXPECT_NEAR(lo, 4.0 / 3 * std::numbers::pi * 0.216, 0.2 * lo);
  EXPECT_NEAR(lo + hi, t.signed_volume, 1e-9 * hi);
  // Equal pieces: no sliver; and the comparison ignores slivers (a piece that shrinks is no
  // change of topology).
  const ExtractResult twins = extract_surface(compile(pair(2.0).c_str()), cube_grid(8, 97));
  const frep::mesh::ShapeTopology u = frep::mesh::shape_topology(twins.surface);
  EXPECT_EQ(u.components, 2u);
  EXPECT_EQ(u.slivers, 0u);
  EXPECT_TRUE(s == u);
  // 2-D: a disc of radius 4 and one of radius 0.3 (0.56% of its area).
  const auto discs = compile("my_model(x[2], a[1]) { d1 = 16 - (x[1]-3)^2 - x[2]^2;"
                             " d2 = 0.09 - (x[1]+5)^2 - x[2]^2; my_model = max(d1, d2); }");
  const ExtractResult contour = extract_contour(discs, cube_grid(8, 321, 2));
  ASSERT_TRUE(contour.ok()) << contour.error;
  const frep::mesh::ShapeTopology c = frep::mesh::shape_topology(contour.surface);
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(c.slivers, 1u);
}

TEST(SurfaceExtraction, DisjointPartsAreSeparateComponents)
{
  const auto tape = compile("my_model(x[3], a[1]) {"
                            " s1 = 4 - (x[1]-5)^2 - x[2]^2 - x[3]^2;"
                            " s2 = 4 - (x[1]+5)^2 - x[2]^2 - x[3]^2;"
                            " s3 = 1 - x[1]^2 - (x[2]-6)^2 - x[3]^2;"
                            " my_model = s1 | s2 | s3; }");
  const ExtractResult r = extract_surface(tape, cube_grid(9, 80));
  ASSERT_TRUE(r.ok()) << r.error;
  expect_closed(r.surface, "three spheres");
  const MeshTopology t = analyse_topology(r.surface);
  EXPECT_EQ(t.components, 3u);
  EXPECT_EQ(t.euler_characteristic, 6);
}

// Triangles as sorted position triples, each rotated to start at its smallest point (keeps the
// orientation), for comparing meshes whose point numbering differs.
std::vector<std::array<std::array<double, 3>, 3>> canonical_triangles(const Surface& s)
{
  std::vector<std::array<std::array<double, 3>, 3>> out;
  for (std::size_t t = 0; t < s.cell_count(); ++t)
  {
    std::array<std::array<double, 3>, 3> tri;
    for (int k = 0; k < 3; ++k)
    {
      const double* p = &s.points[3 * s.cells[3 * t + static_cast<std::size_t>(k)]];
      tri[static_cast<std::size_t>(k)] = { p[0], p[1], p[2] };
    }
    const auto first = std::min_element(tri.begin(), tri.end()) - tri.begin();
    std::rotate(tri.begin(), tri.begin() + first, tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(SurfaceExtraction, CullingGivesTheDenseMeshAndThreadsDoNotMatter)
{
  // CSG with a run-time error region and a shape cut by the box (caps).
  const auto tape = compile("my_model(x[3], a[1]) {"
                            " array v[3]; array c0[2]; v = [-6, -6, -6]; c0 = [0, 0];"
                            " b = hfBlock(x, v, 12, 12, 12);"
                            " sp = 49 - x[1]^2 - x[2]^2 - x[3]^2;"
                            " c = hfCylinderZ(x, c0, 2);"
                            " my_model = (b \\ sp) | c; }");
  GridSpec grid = cube_grid(7.3, 70);
  ExtractOptions dense;
  dense.cull = false;
  dense.threads = 1;
  ExtractOptions culled;
  culled.threads = 2;
  const ExtractResult a = extract_surface(tape, grid, dense);
  const ExtractResult b = extract_surface(tape, grid, culled);
  ASSERT_TRUE(a.ok() && b.ok());
  expect_closed(a.surface, "csg dense");
  expect_closed(b.surface, "csg culled");
  EXPECT_GE(a.statistics.samples, a.statistics.dense_samples); // leaves share their faces
  EXPECT_LT(b.statistics.samples, a.statistics.samples);
  EXPECT_EQ(canonical_triangles(a.surface), canonical_triangles(b.surface));
  // Same thread count twice: identical arrays (deterministic order).
  const ExtractResult c = extract_surface(tape, grid, culled);
  EXPECT_EQ(b.surface.points, c.surface.points);
  EXPECT_EQ(b.surface.cells, c.surface.cells);
}

/// The bit patterns of floats (NaN attributes of failed points compare equal to themselves).
std::vector<std::uint32_t> bits_of(const std::vector<float>& v)
{
  std::vector<std::uint32_t> out(v.size());
  if (!v.empty()) // (memcpy from an empty vector's null data is undefined)
  {
    std::memcpy(out.data(), v.data(), v.size() * sizeof(float));
  }
  return out;
}

/// Meshes `tape` with and without per-box tape simplification and expects identical arrays:
/// points, triangles, normals and attributes bit for bit (the values are the same, so is all).
/// Returns the instructions run per sample with and without.
std::pair<double, double> expect_simplification_changes_nothing(
  const std::shared_ptr<const Tape>& tape,
  const GridSpec& grid,
  const std::string& what)
{
  ExtractOptions simplified;
  simplified.threads = 2;
  ExtractOptions full = simplified;
  full.simplify = false;
  full.jit = false; // the reference: full tapes on the interpreter; the other: compiled leaves

  const ExtractResult a = extract_surface(tape, grid, simplified);
  const ExtractResult b = extract_surface(tape, grid, full);
  EXPECT_TRUE(a.ok() && b.ok()) << what << ": " << a.error << b.error;
  EXPECT_EQ(a.surface.points, b.surface.points) << what;
  EXPECT_EQ(a.surface.cells, b.surface.cells) << what;
  EXPECT_EQ(bits_of(a.surface.normals), bits_of(b.surface.normals)) << what;
  EXPECT_EQ(bits_of(a.surface.attributes), bits_of(b.surface.attributes)) << what;
  EXPECT_EQ(a.statistics.samples, b.statistics.samples) << what;
  EXPECT_EQ(a.statistics.failed_samples, b.statistics.failed_samples) << what;
  const auto per_sample = [](const ExtractResult& r)
  { return r.statistics.samples ? double(r.statistics.sample_instructions) / double(r.statistics.samples) : 0.0; };
  return { per_sample(a), per_sample(b) };
}

TEST(SurfaceExtraction, SimplifiedTapesGiveTheSameSurfaceBitForBit)
{
  // min/max, conditionals, a check that fails in part of the box (sqrt), attributes.
  std::ostringstream spheres;
  spheres << "my_model(x[3], a[1], s[1]) { u = -100;";
  for (int i = 0; i < 24; ++i)
  {
    const double cx = -6 + (i % 4) * 4, cy = -6 + (i / 4 % 3) * 5, cz = -5 + (i / 12) * 9;
    spheres << " u = max(u, 2.2^2 - (x[1]-(" << cx << "))^2 - (x[2]-(" << cy << "))^2 - (x[3]-("
            << cz << "))^2);";
  }
  spheres << " if x[1] > 1 then w = min(u, x[3] + 7); else w = u; endif;"
             " r = sqrt(x[2] + 8); s[1] = x[1] * r; my_model = min(w, r); }";
  const auto tape = compile(spheres.str());
  const auto [with, without] =
    expect_simplification_changes_nothing(tape, cube_grid(9, 90), "max of 24 spheres");
  // The leaves see a few spheres each: if simplification stopped working, this would fail.
  EXPECT_LT(with * 2, without) << with << " vs " << without << " instructions per sample";
}

TEST(SurfaceExtraction, SimplificationChangesNothingOnTheExternalModels)
{
  namespace fc = frep::conformance;
  const std::vector<fc::ConformanceCase> cases =
    fc::load_model_cases(std::filesystem::path(FREPKIT_SHARED_DIR) / "hyperfun" / "models");
  int meshed = 0;
  for (const fc::ConformanceCase& c : cases)
  {
    if (c.points.empty())
    {
      continue;
    }
    const ParseResult parsed = parse_program(c.source, c.program_path.string());
    ASSERT_TRUE(parsed.ok()) << c.id();
    const int object = ast::select_object(*parsed.program, c.object, ast::NameMatch::Exact);
    const auto compiled = Model::compile(parsed.program, object);
    ASSERT_TRUE(compiled.model) << c.id();
    if (compiled.model->x_dim() != 3)
    {
      continue;
    }
    // The box of the reference points (where the model's author looked at it).
    GridSpec grid = cube_grid(0, 64);
    for (GridAxis& axis : grid.axes)
    {
      axis.lo = 1e300;
      axis.hi = -1e300;
    }
    for (const fc::CasePoint& p : c.points)
    {
      for (int k = 0; k < 3; ++k)
      {
        grid.axes[k].lo = std::min(grid.axes[k].lo, p.x[k]);
        grid.axes[k].hi = std::max(grid.axes[k].hi, p.x[k]);
      }
    }
    expect_simplification_changes_nothing(compiled.model->tape(c.points.front().a), grid, c.id());
    ++meshed;
  }
  EXPECT_GE(meshed, 15);
}

TEST(SurfaceExtraction, PiecesTogetherGiveTheWholeMesh)
{
  // A shape cut by the box, so caps are involved; 3 uneven slabs along z and 2 along x.
  const auto tape = compile(sphere_model);
  GridSpec grid = cube_grid(6, 61);
  grid.axes[2].lo = -2.0;
  const ExtractResult whole = extract_surface(tape, grid);
  ASSERT_TRUE(whole.ok());
  Surface joined;
  for (auto [z0, z1] : { std::pair<int, int>{ 0, 17 }, { 17, 40 }, { 40, 60 } })
  {
    for (auto [x0, x1] : { std::pair<int, int>{ 0, 31 }, { 31, 60 } })
    {
      // The cells [x0, x1) x all x [z0, z1): the samples from x0 to x1, neighbours sharing one.
      GridSpec piece = grid;
      piece.axes[0].begin = x0;
      piece.axes[0].end = x1 + 1;
      piece.axes[2].begin = z0;
      piece.axes[2].end = z1 + 1;
      const ExtractResult r = extract_surface(tape, piece);
      ASSERT_TRUE(r.ok()) << r.error;
      const auto offset = static_cast<std::uint32_t>(joined.point_count());
      joined.points.insert(joined.points.end(), r.surface.points.begin(), r.surface.points.end());
      for (std::uint32_t id : r.surface.cells)
      {
        joined.cells.push_back(id + offset);
      }
    }
  }
  EXPECT_EQ(canonical_triangles(joined), canonical_triangles(whole.surface));
  GridSpec outside = grid;
  outside.axes[2].begin = 50;
  outside.axes[2].end = 70;
  EXPECT_NE(extract_surface(tape, outside).error.find("the part [50, 70) is not a range"),
    std::string::npos);
  GridSpec no_cell = grid;
  no_cell.axes[0].begin = 7;
  no_cell.axes[0].end = 8;
  EXPECT_NE(
    extract_surface(tape, no_cell).error.find("at least 2 of the samples"), std::string::npos);
}

TEST(SurfaceExtraction, ShapeCutByTheBoxIsCapped)
{
  // A sphere of radius 5 in the box [-2.5, 2.5]^3 fills it: the mesh is the box itself.
  const auto tape = compile(sphere_model);
  const ExtractResult r = extract_surface(tape, cube_grid(2.5, 20));
  ASSERT_TRUE(r.ok());
  expect_closed(r.surface, "box-filling sphere");
  EXPECT_NEAR(analyse_topology(r.surface).signed_volume, 125.0, 1e-9);
  // Without caps it is empty: the surface does not cross the box.
  ExtractOptions open;
  open.cap_boundary = false;
  EXPECT_EQ(extract_surface(tape, cube_grid(2.5, 20), open).surface.cell_count(), 0u);
  // Half in, half out: closed, volume of the half ball cut by the plane.
  GridSpec half = cube_grid(6, 97);
  half.axes[2].lo = 0.0;
  const ExtractResult h = extract_surface(tape, half);
  expect_closed(h.surface, "half sphere");
  const double volume = 2.0 / 3.0 * std::numbers::pi * 125.0;
  EXPECT_NEAR(analyse_topology(h.surface).signed_volume, volume, 0.01 * volume);
}

TEST(SurfaceExtraction, AmbiguousCellsStayWatertight)
{
  // A gyroid and a noise-like product on coarse grids: many ambiguous faces and cells.
  const char* models[] = {
    "my_model(x[3], a[1]) { my_model = sin(x[1])*cos(x[2]) + sin(x[2])*cos(x[3]) + "
    "sin(x[3])*cos(x[1]); }",
    "my_model(x[3], a[1]) { my_model = sin(3.1*x[1])*sin(2.3*x[2])*sin(1.7*x[3]) - 0.05; }",
    "my_model(x[3], a[1]) { my_model = cos(x[1]*x[2]) + cos(x[2]*x[3]*1.3) - 0.2; }",
  };
  for (const char* model : models)
  {
    const auto tape = compile(model);
    for (std::int64_t n : { 9, 17, 31, 40 })
    {
      const ExtractResult r = extract_surface(tape, cube_grid(6.5, n));
      ASSERT_TRUE(r.ok());
      EXPECT_GT(r.surface.cell_count(), 0u);
      expect_closed(r.surface, model);
    }
  }
}

TEST(SurfaceExtraction, RefinementMovesPointsOntoTheSurface)
{
  const auto tape = compile(sphere_model);
  PointEvaluator eval(tape);
  auto worst_value = [&](const Surface& s)
  {
    double worst = 0;
    for (std::size_t p = 0; p < s.point_count(); ++p)
    {
      worst = std::max(worst, std::abs(eval.value(std::span<const double>(&s.points[3 * p], 3))));
    }
    return worst;
  };
  ExtractOptions options;
  options.refine_steps = 8;
  const ExtractResult r = extract_surface(tape, cube_grid(6, 24), options);
  const ExtractResult linear = extract_surface(tape, cube_grid(6, 24));
  ASSERT_TRUE(r.ok() && linear.ok());
  expect_closed(r.surface, "refined sphere");
  EXPECT_EQ(r.surface.cells, linear.surface.cells) << "refinement keeps the topology";
  EXPECT_GT(worst_value(linear.surface), 0.01);
  EXPECT_LT(worst_value(r.surface), 1e-9);
}

TEST(SurfaceExtraction, AttributesAreTheModelsSArray)
{
  const auto tape = compile("my_model(x[3], a[1], s[2]) { s[1] = x[1]; s[2] = 7; "
                            "my_model = 16 - x[1]^2 - x[2]^2 - x[3]^2; }");
  const ExtractResult r = extract_surface(tape, cube_grid(5, 20));
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.surface.attribute_count, 2);
  ASSERT_EQ(r.surface.attributes.size(), 2 * r.surface.point_count());
  for (std::size_t p = 0; p < r.surface.point_count(); ++p)
  {
    EXPECT_FLOAT_EQ(r.surface.attributes[2 * p], static_cast<float>(r.surface.points[3 * p]));
    EXPECT_FLOAT_EQ(r.surface.attributes[2 * p + 1], 7.0f);
  }
}

TEST(SurfaceExtraction, RunTimeErrorsAreOutsideAndCounted)
{
  // sqrt of a negative for x[1] < 0: that half fails (NaN = outside); the rest is a half ball.
  const auto tape = compile("my_model(x[3], a[1]) { r = sqrt(x[1]); "
                            "my_model = 16 - x[1]^2 - x[2]^2 - x[3]^2 + 0*r; }");
  const ExtractResult r = extract_surface(tape, cube_grid(5, 41));
  ASSERT_TRUE(r.ok());
  EXPECT_GT(r.statistics.failed_samples, 0u);
  expect_closed(r.surface, "half ball next to failing points");
}

TEST(SurfaceExtraction, BadRequestsAreErrorsNotCrashes)
{
  const auto tape = compile(sphere_model);
  GridSpec flat = cube_grid(6, 32);
  flat.axes[1].hi = flat.axes[1].lo;
  EXPECT_NE(
    extract_surface(tape, flat).error.find("the box's minimum must be less than its maximum"),
    std::string::npos);
  GridSpec one = cube_grid(6, 32);
  one.axes[2].samples = 1;
  EXPECT_NE(extract_surface(tape, one).error.find("at least 2 samples"), std::string::npos);
  const auto start = std::chrono::steady_clock::now();
  const ExtractResult huge = extract_surface(tape, cube_grid(6, 100000));
  EXPECT_NE(huge.error.find("limit"), std::string::npos) << huge.error;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.5);
  EXPECT_FALSE(extract_surface(nullptr, cube_grid(6, 8)).error.empty());
  const auto four_d = compile("my_model(x[4], a[1]) { my_model = 1 - x[1]^2 - x[4]^2; }");
  EXPECT_NE(extract_surface(four_d, cube_grid(2, 8)).error.find("4 free coordinates"),
    std::string::npos);
  EXPECT_NE(extract_surface(tape, cube_grid(2, 8, 2)).error.find("the grid has 2 axes; a surface"),
    std::string::npos);
  // Nothing in the box: an empty mesh, not an error.
  const ExtractResult empty = extract_surface(compile(sphere_model),
    []
    {
      GridSpec g = cube_grid(1, 16);
      for (GridAxis& axis : g.axes)
      {
        axis.lo = 20;
        axis.hi = 22;
      }
      return g;
    }());
  EXPECT_TRUE(empty.ok());
  EXPECT_EQ(empty.surface.cell_count(), 0u);
}

TEST(SurfaceExtraction, ProgressIsReportedAndCancels)
{
  const auto tape = compile(sphere_model);
  int calls = 0;
  double last = 0;
  ExtractOptions options;
  options.progress = [&](double f)
  {
    ++calls;
    EXPECT_GE(f, last);
    last = f;
    return true;
  };
  ASSERT_TRUE(extract_surface(tape, cube_grid(6, 100), options).ok());
  EXPECT_GT(calls, 1);
  EXPECT_DOUBLE_EQ(last, 1.0);
  options.progress = [](double) { return false; };
  const ExtractResult cancelled = extract_surface(tape, cube_grid(6, 100), options);
  EXPECT_TRUE(cancelled.cancelled);
  EXPECT_EQ(cancelled.surface.cell_count(), 0u);
}

// RunControl::cancel stops the mesher between blocks, polled from its worker threads: a request
// after the first blocks leaves most of them undone and no mesh.
TEST(SurfaceExtraction, CancelStopsBetweenBlocks)
{
  const auto tape = compile(sphere_model);
  std::atomic<int> polls{ 0 };
  ExtractOptions options;
  options.threads = 2;
  options.cancel = [&polls] { return ++polls > 3; };
  const ExtractResult r = extract_surface(tape, cube_grid(6, 160), options);
  EXPECT_TRUE(r.cancelled);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.surface.cell_count(), 0u);
  EXPECT_LT(polls.load(), 40) << "the remaining blocks are skipped without polling each";
}

TEST(SurfaceExtraction, UsesEveryThreadOfThePool)
{
  auto pool = std::make_shared<ThreadPool>(2);
  ASSERT_EQ(pool->size(), 2);
  const auto tape = compile(sphere_model);
  std::mutex mutex;
  std::set<std::thread::id> threads;
  ExtractOptions options;
  options.pool = pool;
  options.progress = [&](double)
  {
    std::lock_guard lock(mutex);
    threads.insert(std::this_thread::get_id());
    std::this_thread::sleep_for(std::chrono::milliseconds(1)); // let the other thread in
    return true;
  };
  ASSERT_TRUE(extract_surface(tape, cube_grid(6, 160), options).ok());
  EXPECT_EQ(threads.size(), 2u) << "both participants of the pool ran blocks";
}

TEST(ContourExtraction, CircleIsOneClosedCounterClockwiseLoop)
{
  const auto tape = compile("my_model(x[2], a[1]) { my_model = 25 - x[1]^2 - x[2]^2; }");
  const GridSpec grid = cube_grid(6, 200, 2);
  const ExtractResult r = extract_contour(tape, grid);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.surface.dimension, 2);
  // Every point starts one segment and ends one.
  std::vector<int> starts(r.surface.point_count()), ends(r.surface.point_count());
  double area = 0; // shoelace: positive when the inside is on the left
  for (std::size_t s = 0; s < r.surface.cell_count(); ++s)
  {
    const auto a = r.surface.cells[2 * s], b = r.surface.cells[2 * s + 1];
    ++starts[a];
    ++ends[b];
    area += 0.5 * (r.surface.points[3 * a] * r.surface.points[3 * b + 1] -
                    r.surface.points[3 * b] * r.surface.points[3 * a + 1]);
  }
  for (std::size_t p = 0; p < starts.size(); ++p)
  {
    ASSERT_EQ(starts[p], 1);
    ASSERT_EQ(ends[p], 1);
  }
  EXPECT_NEAR(area, std::numbers::pi * 25, 0.005 * std::numbers::pi * 25);
  EXPECT_NE(extract_contour(compile(sphere_model), grid).error.find("3 free coordinates"),
    std::string::npos);
}

// The external models of ../shared/hyperfun/models: closed, oriented meshes over the box their
// expected values were computed on (3-D models only).
TEST(SurfaceExtraction, ExternalModelsGiveClosedMeshes)
{
  const std::filesystem::path root = std::filesystem::path(FREPKIT_SHARED_DIR) / "hyperfun/models";
  ASSERT_TRUE(std::filesystem::exists(root)) << root;
  int meshed = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
  {
    if (entry.path().extension() != ".hf")
    {
      continue;
    }
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    const ParseResult parsed = parse_program(text.str(), entry.path().string());
    ASSERT_TRUE(parsed.ok()) << entry.path();
    const int object = ast::select_default_object(*parsed.program);
    auto compiled = Model::compile(parsed.program, object);
    ASSERT_TRUE(compiled.model) << entry.path();
    if (compiled.model->x_dim() != 3)
    {
      continue;
    }
    // The box of the expected values.
    std::filesystem::path expected = entry.path();
    expected.replace_extension(".expected.txt");
    GridSpec grid = cube_grid(10, 40);
    std::ifstream values(expected);
    std::array<double, 3> lo{ 1e300, 1e300, 1e300 }, hi{ -1e300, -1e300, -1e300 };
    double x, y, z;
    std::string value;
    while (values >> x >> y >> z >> value)
    {
      lo = { std::min(lo[0], x), std::min(lo[1], y), std::min(lo[2], z) };
      hi = { std::max(hi[0], x), std::max(hi[1], y), std::max(hi[2], z) };
    }
    if (lo[0] < hi[0] && lo[1] < hi[1] && lo[2] < hi[2])
    {
      grid = box_grid(lo, hi, std::array<std::int64_t, 3>{ 40, 40, 40 });
    }
    const ExtractResult r = extract_surface(compiled.model->tape(), grid);
    ASSERT_TRUE(r.ok()) << entry.path() << ": " << r.error;
    expect_closed(r.surface, entry.path().c_str());
    ++meshed;
  }
  EXPECT_GE(meshed, 10);
}

} // namespace
} // namespace frep::mesh
