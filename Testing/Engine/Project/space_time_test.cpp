// The questions asked of space-time against analytic answers: two spheres approaching at known
// speeds first touch at the analytic time, a point is inside a pulsating sphere during the
// analytic intervals, a section's volume and area follow the closed forms; bad requests get
// clear errors.
#include "Compiler/load_model.h"
#include "Project/space_time.h"

#include "project_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{

using frep::Interval;
using frep::project::CoordinateRange;
using frep::project::SpaceTimeOptions;

using frep::project::test::model_of;

// Radius 0.5 from x = -2 at speed 1, radius 0.7 from x = 2 at speed 2 (time is x[4]): they
// touch when 4 - 3t = 1.2.
const char* kLeft = "left(x[4], a[1]) { left = 0.25 - ((x[1] + 2 - x[4])^2 + x[2]^2 + x[3]^2); }";
const char* kRight =
  "right(x[4], a[1]) { right = 0.49 - ((x[1] - 2 + 2*x[4])^2 + x[2]^2 + x[3]^2); }";
const std::vector<Interval> kSpace = { { -3, 3 }, { -1, 1 }, { -1, 1 } };

TEST(SpaceTime, ApproachingSpheresFirstTouchAtTheAnalyticTime)
{
  SpaceTimeOptions options;
  options.time_tolerance = 1e-4;
  const auto contact =
    frep::project::first_contact(model_of(kLeft), model_of(kRight), { 4, 0.0, 2.0 }, kSpace, options);
  ASSERT_TRUE(contact.ok()) << contact.error;
  ASSERT_TRUE(contact.found);
  const double exact = 2.8 / 3.0;
  EXPECT_LE(contact.time_lo, exact + 1e-12);
  EXPECT_GE(contact.time, exact - 1e-12); // a common point exists only once they overlap
  EXPECT_LE(contact.time - contact.time_lo, options.time_tolerance);
  EXPECT_LE(contact.time - exact, 2 * options.time_tolerance);
  ASSERT_EQ(contact.where.size(), 4u);
  EXPECT_EQ(contact.where[3], contact.time);
  // Where: between the two centres, near the touching point x = -2 + t + 0.5.
  EXPECT_NEAR(contact.where[0], -2 + exact + 0.5, 0.01);
  EXPECT_NEAR(contact.where[1], 0.0, 0.05);
  std::cout << "[ contact ] t in [" << contact.time_lo << ", " << contact.time << "] after "
            << contact.boxes << " boxes\n";
}

TEST(SpaceTime, SpheresThatPassApartNeverTouch)
{
  // The right sphere passes at y = 1.5: at least 1.5 - 1.2 apart.
  const char* passing =
    "passing(x[4], a[1]) { passing = 0.49 - ((x[1] - 2 + 2*x[4])^2 + (x[2] - 1.5)^2 + x[3]^2); }";
  const auto contact = frep::project::first_contact(model_of(kLeft), model_of(passing),
    { 4, 0.0, 2.0 }, { { -3, 3 }, { -1, 3 }, { -1, 1 } });
  ASSERT_TRUE(contact.ok()) << contact.error;
  EXPECT_FALSE(contact.found);
}

TEST(SpaceTime, PointIsInsideAPulsatingSphereDuringTheAnalyticIntervals)
{
  // Radius 0.5 + 0.3 sin(2 pi t); the point at distance 0.6 is inside while sin(2 pi t) >= 1/3.
  const auto pulsing = model_of("pulse(x[4], a[1]) { r = 0.5 + 0.3*sin(6.283185307179586*x[4]);"
                                " pulse = r - sqrt(x[1]^2 + x[2]^2 + x[3]^2); }");
  SpaceTimeOptions options;
  options.time_tolerance = 1e-6;
  const auto p = frep::project::presence(*pulsing, { 4, 0.0, 2.0 }, { 0.6, 0.0, 0.0, 0.0 }, options);
  ASSERT_TRUE(p.ok()) << p.error;
  ASSERT_EQ(p.inside.size(), 2u);
  const double a = std::asin(1.0 / 3.0) / (2 * M_PI), b = 0.5 - a;
  for (int k = 0; k < 2; ++k)
  {
    EXPECT_NEAR(p.inside[k].lo, a + k, options.time_tolerance);
    EXPECT_NEAR(p.inside[k].hi, b + k, options.time_tolerance);
  }
  // Inside all the time, and never.
  const auto centre = frep::project::presence(*pulsing, { 4, 0.0, 2.0 }, { 0.0, 0.0, 0.0, 0.0 });
  ASSERT_EQ(centre.inside.size(), 1u);
  EXPECT_EQ(centre.inside[0].lo, 0.0);
  EXPECT_EQ(centre.inside[0].hi, 2.0);
  EXPECT_TRUE(frep::project::presence(*pulsing, { 4, 0.0, 2.0 }, { 0.9, 0.0, 0.0, 0.0 }).inside.empty());
}

