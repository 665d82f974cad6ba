// A profile moved along a path (Project/sweep_text.h): at the path's points the moved profile is
// the profile placed there; a sphere along a segment, projected, is the capsule; a long profile
// turned by the tangent lies along the path; bad paths are refused with the reason. The compiled
// form (Project/sweep_model.h) gives the written text's values bit for bit.
#include "Compiler/load_model.h"
#include "Eval/point_evaluator.h"
#include "Project/path_family.h"
#include "Project/projection.h"
#include "Project/sweep_model.h"
#include "Project/sweep_text.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

namespace
{

using frep::project::SweepPath;

const char* kBall = "ball(x[3], a[1]) { ball = 0.25 - (x[1]^2 + x[2]^2 + x[3]^2); }\n";
// Long along its own z (semi-axes 0.1, 0.1, 0.5).
const char* kCigar = "cigar(x[3], a[1]) { cigar = 1 - ((x[1]/0.1)^2 + (x[2]/0.1)^2 + (x[3]/0.5)^2); }\n";

std::shared_ptr<const frep::Model> sweep_model(const char* profile_text, const std::string& profile,
  const SweepPath& path)
{
  const frep::project::SweepText sweep = frep::project::write_sweep("swept", profile, 1, path);
  EXPECT_TRUE(sweep.ok()) << frep::format_diagnostics(sweep.diagnostics);
  frep::LoadOptions options;
  options.object = "swept";
  const frep::LoadedModel loaded = frep::load_model(
    frep::ModelSource::from_text(std::string(profile_text) + sweep.text, "sweep.hf"), options);
  EXPECT_TRUE(loaded.ok()) << loaded.message() << "\n" << sweep.text;
  return loaded.model;
}

double value(const frep::Model& m, std::vector<double> x)
{
  frep::PointEvaluator e(m.tape());
  return e.value(x);
}

TEST(SweepText, AtThePathsPointsTheProfileIsPlacedThere)
{
  for (const SweepPath::Curve curve : { SweepPath::Curve::Polyline, SweepPath::Curve::CatmullRom })
    for (const bool closed : { false, true })
    {
      SweepPath path;
      path.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0.5 }, { 0, 1, 1 } };
      path.curve = curve;
      path.closed = closed;
      const auto swept = sweep_model(kBall, "ball", path);
      ASSERT_TRUE(swept);
      const int segments = closed ? 4 : 3;
      for (int i = 0; i <= segments; ++i)
      {
        const auto& p = path.points[static_cast<std::size_t>(i % 4)];
        const double t = double(i) / segments;
        EXPECT_NEAR(value(*swept, { p[0], p[1], p[2], t }), 0.25, 1e-8) << i;
        EXPECT_NEAR(value(*swept, { p[0] + 0.3, p[1], p[2], t }), 0.25 - 0.09, 1e-8) << i;
      }
    }
}

