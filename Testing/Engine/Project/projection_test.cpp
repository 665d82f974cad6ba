// Projection against analytic answers (issue 28's tests): a 4-D ball projected along x4 is the
// 3-D ball, a moving sphere sweeps a capsule, a rotating box's sweep holds every sampled frame;
// the enclosures hold the values, the gradient is F's at the maximiser, bad requests are refused.
#include "Compiler/load_model.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"
#include "Project/projection.h"

#include "project_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

namespace
{

using frep::project::CoordinateRange;
using frep::project::ProjectionOptions;

using frep::project::test::model_of;

std::shared_ptr<const frep::Model> projected(const std::string& text,
  const std::vector<CoordinateRange>& axes, const ProjectionOptions& options = {})
{
  const frep::LoadedModel loaded = frep::project::project(model_of(text), axes, options);
  EXPECT_TRUE(loaded.ok()) << loaded.message();
  return loaded.model;
}

double value(const frep::Model& model, std::vector<double> x)
{
  frep::PointEvaluator e(model.tape());
  return e.value(x);
}

// The projector's contract on a value v of P (projector.h): within the tolerance below P, unless
// the search ended at the band's ends (v >= band: P >= v; v < -band: P < -band + tolerance).
void expect_contract(double v, double p, const frep::project::ProjectorOptions& o,
  const std::string& where)
{
  EXPECT_LE(v, p + 1e-12) << where; // F at some point: never above P
  if (v >= o.band)
    return;
  if (v < -o.band)
    EXPECT_LT(p, -o.band + o.tolerance) << where;
  else
    EXPECT_GE(v, p - o.tolerance) << where;
}

const char* kBall4 = "ball4(x[4], a[1]) { ball4 = 1 - (x[1]^2 + x[2]^2 + x[3]^2 + x[4]^2); }";

TEST(Projection, FourDimensionalBallAlongX4IsTheThreeDimensionalBall)
{
  ProjectionOptions options;
  options.tolerance = 1e-6;
  const auto ball = projected(kBall4, { { 4, -2.0, 1.5 } }, options);
  ASSERT_TRUE(ball);
  EXPECT_EQ(ball->x_dim(), 3);
  EXPECT_EQ(ball->name(), "ball4_projection");
  std::mt19937 random(4);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int i = 0; i < 2000; ++i)
  {
    const double x = u(random), y = u(random), z = u(random);
    const double exact = 1 - (x * x + y * y + z * z);
    expect_contract(value(*ball, { x, y, z }), exact, options, "ball");
  }
}

TEST(Projection, ValuesAreWithinTheToleranceEverywhereWithoutABand)
{
  ProjectionOptions options;
  options.tolerance = 1e-6;
  options.band = INFINITY;
  const auto ball = projected(kBall4, { { 4, -2.0, 1.5 } }, options);
  ASSERT_TRUE(ball);
  std::mt19937 random(41);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int far = 0;
  for (int i = 0; i < 1000; ++i)
  {
    const double x = u(random), y = u(random), z = u(random);
    const double exact = 1 - (x * x + y * y + z * z);
    const double v = value(*ball, { x, y, z });
    EXPECT_LE(v, exact + 1e-15);
    EXPECT_GE(v, exact - options.tolerance);
    far += std::abs(exact) > 0.1 ? 1 : 0;
  }
  EXPECT_GT(far, 500); // most points are beyond the default band, where it would stop early
}

TEST(Projection, KeptCoordinatesKeepTheirNumbersWhenAsked)
{
  ProjectionOptions options;
  options.keep_coordinates = true;
  const auto ball = projected(kBall4, { { 2, -1.0, 1.0 } }, options);
  ASSERT_TRUE(ball);
  EXPECT_EQ(ball->x_dim(), 4);
  for (const double ignored : { -5.0, 0.0, 3.0 })
    EXPECT_NEAR(value(*ball, { 0.5, ignored, 0.25, 0.1 }), 1 - (0.25 + 0.0625 + 0.01), 1e-4);
}

TEST(Projection, MovingSphereSweepsACapsule)
{
  // A sphere of radius 0.5 whose centre goes from (-1, 0, 0) to (1, 0.5, 0) as x4 goes 0 -> 1.
  const char* moving = "moving(x[4], a[1]) { cx = -1 + 2*x[4]; cy = 0.5*x[4];"
                       " moving = 0.25 - ((x[1]-cx)^2 + (x[2]-cy)^2 + x[3]^2); }";
  ProjectionOptions options;
  options.tolerance = 1e-5;
  const auto swept = projected(moving, { { 4, 0.0, 1.0 } }, options);
  ASSERT_TRUE(swept);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 2000; ++i)
  {
    const double p[3] = { u(random), u(random) * 0.6, u(random) * 0.5 };
    // The squared distance to the segment from a = (-1, 0, 0) to b = (1, 0.5, 0).
    const double d[3] = { 2.0, 0.5, 0.0 };
    const double ap[3] = { p[0] + 1.0, p[1], p[2] };
    const double t =
      std::clamp((ap[0] * d[0] + ap[1] * d[1]) / (d[0] * d[0] + d[1] * d[1]), 0.0, 1.0);
    const double q[3] = { ap[0] - t * d[0], ap[1] - t * d[1], ap[2] };
    const double capsule = 0.25 - (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    expect_contract(value(*swept, { p[0], p[1], p[2] }), capsule, options, "capsule");
  }
}

