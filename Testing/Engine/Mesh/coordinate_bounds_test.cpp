// frep::mesh::find_coordinate_bounds: the default interval of every coordinate of an n-D model
// (Mesh/coordinate_bounds.h), by its three rules, and readable().
#include "Compiler/load_model.h"
#include "Compiler/model.h"
#include "Mesh/coordinate_bounds.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

namespace
{

using frep::Interval;
using frep::mesh::CoordinateBounds;

std::shared_ptr<const frep::Model> model_of(const std::string& text)
{
  const frep::LoadedModel loaded = frep::load_model(frep::ModelSource::from_text(text));
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  return loaded.model;
}

CoordinateBounds bounds_of(const std::string& text,
  std::vector<std::optional<Interval>> given = {},
  std::vector<double> parameters = {})
{
  const auto model = model_of(text);
  return frep::mesh::find_coordinate_bounds(*model, parameters, given, Interval{ -10, 10 });
}

// [lo, hi] plus the margin, up to the search's resolution and the rounding.
void expect_about(const Interval& r, double lo, double hi)
{
  const double extent = hi - lo;
  EXPECT_LE(r.lo, lo - 0.04 * extent);
  EXPECT_GE(r.lo, lo - 0.15 * extent);
  EXPECT_GE(r.hi, hi + 0.04 * extent);
  EXPECT_LE(r.hi, hi + 0.15 * extent);
}

const char* Blend = R"(my_model(x[4], a[1])
{
  ba = 1 - (x[1] + 3)^2 - x[2]^2 - x[3]^2;
  bb = 1 - (x[1] - 3)^2 - x[2]^2 - x[3]^2;
  my_model = (1 - x[4]) * ba + x[4] * bb;
})";

TEST(CoordinateBounds, ABounded4DSolidBoundsEveryCoordinate)
{
  const CoordinateBounds b = bounds_of(
    "my_model(x[4], a[1]) { my_model = a[1]^2 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2; }", {}, { 2.0 });
  EXPECT_EQ(b.rule, CoordinateBounds::Rule::Whole);
  ASSERT_EQ(b.ranges.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
  {
    EXPECT_TRUE(b.found[i]);
    expect_about(b.ranges[i], -2.0, 2.0); // a[1] = 2: the parameters count
  }
  EXPECT_TRUE(b.note.empty());
}

TEST(CoordinateBounds, AGivenIntervalIsKept)
{
  const CoordinateBounds b = bounds_of(
    "my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }", { Interval{ -5, 7 } });
  EXPECT_FALSE(b.found[0]);
  EXPECT_EQ(b.ranges[0].lo, -5.0);
  EXPECT_EQ(b.ranges[0].hi, 7.0);
  expect_about(b.ranges[2], -1.0, 1.0);
}

TEST(CoordinateBounds, AHalfSpaceKeepsTheFallbackAndSaysWhy)
{
  const CoordinateBounds b = bounds_of("my_model(x[3], a[1]) { my_model = x[1]; }");
  EXPECT_EQ(b.rule, CoordinateBounds::Rule::None);
  EXPECT_FALSE(b.found[1]);
  EXPECT_EQ(b.ranges[1].lo, -10.0);
  EXPECT_NE(b.note.find("reaches the edge of [-1000, 1000]"), std::string::npos) << b.note;
}

TEST(CoordinateBounds, SectionsAtTheCornersOfAGivenInterval)
{
  // x4 in [0, 1]: ball A at x4 = 0, B at x4 = 1, nothing at the centre.
  const CoordinateBounds b =
    bounds_of(Blend, { std::nullopt, std::nullopt, std::nullopt, Interval{ 0, 1 } });
  EXPECT_EQ(b.rule, CoordinateBounds::Rule::Sections);
  // The union of the two balls' boxes, each with its own margin (5% of 2 on each side).
  EXPECT_LE(b.ranges[0].lo, -4.08);
  EXPECT_GE(b.ranges[0].lo, -4.3);
  EXPECT_GE(b.ranges[0].hi, 4.08);
  EXPECT_LE(b.ranges[0].hi, 4.3);
  expect_about(b.ranges[1], -1.0, 1.0);
  EXPECT_FALSE(b.found[3]);
  EXPECT_EQ(b.ranges[3].lo, 0.0);
  EXPECT_EQ(b.ranges[3].hi, 1.0);
  EXPECT_NE(b.note.find("sections over x4..'s intervals"), std::string::npos) << b.note;
}

TEST(CoordinateBounds, WithoutAnIntervalOnlyTheCentreSection)
{
  // x4 keeps the fallback [-10, 10]; its corners are extrapolations: only x4 = 0, ball A.
  const CoordinateBounds b = bounds_of(Blend);
  EXPECT_EQ(b.rule, CoordinateBounds::Rule::Sections);
  expect_about(b.ranges[0], -4.0, -2.0);
  EXPECT_EQ(b.ranges[3].lo, -10.0);
  EXPECT_EQ(b.ranges[3].hi, 10.0);
}

TEST(CoordinateBounds, AnUnboundedCentreSectionKeepsTheFallback)
{
  const CoordinateBounds b = bounds_of("my_model(x[4], a[1]) { my_model = x[4] - x[1]; }");
  EXPECT_EQ(b.rule, CoordinateBounds::Rule::None);
  EXPECT_FALSE(b.found[0]);
  EXPECT_NE(b.note.find("centre"), std::string::npos) << b.note;
}

TEST(CoordinateBounds, EverythingGivenSearchesNothing)
{
  const CoordinateBounds b =
    bounds_of("my_model(x[2], a[1]) { my_model = x[1]; }", { Interval{ 0, 1 }, Interval{ 2, 3 } });
  EXPECT_EQ(b.rule, CoordinateBounds::Rule::None);
  EXPECT_TRUE(b.note.empty());
  EXPECT_EQ(b.ranges[1].lo, 2.0);
}

TEST(CoordinateBounds, ABadFallbackThrows)
{
  const auto model = model_of("my_model(x[3], a[1]) { my_model = 1; }");
  EXPECT_THROW(
    frep::mesh::find_coordinate_bounds(*model, {}, {}, Interval{ 1, -1 }), std::invalid_argument);
}

TEST(CoordinateBounds, ReadableRoundsOutwardsToThreeDigits)
{
  const Interval r = frep::mesh::readable({ -7.57205, 7.79378 });
  EXPECT_EQ(r.lo, -7.6); // extent 15.4: steps of 0.1
  EXPECT_EQ(r.hi, 7.8);
  const Interval big = frep::mesh::readable({ -1234.5, 987.6 });
  EXPECT_EQ(big.lo, -1240.0);
  EXPECT_EQ(big.hi, 990.0);
  const Interval point = frep::mesh::readable({ 2.0, 2.0 });
  EXPECT_EQ(point.lo, 2.0); // no extent: as it is
}

} // namespace
