#include "Mapping/path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace frep::mapping
{
namespace
{

double distance(const std::vector<double>& a, const std::vector<double>& b)
{
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    d += (a[i] - b[i]) * (a[i] - b[i]);
  }
  return std::sqrt(d);
}

Path square(bool closed, Path::Interpolation interpolation)
{
  Path p;
  p.coordinates = { "x4", "x5" };
  p.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  p.closed = closed;
  p.interpolation = interpolation;
  return p;
}

// Consecutive distances of 200 samples are equal within 1% (of their mean).
void expect_uniform(const SampledPath& path)
{
  const int n = 200;
  std::vector<double> d;
  auto previous = path.point_at(0);
  for (int k = 1; k < n; ++k)
  {
    const auto p = path.point_at(static_cast<double>(k) / (n - 1));
    d.push_back(distance(previous, p));
    previous = p;
  }
  double mean = 0;
  for (double x : d)
  {
    mean += x;
  }
  mean /= static_cast<double>(d.size());
  for (double x : d)
  {
    EXPECT_NEAR(x, mean, 0.01 * mean);
  }
}

TEST(SampledPath, EndpointsHitExactly)
{
  for (auto interpolation : { Path::Interpolation::Polyline, Path::Interpolation::CatmullRom })
  {
    const auto r = SampledPath::make(square(false, interpolation));
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.path.point_at(0), (std::vector<double>{ 0, 0 }));
    EXPECT_EQ(r.path.point_at(1), (std::vector<double>{ 0, 1 }));
    EXPECT_EQ(r.path.segment_count(), 3u);
  }
}

TEST(SampledPath, ClosedPathEndsWhereItStarts)
{
  const auto r = SampledPath::make(square(true, Path::Interpolation::CatmullRom));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.path.point_at(0), r.path.point_at(1));
  EXPECT_EQ(r.path.segment_count(), 4u);
  // Smooth at the join: the directions just before and just after the start agree.
  const auto a = r.path.point_at(0.999);
  const auto b = r.path.point_at(0.001);
  const auto o = r.path.point_at(0);
  const double ax = o[0] - a[0], ay = o[1] - a[1], bx = b[0] - o[0], by = b[1] - o[1];
  const double cosine = (ax * bx + ay * by) / std::hypot(ax, ay) / std::hypot(bx, by);
  EXPECT_GT(cosine, 0.99);
}

TEST(SampledPath, PassesThroughEveryControlPoint)
{
  const auto r = SampledPath::make(square(true, Path::Interpolation::CatmullRom));
  const auto line = r.path.polyline(4001);
  for (const auto& control : square(true, Path::Interpolation::CatmullRom).points)
  {
    double nearest = 1e9;
    for (const auto& p : line)
    {
      nearest = std::min(nearest, distance(p, control));
    }
    EXPECT_LT(nearest, 2e-3);
  }
}

TEST(SampledPath, ArcLengthIsUniform)
{
  expect_uniform(SampledPath::make(square(true, Path::Interpolation::CatmullRom)).path);
  expect_uniform(SampledPath::make(square(false, Path::Interpolation::CatmullRom)).path);
  // A polyline's corners would shorten the chords measured across them: keep it straight,
  // with segments of very different lengths.
  Path straight;
  straight.interpolation = Path::Interpolation::Polyline;
  straight.points = { { 0, 0 }, { 0.1, 0 }, { 1, 0 }, { 3, 0 } };
  expect_uniform(SampledPath::make(straight).path);
  Path uneven;
  uneven.points = { { 0, 0, 0 }, { 0.1, 0, 0 }, { 2, 1, 0 }, { 2, 1, 3 } };
  expect_uniform(SampledPath::make(uneven).path);
}

TEST(SampledPath, PolylineLength)
{
  const auto r = SampledPath::make(square(true, Path::Interpolation::Polyline));
  EXPECT_NEAR(r.path.length(), 4.0, 1e-12);
  EXPECT_NEAR(r.path.point_at(0.375)[0], 1.0, 1e-12);
  EXPECT_NEAR(r.path.point_at(0.375)[1], 0.5, 1e-12);
  const auto line = r.path.polyline(5);
  ASSERT_EQ(line.size(), 5u);
  EXPECT_EQ(line.front(), line.back());
}

TEST(SampledPath, KeyTimesPlaceControlPoints)
{
  Path p = square(false, Path::Interpolation::Polyline);
  p.timing = Path::Timing::Keys;
  p.key_times = { 0, 1, 5, 6 };
  const auto r = SampledPath::make(p);
  ASSERT_TRUE(r.ok()) << format_errors(r.errors);
  EXPECT_NEAR(r.path.fraction_at_time(1), 1.0 / 3, 1e-12);
  EXPECT_NEAR(r.path.fraction_at_time(3), 0.5, 1e-12); // halfway along the middle segment
  EXPECT_NEAR(r.path.fraction_at_time(5), 2.0 / 3, 1e-12);
  EXPECT_DOUBLE_EQ(r.path.fraction_at_time(-1), 0);
  EXPECT_DOUBLE_EQ(r.path.fraction_at_time(60), 1);
  const auto at3 = r.path.point_at(r.path.fraction_at_time(3));
  EXPECT_NEAR(at3[0], 1, 1e-12);
  EXPECT_NEAR(at3[1], 0.5, 1e-12);
}