TEST(SweepText, SphereAlongASegmentSweepsTheCapsule)
{
  SweepPath path;
  path.points = { { -1, 0, 0 }, { 1, 0.5, 0 } };
  const auto swept = sweep_model(kBall, "ball", path);
  ASSERT_TRUE(swept);
  frep::project::ProjectionOptions options;
  options.band = INFINITY;
  const frep::LoadedModel capsule = frep::project::project(swept, { { 4, 0, 1 } }, options);
  ASSERT_TRUE(capsule.ok()) << capsule.message();
  std::mt19937 random(12);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  for (int i = 0; i < 300; ++i)
  {
    const double p[3] = { u(random), u(random) * 0.6, u(random) * 0.4 };
    const double ap[2] = { p[0] + 1, p[1] };
    const double t = std::clamp((ap[0] * 2 + ap[1] * 0.5) / 4.25, 0.0, 1.0);
    const double q[3] = { ap[0] - 2 * t, ap[1] - 0.5 * t, p[2] };
    const double exact = 0.25 - (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    const double v = value(*capsule.model, { p[0], p[1], p[2] });
    EXPECT_LE(v, exact + 1e-9);
    EXPECT_GE(v, exact - options.tolerance - 1e-9);
  }
}

TEST(SweepText, TangentOrientationLaysTheProfileAlongThePath)
{
  SweepPath path;
  path.points = { { 0, 0, 0 }, { 2, 0, 0 } }; // along x
  path.orientation = SweepPath::Orientation::Tangent;
  const auto along = sweep_model(kCigar, "cigar", path);
  path.orientation = SweepPath::Orientation::Fixed;
  const auto fixed = sweep_model(kCigar, "cigar", path);
  ASSERT_TRUE(along && fixed);
  // At t = 0.5 the centre is (1, 0, 0): turned, the cigar reaches 0.4 along x, not along z.
  EXPECT_GT(value(*along, { 1.4, 0, 0, 0.5 }), 0.0);
  EXPECT_LT(value(*along, { 1.0, 0, 0.4, 0.5 }), 0.0);
  EXPECT_LT(value(*fixed, { 1.4, 0, 0, 0.5 }), 0.0);
  EXPECT_GT(value(*fixed, { 1.0, 0, 0.4, 0.5 }), 0.0);
  // A path straight up (z): the frame's up switches to y, and the cigar lies along z.
  path.points = { { 0, 0, 0 }, { 0, 0, 2 } };
  path.orientation = SweepPath::Orientation::Tangent;
  const auto up = sweep_model(kCigar, "cigar", path);
  ASSERT_TRUE(up);
  EXPECT_GT(value(*up, { 0, 0, 1.4, 0.5 }), 0.0);
  EXPECT_LT(value(*up, { 0.4, 0, 1.0, 0.5 }), 0.0);
}

TEST(SweepModel, GivesTheWrittenSweepsValuesBitForBit)
{
  frep::LoadOptions options;
  options.object = "cigar";
  const frep::LoadedModel cigar =
    frep::load_model(frep::ModelSource::from_text(kCigar, "cigar.hf"), options);
  ASSERT_TRUE(cigar.ok()) << cigar.message();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-0.2, 1.2), t(0.0, 1.0);
  for (const auto orientation : { SweepPath::Orientation::Fixed, SweepPath::Orientation::Tangent })
    for (const auto curve : { SweepPath::Curve::Polyline, SweepPath::Curve::CatmullRom })
    {
      SweepPath path;
      path.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0.5 }, { 0, 1, 1 } };
      path.curve = curve;
      path.closed = curve == SweepPath::Curve::CatmullRom;
      path.orientation = orientation;
      const auto written = sweep_model(kCigar, "cigar", path);
      const frep::LoadedModel compiled = frep::project::sweep_model({ cigar.model, {} }, path);
      ASSERT_TRUE(written && compiled.ok()) << compiled.message();
      EXPECT_EQ(compiled.model->x_dim(), 4);
      frep::PointEvaluator a(written->tape()), b(compiled.model->tape());
      int inside = 0;
      for (int i = 0; i < 2000; ++i)
      {
        const std::vector<double> x = { u(random), u(random), u(random), t(random) };
        const double v = a.value(x), w = b.value(x);
        EXPECT_EQ(std::memcmp(&v, &w, sizeof v), 0) << v << " vs " << w << " at " << i;
        inside += v >= 0;
      }
      EXPECT_GT(inside, 0); // the points reach the cigar somewhere
    }
}

TEST(SweepModel, RefusesABadPathOrAProfileThatIsNot3D)
{
  const frep::LoadedModel four = frep::load_model(frep::ModelSource::from_text(
    "four(x[4], a[1]) { four = 1 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2; }\n", "four.hf"));
  ASSERT_TRUE(four.ok());
  SweepPath path;
  path.points = { { 0, 0, 0 }, { 1, 0, 0 } };
  const frep::LoadedModel bad = frep::project::sweep_model({ four.model, {} }, path);
  EXPECT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("3 free coordinates (four has 4)"), std::string::npos) << bad.message();
  frep::Specialisation fix_x4;
  fix_x4.fixed = { std::nullopt, std::nullopt, std::nullopt, 0.5 };
  EXPECT_TRUE(frep::project::sweep_model({ four.model, fix_x4 }, path).ok());
  path.points = { { 0, 0, 0 }, { 0, 0, 0 } };
  const frep::LoadedModel same = frep::project::sweep_model({ four.model, fix_x4 }, path);
  EXPECT_NE(same.message().find("are the same"), std::string::npos) << same.message();
}