TEST(Projection, RotatingBoxSweepHoldsEverySampledFrame)
{
  // A 1 x 0.2 x 0.2 box turning a quarter turn about z as x4 goes 0 -> 1.
  const char* turning =
    "turning(x[4], a[1]) { an = 1.5707963267948966*x[4]; cs = cos(an); sn = sin(an);"
    " u = cs*x[1] + sn*x[2]; v = -sn*x[1] + cs*x[2];"
    " turning = min(min(0.5 - abs(u), 0.1 - abs(v)), 0.1 - abs(x[3])); }";
  const auto frames = model_of(turning);
  ProjectionOptions options;
  options.tolerance = 1e-4;
  const auto swept = projected(turning, { { 4, 0.0, 1.0 } }, options);
  ASSERT_TRUE(swept && frames);
  frep::PointEvaluator frame(frames->tape());
  std::mt19937 random(6);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  int inside_some_frame = 0;
  for (int i = 0; i < 3000; ++i)
  {
    const double x = u(random), y = u(random), z = u(random) * 0.2;
    double best = -INFINITY;
    for (int f = 0; f < 64; ++f)
      best = std::max(best, frame.value(std::vector<double>{ x, y, z, f / 63.0 }));
    const double v = value(*swept, { x, y, z });
    if (v >= -options.band) // beyond the band the value is only a lower bound of P
      EXPECT_GE(v, std::min(best, options.band) - options.tolerance) << x << " " << y << " " << z;
    else
      EXPECT_LT(best, -options.band + options.tolerance);
    if (best >= 0)
    {
      ++inside_some_frame;
      EXPECT_GE(v, 0.0); // every frame's solid is inside the sweep
    }
  }
  EXPECT_GT(inside_some_frame, 100);
}

TEST(Projection, EnclosuresHoldThePointValues)
{
  const auto ball = projected(kBall4, { { 4, -0.5, 0.75 } });
  ASSERT_TRUE(ball);
  frep::IntervalEvaluator intervals(ball->tape());
  frep::PointEvaluator points(ball->tape());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.2, 1.2), w(0.01, 0.5);
  for (int i = 0; i < 300; ++i)
  {
    std::vector<frep::Interval> box;
    for (int k = 0; k < 3; ++k)
    {
      const double lo = u(random);
      box.push_back({ lo, lo + w(random) });
    }
    const frep::IntervalResult r = intervals.evaluate(box);
    for (int j = 0; j < 20; ++j)
    {
      std::vector<double> x;
      for (const frep::Interval& b : box)
        x.push_back(b.lo + (b.hi - b.lo) * (j / 19.0));
      const double v = points.value(x);
      EXPECT_GE(v, r.value.lo);
      EXPECT_LE(v, r.value.hi);
    }
  }
}

TEST(Projection, GradientIsTheSourcesAtTheMaximiser)
{
  const auto ball = projected(kBall4, { { 4, 0.2, 1.0 } }); // the maximiser is x4 = 0.2
  ASSERT_TRUE(ball);
  frep::GradientEvaluator gradients(ball->tape());
  std::vector<double> g(3);
  const double v = gradients.evaluate(std::vector<double>{ 0.3, -0.4, 0.5 }, g);
  EXPECT_NEAR(v, 1 - (0.09 + 0.16 + 0.25 + 0.04), 1e-4);
  EXPECT_NEAR(g[0], -0.6, 1e-9);
  EXPECT_NEAR(g[1], 0.8, 1e-9);
  EXPECT_NEAR(g[2], -1.0, 1e-9);
}

TEST(Projection, ProjectedBallMeshesWatertight)
{
  const auto ball = projected(kBall4, { { 4, -1.0, 1.0 } });
  ASSERT_TRUE(ball);
  const double lo[3] = { -1.3, -1.3, -1.3 }, hi[3] = { 1.3, 1.3, 1.3 };
  const std::int64_t samples[3] = { 33, 33, 33 };
  const frep::mesh::ExtractResult mesh =
    frep::mesh::extract_surface(ball->tape(), frep::box_grid(lo, hi, samples));
  ASSERT_TRUE(mesh.ok()) << mesh.error;
  const frep::mesh::MeshTopology topology = frep::mesh::analyse_topology(mesh.surface);
  EXPECT_TRUE(topology.watertight_and_oriented());
  EXPECT_EQ(topology.components, 1u);
  EXPECT_EQ(topology.euler_characteristic, 2);
  EXPECT_NEAR(topology.signed_volume, 4.0 / 3.0 * M_PI, 0.05);
  EXPECT_GT(mesh.statistics.boxes_culled, 0u); // the enclosures cull
}

