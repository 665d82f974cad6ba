// VolumeField: trilinear values (exact for a linear field), the distance outside the grid,
// enclosures that hold and cull (a small box's from its own cells, a large one's from the
// bricks), and refused volumes.
#include "Shapes/volume_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace frep::shapes
{
namespace
{

VolumeGrid ball_grid(int n)
{
  VolumeGrid g;
  g.dims = { n, n, n };
  g.origin = { -2, -2, -2 };
  g.spacing = { 4.0 / (n - 1), 4.0 / (n - 1), 4.0 / (n - 1) };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = -2 + i * g.spacing[0], y = -2 + j * g.spacing[1], z = -2 + k * g.spacing[2];
        g.values.push_back(1 - (x * x + y * y + z * z)); // >= 0 inside the unit ball
      }
  return g;
}

TEST(VolumeField, TrilinearIsExactForALinearField)
{
  VolumeGrid g;
  g.dims = { 3, 4, 5 };
  g.spacing = { 0.5, 1, 2 };
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 3; ++i)
        g.values.push_back(2 * (i * 0.5) - 3 * j + 0.25 * (k * 2));
  const auto f = VolumeField::build(g, 1.0);
  ASSERT_TRUE(f.field) << f.error;
  EXPECT_NEAR(f.field->value({ 0.3, 1.7, 5.1 }), 2 * 0.3 - 3 * 1.7 + 0.25 * 5.1 - 1.0, 1e-12);
  std::array<double, 3> grad{};
  f.field->value_and_gradient({ 0.3, 1.7, 5.1 }, grad);
  EXPECT_NEAR(grad[0], 2, 1e-12);
  EXPECT_NEAR(grad[1], -3, 1e-12);
  EXPECT_NEAR(grad[2], 0.25, 1e-12);
  // Outside: the border's value minus the distance to the grid.
  EXPECT_NEAR(f.field->value({ -2, 0, 0 }), f.field->value({ 0, 0, 0 }) - 2, 1e-12);
}

TEST(VolumeField, EnclosuresHoldAndCull)
{
  const auto f = VolumeField::build(ball_grid(33), 0.0);
  ASSERT_TRUE(f.field) << f.error;
  double lo = 0, hi = 0;
  ASSERT_TRUE(f.field->enclose({ 1.5, 1.5, 1.5 }, { 1.9, 1.9, 1.9 }, lo, hi));
  EXPECT_LT(hi, 0);
  ASSERT_TRUE(f.field->enclose({ 3, 3, 3 }, { 4, 4, 4 }, lo, hi));
  EXPECT_LT(hi, 0) << "outside the grid";
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3, 3), s(0, 1.5), t(0, 1);
  for (int b = 0; b < 300; ++b)
  {
    const std::array<double, 3> l{ u(rng), u(rng), u(rng) };
    const std::array<double, 3> h{ l[0] + s(rng), l[1] + s(rng), l[2] + s(rng) };
    ASSERT_TRUE(f.field->enclose(l, h, lo, hi));
    for (int i = 0; i < 20; ++i)
    {
      const std::array<double, 3> p{ l[0] + t(rng) * (h[0] - l[0]), l[1] + t(rng) * (h[1] - l[1]),
        l[2] + t(rng) * (h[2] - l[2]) };
      const double v = f.field->value(p);
      ASSERT_LE(lo, v);
      ASSERT_GE(hi, v);
    }
  }
}

TEST(VolumeField, SmallBoxesAreEnclosedByTheirOwnCells)
{
  // v = x on a 65^3 grid of spacing 1/16: a box inside one cell is enclosed by that cell's
  // corners (width one cell), not by its 8^3-cell brick (width eight cells).
  VolumeGrid g;
  g.dims = { 65, 65, 65 };
  g.spacing = { 1.0 / 16, 1.0 / 16, 1.0 / 16 };
  for (int k = 0; k < 65; ++k)
    for (int j = 0; j < 65; ++j)
      for (int i = 0; i < 65; ++i)
        g.values.push_back(i / 16.0);
  const auto f = VolumeField::build(g, 0.0);
  ASSERT_TRUE(f.field) << f.error;
  double lo = 0, hi = 0;
  ASSERT_TRUE(f.field->enclose({ 1.52, 0.5, 0.5 }, { 1.55, 0.55, 0.55 }, lo, hi));
  EXPECT_LE(lo, 1.52);
  EXPECT_GE(hi, 1.55);
  EXPECT_LT(hi - lo, 1.0 / 16 + 1e-9);
  // A large box still holds (the bricks).
  ASSERT_TRUE(f.field->enclose({ 0.1, 0.1, 0.1 }, { 3.9, 3.9, 3.9 }, lo, hi));
  EXPECT_LE(lo, 0.1);
  EXPECT_GE(hi, 3.9);
}

TEST(VolumeField, BadVolumesAreRefused)
{
  VolumeGrid flat = ball_grid(5);
  flat.dims[2] = 1;
  EXPECT_NE(VolumeField::build(flat, 0).error.find("at least 2 samples"), std::string::npos);
  VolumeGrid empty;
  empty.dims = { 4, 4, 4 };
  EXPECT_NE(VolumeField::build(empty, 0).error.find("0 values for 64"), std::string::npos)
    << "a volume without scalars";
  VolumeGrid nan = ball_grid(5);
  nan.values[3] = NAN;
  nan.values[7] = INFINITY;
  EXPECT_NE(VolumeField::build(nan, 0).error.find("2 non-finite"), std::string::npos);
  VolumeGrid spacing = ball_grid(5);
  spacing.spacing[1] = 0;
  EXPECT_NE(VolumeField::build(spacing, 0).error.find("spacing"), std::string::npos);
}

} // namespace
} // namespace frep::shapes
