// frep::mesh::find_solid_bounds and solid_bounds_in: the box of {F >= 0} from interval
// subdivision (Mesh/solid_bounds.h).
#include "Compiler/load_model.h"
#include "Compiler/model.h"
#include "Mesh/solid_bounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

namespace
{

using frep::mesh::SolidBounds;

std::shared_ptr<const frep::Tape> tape_of(const std::string& text,
  std::vector<std::optional<double>> fixed = {})
{
  const frep::LoadedModel loaded = frep::load_model(frep::ModelSource::from_text(text));
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  frep::Specialisation s;
  s.fixed = std::move(fixed);
  return loaded.model->specialise(s);
}

// The box found is the solid's box plus the margin (5% of the extent on each side), up to the
// search's resolution: at most a few percent more.
void expect_box(const SolidBounds& b, std::size_t axis, double lo, double hi, double slack = 0.15)
{
  ASSERT_TRUE(b.bounded());
  const double extent = hi - lo;
  EXPECT_LE(b.box[axis].lo, lo - 0.04 * extent) << "axis " << axis;
  EXPECT_GE(b.box[axis].lo, lo - slack * extent) << "axis " << axis;
  EXPECT_GE(b.box[axis].hi, hi + 0.04 * extent) << "axis " << axis;
  EXPECT_LE(b.box[axis].hi, hi + slack * extent) << "axis " << axis;
}

TEST(SolidBounds, UnitBallGetsOnePlusTheMargin)
{
  const SolidBounds b = frep::mesh::find_solid_bounds(
    tape_of("ball(x[3], a[1]) { ball = 1 - x[1]^2 - x[2]^2 - x[3]^2; }"));
  for (std::size_t k = 0; k < 3; ++k)
  {
    expect_box(b, k, -1.0, 1.0);
  }
  EXPECT_LT(b.seconds, 1.0);
}

TEST(SolidBounds, OffCentreTorus)
{
  // Major radius 3, minor 1, centred at (5, 0, -2): x in [1, 9], y in [-4, 4], z in [-3, -1].
  // As a quartic (hfTorusZ below): its enclosures are loose near the surface (the dependency
  // problem), hence more slack.
  const SolidBounds b = frep::mesh::find_solid_bounds(tape_of(
    "t(x[3], a[1]) { p = (x[1] - 5)^2 + x[2]^2; q = p + (x[3] + 2)^2 + 8; t = 36 * p - q^2; }"));
  expect_box(b, 0, 1.0, 9.0, 0.25);
  expect_box(b, 1, -4.0, 4.0, 0.25);
  expect_box(b, 2, -3.0, -1.0, 0.6); // about 1 unit over the 2 units of height
}

TEST(SolidBounds, Box)
{
  const SolidBounds b = frep::mesh::find_solid_bounds(
    tape_of("b(x[3], a[1]) { array v[3]; v = [-1, 2, 3]; b = hfBlock(x, v, 4, 1, 0.5); }"));
  expect_box(b, 0, -1.0, 3.0);
  expect_box(b, 1, 2.0, 3.0);
  expect_box(b, 2, 3.0, 3.5);
}

TEST(SolidBounds, UnionOfFarApartBallsCoversBoth)
{
  const SolidBounds b = frep::mesh::find_solid_bounds(
    tape_of("u(x[3], a[1]) { u = (1 - (x[1] + 200)^2 - x[2]^2 - x[3]^2) | "
            "(4 - (x[1] - 300)^2 - (x[2] - 5)^2 - x[3]^2); }"));
  expect_box(b, 0, -201.0, 302.0);
  ASSERT_TRUE(b.bounded());
  EXPECT_LE(b.box[1].lo, -1.0);
  EXPECT_GE(b.box[1].hi, 7.0);
  EXPECT_LE(b.box[2].lo, -2.0);
  EXPECT_GE(b.box[2].hi, 2.0);
}

TEST(SolidBounds, HalfSpaceIsUnbounded)
{
  const SolidBounds b = frep::mesh::find_solid_bounds(tape_of("h(x[3], a[1]) { h = x[3] - 1; }"));
  EXPECT_EQ(b.status, SolidBounds::Status::Unbounded);
}

TEST(SolidBounds, EmptySolidIsEmpty)
{
  const SolidBounds b =
    frep::mesh::find_solid_bounds(tape_of("e(x[3], a[1]) { e = -1 - x[1]^2; }"));
  EXPECT_EQ(b.status, SolidBounds::Status::Empty);
}

TEST(SolidBounds, CrossSectionOfAFourDimensionalBall)
{
  // x4 = 0.6 fixed: a ball of radius 0.8 in the free coordinates; a 2-D section too.
  const std::string ball = "b(x[4], a[1]) { b = 1 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2; }";
  const SolidBounds b3 =
    frep::mesh::find_solid_bounds(tape_of(ball, { std::nullopt, std::nullopt, std::nullopt, 0.6 }));
  ASSERT_EQ(b3.box.size(), 3U);
  for (std::size_t k = 0; k < 3; ++k)
  {
    expect_box(b3, k, -0.8, 0.8);
  }
  const SolidBounds b2 =
    frep::mesh::find_solid_bounds(tape_of(ball, { 0.0, std::nullopt, std::nullopt, 0.6 }));
  ASSERT_EQ(b2.box.size(), 2U);
  expect_box(b2, 0, -0.8, 0.8);
  expect_box(b2, 1, -0.8, 0.8);
}

TEST(SolidBounds, NaNEnclosuresDoNotCrash)
{
  // sqrt of a negative part and a division by zero: intervals may be NaN or the whole line.
  const SolidBounds b = frep::mesh::find_solid_bounds(
    tape_of("n(x[3], a[1]) { n = sqrt(1 - x[1]^2) - x[2]^2 / x[3] - 100000; }"));
  EXPECT_TRUE(b.status == SolidBounds::Status::Unbounded ||
              b.status == SolidBounds::Status::Empty || b.bounded());
}

TEST(SolidBounds, ABudgetStopsLooseSearches)
{
  // A search that needs more interval evaluations than its budget stops there and says
  // Unbounded (the callers then fall back): a 6-D ball needs a few thousand, allowed 100.
  const auto ball =
    tape_of("l(x[6], a[1]) { l = 1 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2 - x[5]^2 - x[6]^2; }");
  frep::mesh::SolidBoundsOptions options;
  options.budget = 100;
  const SolidBounds stopped = frep::mesh::find_solid_bounds(ball, options);
  EXPECT_EQ(stopped.status, SolidBounds::Status::Unbounded);
  EXPECT_EQ(stopped.interval_evaluations, 100U);
  const SolidBounds found = frep::mesh::find_solid_bounds(ball);
  ASSERT_TRUE(found.bounded());
  EXPECT_GT(found.interval_evaluations, 100U);
  EXPECT_LT(found.interval_evaluations,
    500000U); // 364,067: work, not seconds (sanitized builds are 10x slower)
}

TEST(SolidBounds, SquareRootsOfSumsOfSquaresAreBounded)
{
  // sqrt(x^2 + y^2) over a cell touching an axis: the sum's lower bound is exactly 0 and stays
  // 0 (it was pushed an ulp below 0, and the square root of a possibly negative number was the
  // whole line, so these were Unbounded). A capped cylinder, a 6-D one, and hfTorusZ.
  const SolidBounds capped = frep::mesh::find_solid_bounds(
    tape_of("c(x[3], a[1]) { c = 1 - sqrt(x[1]^2 + x[2]^2) - x[3]^2; }"));
  for (std::size_t k = 0; k < 3; ++k)
  {
    expect_box(capped, k, -1.0, 1.0);
  }
  const SolidBounds six = frep::mesh::find_solid_bounds(tape_of(
    "l(x[6], a[1]) { l = 1 - sqrt(x[1]^2 + x[2]^2) - x[3]^2 - x[4]^2 - x[5]^2 - x[6]^2; }"));
  ASSERT_TRUE(six.bounded());
  EXPECT_LT(six.interval_evaluations,
    400000U); // 288,599: work, not seconds (sanitized builds are 10x slower)
  const SolidBounds torus = frep::mesh::find_solid_bounds(
    tape_of("t(x[3], a[1]) { array c[3]; c = [5, 0, -2]; t = hfTorusZ(x, c, 3, 1); }"));
  expect_box(torus, 0, 1.0, 9.0, 0.25);
  expect_box(torus, 1, -4.0, 4.0, 0.25);
  expect_box(torus, 2, -3.0, -1.0, 0.6);
}

TEST(SolidBounds, InABoxTheSolidMayTouchIt)
{
  const std::vector<frep::Interval> box(3, frep::Interval{ 0.0, 4.0 });
  const SolidBounds b = frep::mesh::solid_bounds_in(
    tape_of("ball(x[3], a[1]) { ball = 1 - x[1]^2 - x[2]^2 - x[3]^2; }"), box, 5);
  ASSERT_TRUE(b.bounded());
  for (std::size_t k = 0; k < 3; ++k)
  {
    EXPECT_EQ(b.box[k].lo, 0.0);
    EXPECT_GE(b.box[k].hi, 1.0);
    EXPECT_LE(b.box[k].hi, 1.0 + 4.0 / 32.0 + 1e-12);
  }
  EXPECT_THROW(frep::mesh::solid_bounds_in(nullptr, box, 5), std::invalid_argument);
}

} // namespace