TEST(Projection, FurtherOperationsTakeTheProjection)
{
  // The projection sliced again: x3 fixed at 0.5 leaves a disc of radius sqrt(0.75).
  const auto ball = projected(kBall4, { { 4, -1.0, 1.0 } });
  ASSERT_TRUE(ball);
  frep::Specialisation slice;
  slice.fixed = { std::nullopt, std::nullopt, 0.5 };
  frep::PointEvaluator disc(ball->specialise(slice));
  EXPECT_NEAR(disc.value(std::vector<double>{ 0.0, 0.0 }), 0.75, 1e-4);
  EXPECT_LT(disc.value(std::vector<double>{ 0.9, 0.0 }), 0.0);
}

TEST(Projection, BadRequestsAreRefusedClearly)
{
  const auto ball = model_of(kBall4);
  const auto refused = [&](std::vector<CoordinateRange> axes, ProjectionOptions options = {})
  {
    const frep::LoadedModel r = frep::project::project(ball, axes, options);
    EXPECT_FALSE(r.ok());
    return r.message();
  };
  EXPECT_NE(refused({ { 5, 0, 1 } }).find("ball4 has x[4]"), std::string::npos);
  EXPECT_NE(refused({ { 0, 0, 1 } }).find("cannot project along x0"), std::string::npos);
  EXPECT_NE(refused({ { 4, 1, 0 } }).find("lo <= hi"), std::string::npos);
  EXPECT_NE(refused({ { 4, 0, INFINITY } }).find("finite"), std::string::npos);
  EXPECT_NE(refused({ { 4, 0, 1 }, { 4, 0, 1 } }).find("projected twice"), std::string::npos);
  EXPECT_NE(refused({}).find("no coordinate"), std::string::npos);
  EXPECT_NE(refused({ { 1, 0, 1 }, { 2, 0, 1 }, { 3, 0, 1 }, { 4, 0, 1 } }).find("nothing would"),
    std::string::npos);
  ProjectionOptions zero;
  zero.tolerance = 0;
  EXPECT_NE(refused({ { 4, 0, 1 } }, zero).find("tolerance must be > 0"), std::string::npos);
  ProjectionOptions negative;
  negative.tolerance = -1;
  EXPECT_NE(refused({ { 4, 0, 1 } }, negative).find("tolerance"), std::string::npos);
}

TEST(Projection, RangesParseAndPrint)
{
  std::string error;
  const auto axes = frep::project::parse_eliminated("x4=0:1,5=-0.5:2.25", error);
  ASSERT_EQ(axes.size(), 2u) << error;
  EXPECT_EQ(axes[0].coordinate, 4);
  EXPECT_EQ(axes[1].coordinate, 5);
  EXPECT_EQ(axes[1].lo, -0.5);
  EXPECT_EQ(axes[1].hi, 2.25);
  EXPECT_EQ(frep::project::eliminated_text(axes), "x4=0:1,x5=-0.5:2.25");
  for (const char* bad : { "x4", "x4=0", "x4=a:1", "x4.5=0:1", "x4=0:1,", "=0:1" })
  {
    EXPECT_TRUE(frep::project::parse_eliminated(bad, error).empty()) << bad;
    EXPECT_NE(error.find("COORDINATE=LO:HI"), std::string::npos) << bad;
  }
}

} // namespace

namespace
{

TEST(Projection, ValuesDoNotDependOnWhatWasSearchedBefore)
{
  // A turning blade (min/max: its boxes simplify, and the walker learns whether that pays): one
  // projector searching 300 points forward and another backward give the same bits, so pictures
  // do not change with the number of threads or the order of the work (a guard against seeding a
  // search with the previous one's maximiser, which neighbouring grid points would gain from).
  const auto blade = model_of(
    "blade(x[4], a[1]) { an = 3.141592653589793*x[4]; cs = cos(an); sn = sin(an);"
    " u = cs*x[1] + sn*x[2]; v = -sn*x[1] + cs*x[2];"
    " blade = min(min(1 - abs(u), 0.01 - abs(v)), 0.1 - abs(x[3])); }");
  ASSERT_TRUE(blade);
  const auto tape = blade->tape();
  frep::project::Projector forward(tape, { { 0.0, 1.0 } }), backward(tape, { { 0.0, 1.0 } });
  std::mt19937 random(8);
  std::uniform_real_distribution<double> u(-1.1, 1.1);
  std::vector<std::vector<double>> points;
  for (int i = 0; i < 300; ++i)
    points.push_back({ u(random), u(random), u(random) * 0.1 });
  std::vector<double> a, b(points.size());
  for (const auto& p : points)
    a.push_back(forward.maximise(p).value);
  for (std::size_t i = points.size(); i-- > 0;)
    b[i] = backward.maximise(points[i]).value;
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a[i]), std::bit_cast<std::uint64_t>(b[i])) << i;
}

} // namespace