TEST(SweepModel, BoundsHoldThePathsExtentAndTheProfile)
{
  SweepPath line;
  line.points = { { 0, 0, 0 }, { 2, 0, 0 } };
  const std::array<frep::Interval, 3> cube{ frep::Interval{ -0.5, 0.5 }, frep::Interval{ -0.5, 0.5 },
    frep::Interval{ -0.5, 0.5 } };
  auto b = frep::project::sweep_bounds(line, cube);
  EXPECT_EQ(b[0].lo, -0.5);
  EXPECT_EQ(b[0].hi, 2.5);
  EXPECT_EQ(b[1].hi, 0.5);
  line.orientation = SweepPath::Orientation::Tangent; // turned: the corner's distance, sqrt(0.75)
  b = frep::project::sweep_bounds(line, cube);
  EXPECT_NEAR(b[1].hi, std::sqrt(0.75), 1e-15);
  EXPECT_NEAR(b[0].hi, 2 + std::sqrt(0.75), 1e-15);
  // A closed spline overshoots its points: the bounds are its cubics' extremes, sampled finely.
  SweepPath loop;
  loop.points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0.5 }, { 0, 1, 1 } };
  loop.curve = SweepPath::Curve::CatmullRom;
  loop.closed = true;
  const std::array<frep::Interval, 3> point{ frep::Interval{ 0, 0 }, frep::Interval{ 0, 0 },
    frep::Interval{ 0, 0 } };
  b = frep::project::sweep_bounds(loop, point);
  std::vector<std::vector<double>> points;
  for (const auto& p : loop.points)
    points.emplace_back(p.begin(), p.end());
  for (std::size_t a = 0; a < 3; ++a)
  {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& piece : frep::project::catmull_rom_pieces(points, true))
      for (int i = 0; i <= 1000; ++i)
      {
        const double v = frep::project::piece_value(piece[a], i / 1000.0);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    EXPECT_LE(b[a].lo, lo + 1e-12);
    EXPECT_GE(b[a].hi, hi - 1e-12);
      EXPECT_NEAR(b[a].lo, lo, 1e-5);
    EXPECT_NEAR(b[a].hi, hi, 1e-5);
  }
  EXPECT_LT(b[0].lo, 0.0); // the spline overshoots x = 0
}

TEST(SweepText, BadPathsAreRefusedWithTheReason)
{
  const auto refused = [](const std::string& name, const std::string& profile, SweepPath path)
  {
    const frep::project::SweepText t = frep::project::write_sweep(name, profile, 1, path);
    EXPECT_FALSE(t.ok());
    EXPECT_TRUE(t.text.empty());
    return t.diagnostics.empty() ? std::string() : t.diagnostics.front().message;
  };
  SweepPath one;
  one.points = { { 0, 0, 0 } };
  EXPECT_NE(refused("s", "ball", one).find("at least 2 points"), std::string::npos);
  SweepPath two_closed;
  two_closed.points = { { 0, 0, 0 }, { 1, 0, 0 } };
  two_closed.closed = true;
  EXPECT_NE(refused("s", "ball", two_closed).find("closed path needs at least 3"), std::string::npos);
  SweepPath repeated;
  repeated.points = { { 0, 0, 0 }, { 0, 0, 0 }, { 1, 0, 0 } };
  EXPECT_NE(refused("s", "ball", repeated).find("are the same"), std::string::npos);
  SweepPath infinite;
  infinite.points = { { 0, 0, 0 }, { INFINITY, 0, 0 } };
  EXPECT_NE(refused("s", "ball", infinite).find("not finite"), std::string::npos);
  EXPECT_NE(refused("2s", "ball", two_closed).find("identifiers"), std::string::npos);
  EXPECT_NE(refused("ball", "ball", one).find("named like its profile"), std::string::npos);
}

} // namespace

// A ball in (x1, x2, x3) whose centre's x1, x2 are the model's x4, x5, driven along an L of
// (x4, x5) points, as text (write_path_family) and as a composed model (path_family): the same
// values; at the path's points it is the ball there; projected along the family's x6 it is the
// union of the balls along the L (the distance to the L, closed form), within the tolerance;
// bad requests name the reason.
const char* kMoved =
  "moved(x[5], a[1]) { moved = 0.25 - ((x[1] - x[4])^2 + (x[2] - x[5])^2 + x[3]^2); }\n";

