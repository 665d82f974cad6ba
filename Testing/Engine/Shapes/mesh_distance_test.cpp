// MeshDistance: values against a brute-force loop over the triangles (the test's reference
// only), signs inside and outside, enclosures that hold and cull, the refusal of open meshes
// naming the open-edge count, the unsigned mode, inward meshes flipped.
#include "Shapes/mesh_distance.h"

#include "shape_test_meshes.h"

#include <gtest/gtest.h>

#include <random>

namespace frep::shapes
{
namespace
{

using testing::cube_mesh;
using testing::sphere_mesh;
using V = std::array<double, 3>;

double segment_d2(const V& p, const V& a, const V& b)
{
  V ab{ b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  V ap{ p[0] - a[0], p[1] - a[1], p[2] - a[2] };
  const double t = std::clamp((ab[0] * ap[0] + ab[1] * ap[1] + ab[2] * ap[2]) /
      (ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]), 0.0, 1.0);
  double d2 = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = ap[k] - t * ab[k];
    d2 += d * d;
  }
  return d2;
}

// Reference: the minimum over every triangle of the distance to its plane (if the projection
// falls inside) or to its edges.
double brute_distance(const TriangleMesh& m, const V& p)
{
  double best = INFINITY;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
  {
    V v[3];
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t id = m.triangles[3 * t + k];
      v[k] = { m.points[3 * id], m.points[3 * id + 1], m.points[3 * id + 2] };
    }
    const V e1{ v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2] };
    const V e2{ v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2] };
    V n{ e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0] };
    const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& c : n)
    {
      c /= nl;
    }
    const double h = (p[0] - v[0][0]) * n[0] + (p[1] - v[0][1]) * n[1] + (p[2] - v[0][2]) * n[2];
    const V q{ p[0] - h * n[0], p[1] - h * n[1], p[2] - h * n[2] };
    bool inside = true;
    for (int k = 0; k < 3; ++k)
    {
      const V& a = v[k];
      const V& b = v[(k + 1) % 3];
      const V ab{ b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const V aq{ q[0] - a[0], q[1] - a[1], q[2] - a[2] };
      const V c{ ab[1] * aq[2] - ab[2] * aq[1], ab[2] * aq[0] - ab[0] * aq[2], ab[0] * aq[1] - ab[1] * aq[0] };
      inside = inside && (c[0] * n[0] + c[1] * n[1] + c[2] * n[2]) >= 0;
    }
    double d2 = inside ? h * h : INFINITY;
    for (int k = 0; k < 3; ++k)
    {
      d2 = std::min(d2, segment_d2(p, v[k], v[(k + 1) % 3]));
    }
    best = std::min(best, d2);
  }
  return std::sqrt(best);
}

TEST(MeshDistance, EqualsTheBruteForceDistanceWithTheRightSign)
{
  const TriangleMesh mesh = sphere_mesh(1.0, 24, 48);
  const auto built = MeshDistance::build(mesh, true);
  ASSERT_TRUE(built.distance) << built.error;
  EXPECT_FALSE(built.distance->flipped());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  for (int i = 0; i < 2000; ++i)
  {
    const V p{ u(rng), u(rng), u(rng) };
    const double f = built.distance->value(p);
    const double d = brute_distance(mesh, p);
    ASSERT_NEAR(std::fabs(f), d, 1e-12) << i;
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (std::fabs(r - 1) > 0.02) // away from the faceted surface the sign is the sphere's
    {
      ASSERT_EQ(f > 0, r < 1) << "F >= 0 inside at " << p[0] << " " << p[1] << " " << p[2];
    }
  }
}