TEST(SpaceTime, SectionVolumeAndAreaFollowTheClosedForms)
{
  const auto pulsing = model_of("pulse(x[4], a[1]) { r = 0.5 + 0.3*x[4];"
                                " pulse = r - sqrt(x[1]^2 + x[2]^2 + x[3]^2); }");
  const auto volumes = frep::project::section_measures(
    *pulsing, { 4, 0.0, 1.0 }, { { -1, 1 }, { -1, 1 }, { -1, 1 } }, 5, 65);
  ASSERT_TRUE(volumes.ok()) << volumes.error;
  ASSERT_EQ(volumes.table.size(), 5u);
  EXPECT_EQ(volumes.dimension, 3);
  for (const auto& m : volumes.table)
  {
    const double r = 0.5 + 0.3 * m.time;
    EXPECT_NEAR(m.measure, 4.0 / 3.0 * M_PI * r * r * r, 0.01 * r * r * r) << m.time;
    EXPECT_EQ(m.components, 1u);
  }
  EXPECT_EQ(volumes.table.back().time, 1.0);

  // Two discs in (x, y) moving apart: area 2 pi r^2, two loops once they part.
  const auto discs = model_of("discs(x[3], a[1]) { d = 0.3 + 0.4*x[3];"
                              " discs = max(0.25 - (x[1]-d)^2 - x[2]^2, 0.25 - (x[1]+d)^2 - x[2]^2); }");
  const auto areas =
    frep::project::section_measures(*discs, { 3, 0.0, 1.0 }, { { -2, 2 }, { -1, 1 } }, 3, 201);
  ASSERT_TRUE(areas.ok()) << areas.error;
  EXPECT_EQ(areas.dimension, 2);
  EXPECT_EQ(areas.table[0].components, 1u); // centres 0.6 apart: one merged piece
  EXPECT_EQ(areas.table[2].components, 2u); // 1.4 apart: two discs
  EXPECT_NEAR(areas.table[2].measure, 2 * M_PI * 0.25, 0.01);
}

TEST(SpaceTime, TopologyEventsOfAnalyticFamiliesAreFoundAtTheAnalyticTime)
{
  // Two balls of radius 0.5 at +-x4 (max: their union): one piece until they part at x4 = 0.5.
  const auto parting = model_of("parting(x[4], a[1]) { parting = max(0.25 - ((x[1]-x[4])^2 + x[2]^2"
                                " + x[3]^2), 0.25 - ((x[1]+x[4])^2 + x[2]^2 + x[3]^2)); }");
  const double h = 4.0 / 64; // the grid's spacing
  const auto split = frep::project::topology_events(
    *parting, { 4, 0.2, 0.8 }, { { -2, 2 }, { -1, 1 }, { -1, 1 } }, 4, 65, 1e-4);
  ASSERT_TRUE(split.ok()) << split.error;
  ASSERT_EQ(split.events.size(), 1u);
  const auto& e = split.events[0];
  EXPECT_EQ(e.components_before, 1u);
  EXPECT_EQ(e.components_after, 2u);
  EXPECT_LE(e.after - e.before, 1e-4);
  EXPECT_NEAR(e.after, 0.5, h);
  EXPECT_EQ(split.samples.front().components, 1u);
  EXPECT_EQ(split.samples.back().components, 2u);

  // A torus of ring radius 0.6 whose tube grows as 0.3 + 0.6 x4: its hole closes (genus 1 -> 0)
  // when the tube reaches the ring, x4 = 0.5.
  const auto closing = model_of("closing(x[4], a[1]) { r = 0.3 + 0.6*x[4];"
                                " closing = r*r - ((sqrt(x[1]^2 + x[2]^2) - 0.6)^2 + x[3]^2); }");
  const double g = 3.2 / 80;
  const auto shut = frep::project::topology_events(
    *closing, { 4, 0.0, 1.0 }, { { -1.6, 1.6 }, { -1.6, 1.6 }, { -1.2, 1.2 } }, 5, 81, 1e-3);
  ASSERT_TRUE(shut.ok()) << shut.error;
  ASSERT_EQ(shut.events.size(), 1u);
  EXPECT_EQ(shut.events[0].genus_before, 1);
  EXPECT_EQ(shut.events[0].genus_after, 0);
  EXPECT_EQ(shut.events[0].components_after, 1u);
  EXPECT_NEAR(shut.events[0].after, 0.5, 2 * g / 0.6); // the hole's radius 0.3 - 0.6 (x4 - 0.5)
  std::cout << "[ topology ] parted in [" << e.before << ", " << e.after << "], hole closed in ["
            << shut.events[0].before << ", " << shut.events[0].after << "]\n";

  EXPECT_NE(frep::project::topology_events(*parting, { 4, 0, 1 }, { { -2, 2 }, { -1, 1 }, { -1, 1 } },
              1, 17, 1e-3).error.find("at least two times"),
    std::string::npos);
  EXPECT_NE(frep::project::topology_events(*parting, { 4, 0, 1 }, { { -2, 2 }, { -1, 1 }, { -1, 1 } },
              3, 17, 0).error.find("resolution must be > 0"),
    std::string::npos);
}