void expect_union_of_balls_along_the_l(const std::shared_ptr<const frep::Model>& family)
{
  ASSERT_EQ(family->x_dim(), 6);
  EXPECT_NEAR(value(*family, { 1, 0, 0, 9, 9, 0.5 }), 0.25, 1e-12);    // at the corner
  EXPECT_NEAR(value(*family, { 1, 0.5, 0, 9, 9, 0.75 }), 0.25, 1e-12); // half way up
  EXPECT_NEAR(value(*family, { 0.5, 0, 0.3, 0, 0, 0.25 }), 0.16, 1e-12);
  frep::project::ProjectionOptions projection;
  projection.band = INFINITY;
  const frep::LoadedModel ghost = frep::project::project(family, { { 6, 0, 1 } }, projection);
  ASSERT_TRUE(ghost.ok()) << ghost.message();
  std::mt19937 random(29);
  std::uniform_real_distribution<double> u(-0.6, 1.6);
  for (int i = 0; i < 200; ++i)
  {
    const double p[3] = { u(random), u(random), u(random) * 0.4 };
    // Squared distance of (p1, p2) to the L: the bottom segment or the right one.
    const double bottom = std::pow(std::clamp(p[0], 0.0, 1.0) - p[0], 2) + p[1] * p[1];
    const double right = std::pow(p[0] - 1, 2) + std::pow(std::clamp(p[1], 0.0, 1.0) - p[1], 2);
    const double exact = 0.25 - (std::min(bottom, right) + p[2] * p[2]);
    const double v = value(*ghost.model, { p[0], p[1], p[2], 0, 0 });
    EXPECT_LE(v, exact + 1e-9);
    EXPECT_GE(v, exact - projection.tolerance - 1e-9);
  }
}

TEST(PathFamilyText, AModelAlongAPathThroughItsCoordinatesProjectsToTheUnion)
{
  const std::vector<std::vector<double>> points = { { 0, 0 }, { 1, 0 }, { 1, 1 } };
  const std::vector<frep::project::PathPiece> pieces = frep::project::polyline_pieces(points, false);
  const frep::project::SweepText family =
    frep::project::write_path_family("family", "moved", 5, 1, { 4, 5 }, pieces);
  ASSERT_TRUE(family.ok()) << frep::format_diagnostics(family.diagnostics);
  frep::LoadOptions options;
  options.object = "family";
  const frep::LoadedModel text = frep::load_model(
    frep::ModelSource::from_text(std::string(kMoved) + family.text, "family.hf"), options);
  ASSERT_TRUE(text.ok()) << text.message() << "\n" << family.text;
  expect_union_of_balls_along_the_l(text.model);

  const frep::LoadedModel moved = frep::load_model(frep::ModelSource::from_text(kMoved, "moved.hf"));
  ASSERT_TRUE(moved.ok()) << moved.message();
  const frep::LoadedModel composed = frep::project::path_family(moved.model, { 4, 5 }, pieces, {});
  ASSERT_TRUE(composed.ok()) << composed.message();
  expect_union_of_balls_along_the_l(composed.model);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  for (int i = 0; i < 100; ++i) // the composed tape computes what the text computes
  {
    const std::vector<double> x = { u(random), u(random), u(random), u(random), u(random), u(random) };
    EXPECT_NEAR(value(*composed.model, x), value(*text.model, x), 1e-12);
  }
  for (const auto& [coordinates, why] :
    std::vector<std::pair<std::vector<int>, std::string>>{ { { 4, 4 }, "given twice" },
      { { 6 }, "x6 is not one of x1..x5" }, { {}, "at least one" } })
  {
    const frep::LoadedModel bad = frep::project::path_family(moved.model, coordinates, pieces, {});
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(bad.message().find(why), std::string::npos) << bad.message();
  }
  EXPECT_NE(frep::project::path_family(moved.model, { 4 }, pieces, {}).message().find(
              "has 2 coordinates, the path 1"),
    std::string::npos);
}

TEST(PathFamilyText, BadRequestsNameTheReason)
{
  const auto refused = [](const std::vector<int>& coordinates,
                         const std::vector<std::vector<double>>& path, const char* why)
  {
    const frep::project::SweepText bad = frep::project::write_path_family(
      "family", "moved", 5, 1, coordinates, frep::project::polyline_pieces(path, true));
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(frep::format_diagnostics(bad.diagnostics).find(why), std::string::npos)
      << frep::format_diagnostics(bad.diagnostics);
  };
  const std::vector<std::vector<double>> triangle = { { 0, 0 }, { 1, 0 }, { 1, 1 } };
  refused({ 4, 4 }, triangle, "given twice");
  refused({ 6 }, { { 0 }, { 1 }, { 2 } }, "x6 is not one of x1..x5");
  refused({ 4, 5 }, { { 0, 0 } }, "at least one piece");
  refused({ 4 }, triangle, "has 2 coordinates, the path 1");
  refused({}, triangle, "at least one of the source's coordinates");
}