TEST(MeshDistance, SignsAtVerticesAndEdgesOfACube)
{
  const auto built = MeshDistance::build(cube_mesh(1.0), true);
  ASSERT_TRUE(built.distance) << built.error;
  // Closest features: a vertex (corner), an edge, a face, and points inside.
  EXPECT_NEAR(built.distance->value({ 2, 2, 2 }), -std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(built.distance->value({ 2, 2, 0 }), -std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(built.distance->value({ 0, 0, 3 }), -2.0, 1e-12);
  EXPECT_NEAR(built.distance->value({ 0.9, 0.9, 0.9 }), 0.1, 1e-12);
  EXPECT_NEAR(built.distance->value({ 0, 0, 0 }), 1.0, 1e-12);
  std::array<double, 3> g{};
  built.distance->value_and_gradient({ 0, 0, 3 }, g);
  EXPECT_NEAR(g[2], -1.0, 1e-12) << "F decreases going out";
}

TEST(MeshDistance, EnclosuresHoldAndCullFarBoxes)
{
  const auto built = MeshDistance::build(sphere_mesh(1.0, 16, 32), true);
  ASSERT_TRUE(built.distance);
  const MeshDistance& d = *built.distance;
  double lo = 0, hi = 0;
  ASSERT_TRUE(d.enclose({ 2, 2, 2 }, { 2.5, 2.5, 2.5 }, lo, hi));
  EXPECT_LT(hi, 0) << "outside: culled";
  ASSERT_TRUE(d.enclose({ -0.2, -0.2, -0.2 }, { 0.2, 0.2, 0.2 }, lo, hi));
  EXPECT_GT(lo, 0) << "deep inside: culled";
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::uniform_real_distribution<double> s(0.0, 0.7);
  for (int b = 0; b < 200; ++b)
  {
    const V l{ u(rng), u(rng), u(rng) };
    const V h{ l[0] + s(rng), l[1] + s(rng), l[2] + s(rng) };
    ASSERT_TRUE(d.enclose(l, h, lo, hi));
    for (int i = 0; i < 20; ++i)
    {
      std::uniform_real_distribution<double> t(0, 1);
      const V p{ l[0] + t(rng) * (h[0] - l[0]), l[1] + t(rng) * (h[1] - l[1]), l[2] + t(rng) * (h[2] - l[2]) };
      const double f = d.value(p);
      ASSERT_LE(lo, f);
      ASSERT_GE(hi, f);
    }
  }
  EXPECT_FALSE(d.enclose({ -INFINITY, 0, 0 }, { 1, 1, 1 }, lo, hi)) << "unbounded: no enclosure";
}

TEST(MeshDistance, AnOpenMeshIsRefusedNamingItsOpenEdges)
{
  TriangleMesh open = cube_mesh(1.0);
  open.triangles.resize(open.triangles.size() - 6); // two triangles off: a square hole
  const auto built = MeshDistance::build(open, true);
  EXPECT_FALSE(built.distance);
  EXPECT_NE(built.error.find("4 open edges"), std::string::npos) << built.error;
  EXPECT_EQ(built.edges.open, 4u);
  const auto unsigned_distance = MeshDistance::build(open, false);
  ASSERT_TRUE(unsigned_distance.distance) << unsigned_distance.error;
  EXPECT_NEAR(unsigned_distance.distance->value({ 0, 0, 0 }), -1.0, 1e-12) << "F = -d";

  TriangleMesh twisted = cube_mesh(1.0);
  std::swap(twisted.triangles[1], twisted.triangles[2]); // one triangle the wrong way round
  const auto t = MeshDistance::build(twisted, true);
  EXPECT_FALSE(t.distance);
  EXPECT_NE(t.error.find("3 inconsistently oriented edges"), std::string::npos) << t.error;

  TriangleMesh bad = cube_mesh(1.0);
  bad.triangles[0] = 99;
  EXPECT_NE(MeshDistance::build(bad, true).error.find("refers to point 99"), std::string::npos);
  EXPECT_NE(MeshDistance::build(TriangleMesh{}, true).error.find("no triangle"), std::string::npos);
}

TEST(MeshDistance, AnInwardMeshIsFlipped)
{
  TriangleMesh inward = cube_mesh(1.0);
  for (std::size_t t = 0; t < inward.triangle_count(); ++t)
  {
    std::swap(inward.triangles[3 * t + 1], inward.triangles[3 * t + 2]);
  }
  const auto built = MeshDistance::build(inward, true);
  ASSERT_TRUE(built.distance);
  EXPECT_TRUE(built.distance->flipped());
  EXPECT_NEAR(built.distance->value({ 0, 0, 0 }), 1.0, 1e-12);
}

} // namespace
} // namespace frep::shapes