TEST(SampledPath, BadPathsAreErrorsWithPlaces)
{
  Path one;
  one.coordinates = { "x4", "x5" };
  one.points = { { 0, 0 } };
  auto r = SampledPath::make(one);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].place, "points");

  Path wrong = square(false, Path::Interpolation::Polyline);
  wrong.points[2] = { 1, 1, 1 };
  r = SampledPath::make(wrong);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].place, "points[2]");

  Path keys = square(true, Path::Interpolation::Polyline);
  keys.timing = Path::Timing::Keys;
  keys.key_times = { 0, 1, 2, 3 }; // closed: 5 needed
  r = SampledPath::make(keys);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].place, "key_times");
  keys.key_times = { 0, 1, 1, 3, 4 };
  r = SampledPath::make(keys);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].place, "key_times[2]");

  Path still;
  still.points = { { 1, 1 }, { 1, 1 } };
  EXPECT_FALSE(SampledPath::make(still).ok());
}

TEST(SampledPath, RepeatedPointsDoNotBreakTheSpline)
{
  Path p;
  p.points = { { 0, 0 }, { 1, 0 }, { 1, 0 }, { 2, 1 } };
  const auto r = SampledPath::make(p);
  ASSERT_TRUE(r.ok());
  for (const auto& q : r.path.polyline(100))
  {
    EXPECT_TRUE(std::isfinite(q[0]) && std::isfinite(q[1]));
  }
  EXPECT_EQ(r.path.point_at(1), (std::vector<double>{ 2, 1 }));
}

} // namespace
} // namespace frep::mapping

namespace frep::mapping
{
namespace
{

// Distance from p to the pieces' curve: the nearest of 200 samples per piece, refined by a
// ternary search around the nearest (the pieces are smooth: this finds the foot of p on them).
double distance_to_pieces(const std::vector<project::PathPiece>& pieces, const std::vector<double>& p)
{
  const auto at = [&](const project::PathPiece& piece, double u)
  {
    std::vector<double> q(piece.size());
    for (std::size_t a = 0; a < piece.size(); ++a)
      q[a] = project::piece_value(piece[a], u);
    return distance(q, p);
  };
  std::size_t piece = 0;
  int sample = 0;
  double best = 1e9;
  for (std::size_t j = 0; j < pieces.size(); ++j)
    for (int k = 0; k <= 200; ++k)
      if (const double d = at(pieces[j], k / 200.0); d < best)
      {
        best = d;
        piece = j;
        sample = k;
      }
  double lo = std::max(0.0, (sample - 1) / 200.0), hi = std::min(1.0, (sample + 1) / 200.0);
  for (int step = 0; step < 100; ++step)
  {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (at(pieces[piece], m1) < at(pieces[piece], m2))
      hi = m2;
    else
      lo = m1;
  }
  best = std::min(best, at(pieces[piece], 0.5 * (lo + hi)));
  return best;
}

// The pieces are the curve the frames follow: they start and end at the control points, and
// every point of the sampled curve lies on them (centripetal Catmull-Rom on uneven spacing, and
// a polyline).
TEST(SampledPath, PiecesAreTheCurve)
{
  for (auto interpolation : { Path::Interpolation::Polyline, Path::Interpolation::CatmullRom })
  {
    Path spec;
    spec.coordinates = { "x4", "x5" };
    spec.points = { { 0, 0 }, { 1, 0 }, { 1.2, 2 }, { 0, 1.5 } };
    spec.closed = true;
    spec.interpolation = interpolation;
    const auto r = SampledPath::make(spec);
    ASSERT_TRUE(r.ok());
    const std::vector<project::PathPiece> pieces = r.path.pieces();
    ASSERT_EQ(pieces.size(), 4u);
    for (std::size_t j = 0; j < pieces.size(); ++j)
      for (std::size_t a = 0; a < 2; ++a)
      {
        EXPECT_EQ(project::piece_value(pieces[j][a], 0.0), spec.points[j][a]);
        EXPECT_NEAR(project::piece_value(pieces[j][a], 1.0), spec.points[(j + 1) % 4][a], 1e-12);
      }
    for (const auto& p : r.path.polyline(101))
      EXPECT_LT(distance_to_pieces(pieces, p), 1e-9);
  }
}

} // namespace
} // namespace frep::mapping