// The bisection alone, on a family whose topology is known everywhere: one piece below 0.3,
// two up to 0.7, then two pieces of genus 1. Both changes in the one step [0, 1] are found,
// nearest first, each within the resolution of the analytic place, with the probes that
// bisection costs; ends of the same shape give nothing.
TEST(SpaceTime, TopologyChangesBetweenTwoEndsAreEachLocated)
{
  using frep::mesh::ShapeTopology;
  int probes = 0;
  const auto shape_at = [&](double u)
  {
    ++probes;
    return u < 0.3 ? ShapeTopology{ 1, 0 } : u < 0.7 ? ShapeTopology{ 2, 0 } : ShapeTopology{ 2, 1 };
  };
  const double resolution = 1.0 / 1024;
  const auto events = frep::project::locate_topology_changes(
    0.0, shape_at(0.0), 1.0, shape_at(1.0), resolution, shape_at);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_LE(events[0].before, 0.3);
  EXPECT_GT(events[0].after, 0.3);
  EXPECT_LE(events[0].after - events[0].before, resolution);
  EXPECT_EQ(events[0].components_before, 1u);
  EXPECT_EQ(events[0].components_after, 2u);
  EXPECT_LE(events[1].before, 0.7);
  EXPECT_GT(events[1].after, 0.7);
  EXPECT_EQ(events[1].genus_before, 0);
  EXPECT_EQ(events[1].genus_after, 1);
  EXPECT_LE(probes, 2 + 2 * 11);
  EXPECT_TRUE(frep::project::locate_topology_changes(
    0.0, shape_at(0.0), 0.2, shape_at(0.2), resolution, shape_at).empty());
}

// topology_events under a run control: progress rises to 1; a progress that returns false stops
// it with nothing reported.
TEST(SpaceTime, TopologyEventsReportProgressAndStop)
{
  const auto parting = model_of("p(x[4], a[1]) { p = max(0.25 - ((x[1] - x[4])^2 + x[2]^2 + x[3]^2),"
                                " 0.25 - ((x[1] + x[4])^2 + x[2]^2 + x[3]^2)); }");
  const std::vector<Interval> box{ { -2, 2 }, { -1, 1 }, { -1, 1 } };
  SpaceTimeOptions options;
  std::vector<double> seen;
  options.progress = [&](double f) { seen.push_back(f); return true; };
  const auto done = frep::project::topology_events(*parting, { 4, 0, 1 }, box, 4, 33, 1e-2, options);
  ASSERT_TRUE(done.ok()) << done.error;
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  options.progress = [](double) { return false; };
  const auto stopped = frep::project::topology_events(*parting, { 4, 0, 1 }, box, 4, 33, 1e-2, options);
  EXPECT_TRUE(stopped.cancelled);
  EXPECT_FALSE(stopped.ok());
  EXPECT_TRUE(stopped.samples.empty() && stopped.events.empty());
}

TEST(SpaceTime, BadRequestsGetClearErrors)
{
  const auto left = model_of(kLeft);
  const auto flat = model_of("flat(x[3], a[1]) { flat = 1 - x[1]^2; }");
  EXPECT_NE(frep::project::first_contact(left, flat, { 4, 0, 1 }, kSpace).error.find("same space-time"),
    std::string::npos);
  EXPECT_NE(frep::project::first_contact(left, left, { 5, 0, 1 }, kSpace).error.find("time x5"),
    std::string::npos);
  EXPECT_NE(frep::project::first_contact(left, left, { 4, 1, 0 }, kSpace).error.find("lo <= hi"),
    std::string::npos);
  EXPECT_NE(frep::project::first_contact(left, left, { 4, 0, 1 }, { { 0, 1 } }).error.find("the box has 1"),
    std::string::npos);
  SpaceTimeOptions zero;
  zero.time_tolerance = 0;
  EXPECT_NE(frep::project::presence(*left, { 4, 0, 1 }, { 0, 0, 0, 0 }, zero).error.find("time tolerance"),
    std::string::npos);
  EXPECT_NE(frep::project::presence(*left, { 4, 0, 1 }, { 0, 0 }).error.find("the point has 2"),
    std::string::npos);
  const auto five = model_of("five(x[5], a[1]) { five = 1; }");
  EXPECT_NE(frep::project::section_measures(*five, { 5, 0, 1 }, { { 0, 1 }, { 0, 1 }, { 0, 1 }, { 0, 1 } }, 2, 8)
              .error.find("2 or 3 coordinates besides time"),
    std::string::npos);
}

} // namespace
