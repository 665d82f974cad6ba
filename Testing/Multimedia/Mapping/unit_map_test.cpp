#include "Mapping/unit_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

namespace frep::mapping
{
namespace
{

Curve power(double e)
{
  Curve c;
  c.kind = Curve::Kind::Power;
  c.exponent = e;
  return c;
}

Curve table(std::vector<std::array<double, 2>> points)
{
  Curve c;
  c.kind = Curve::Kind::Table;
  c.table = std::move(points);
  return c;
}

Curve expression(std::string text)
{
  Curve c;
  c.kind = Curve::Kind::Expression;
  c.expression = std::move(text);
  return c;
}

Curve ease()
{
  Curve c;
  c.kind = Curve::Kind::EaseInOut;
  return c;
}

std::vector<Curve> monotone_curves()
{
  return { Curve{},
    power(2),
    power(0.5),
    ease(),
    table({ { 0, 0 }, { 0.5, 0.8 }, { 1, 1 } }),
    table({ { 0, 1 }, { 1, 0 } }),
    expression("t*t*t"),
    expression("sqrt(t)") };
}

TEST(UnitCurve, ValuesOfEachKind)
{
  EXPECT_DOUBLE_EQ(evaluate_curve(Curve{}, 0.3), 0.3);
  EXPECT_DOUBLE_EQ(evaluate_curve(power(2), 0.5), 0.25);
  EXPECT_DOUBLE_EQ(evaluate_curve(ease(), 0.25), 0.25 * 0.25 * 2.5);
  EXPECT_DOUBLE_EQ(evaluate_curve(table({ { 0, 0 }, { 0.5, 0.8 }, { 1, 1 } }), 0.25), 0.4);
  EXPECT_DOUBLE_EQ(evaluate_curve(table({ { 0, 0 }, { 0.5, 0.8 }, { 1, 1 } }), 0.75), 0.9);
  EXPECT_NEAR(evaluate_curve(expression("t*t"), 0.3), 0.09, 1e-15);
  EXPECT_NEAR(
    evaluate_curve(expression("0.5 + 0.5*sin(t)"), 0.2), 0.5 + 0.5 * std::sin(0.2), 1e-15);
}

TEST(UnitCurve, EndsAreZeroAndOneAndArgumentsAreClamped)
{
  for (const Curve& c : { Curve{}, power(3), ease(), expression("t^2") })
  {
    EXPECT_DOUBLE_EQ(evaluate_curve(c, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(evaluate_curve(c, 1.0), 1.0);
    EXPECT_DOUBLE_EQ(evaluate_curve(c, -5.0), 0.0);
    EXPECT_DOUBLE_EQ(evaluate_curve(c, 7.0), 1.0);
  }
}

TEST(UnitCurve, ValuesOutsideTheUnitIntervalAreClamped)
{
  EXPECT_DOUBLE_EQ(evaluate_curve(expression("2*t"), 0.8), 1.0);
  EXPECT_DOUBLE_EQ(evaluate_curve(expression("t - 0.5"), 0.2), 0.0);
  EXPECT_DOUBLE_EQ(evaluate_curve(table({ { 0, -1 }, { 1, 3 } }), 0.5), 1.0);
  // A run-time error (sqrt of a negative) counts as 0.
  EXPECT_DOUBLE_EQ(evaluate_curve(expression("sqrt(t - 2)"), 0.5), 0.0);
}

TEST(UnitCurve, InvalidCurvesAreErrors)
{
  EXPECT_FALSE(UnitCurve::make(power(0)).ok());
  EXPECT_FALSE(UnitCurve::make(power(-1)).ok());
  EXPECT_FALSE(UnitCurve::make(table({ { 0, 0 } })).ok());
  EXPECT_FALSE(UnitCurve::make(table({ { 0.1, 0 }, { 1, 1 } })).ok());
  EXPECT_FALSE(UnitCurve::make(table({ { 0, 0 }, { 0.6, 0.5 }, { 0.5, 0.7 }, { 1, 1 } })).ok());
  EXPECT_FALSE(UnitCurve::make(expression("  ")).ok());
  EXPECT_TRUE(std::isnan(evaluate_curve(power(0), 0.5)));
}

TEST(UnitCurve, ParseErrorComesBackWithItsColumn)
{
  const UnitCurve::Result r = UnitCurve::make(expression("t * (t + "));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error.find("t * (t + "), std::string::npos) << r.error;
  const UnitCurve::Result r2 = UnitCurve::make(expression("t $ 2"));
  ASSERT_FALSE(r2.ok());
  EXPECT_NE(r2.error.find("column 3"), std::string::npos) << r2.error;
}

TEST(UnitCurve, MonotoneWhereDeclared)
{
  for (const Curve& c : monotone_curves())
  {
    const auto r = UnitCurve::make(c);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.curve.is_monotone()) << static_cast<int>(c.kind) << " " << c.expression;
  }
  EXPECT_FALSE(UnitCurve::make(table({ { 0, 0 }, { 0.5, 1 }, { 1, 0 } })).curve.is_monotone());
  EXPECT_FALSE(UnitCurve::make(expression("4*t*(1-t)")).curve.is_monotone());
}

TEST(ChannelMap, NormalisesAndMapsOntoTheTarget)
{
  const auto r = ChannelMap::make({ 2, 4 }, Curve{}, { 220, 440 });
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.map.to_unit(3), 0.5);
  EXPECT_DOUBLE_EQ(r.map.to_unit(10), 1.0);
  EXPECT_DOUBLE_EQ(r.map.to_unit(-10), 0.0);
  EXPECT_DOUBLE_EQ(r.map.forward(3), 330);
  EXPECT_DOUBLE_EQ(r.map.forward(2), 220);
  EXPECT_DOUBLE_EQ(r.map.forward(4), 440);
  const auto p = ChannelMap::make({ 0, 1 }, power(2), { 220, 440 });
  EXPECT_DOUBLE_EQ(p.map.forward(0.5), 220 + 0.25 * 220);
  // A reversed target: opacity 1 -> 0.3.
  const auto o = ChannelMap::make({ 0, 1 }, Curve{}, { 1, 0.3 });
  EXPECT_DOUBLE_EQ(o.map.forward(0.5), 0.65);
}

TEST(ChannelMap, InverseRoundTripsForEveryCurveKind)
{
  for (const Curve& c : monotone_curves())
  {
    const auto r = ChannelMap::make({ -2, 6 }, c, { 10, 0 });
    ASSERT_TRUE(r.ok()) << r.error;
    for (int k = 0; k <= 20; ++k)
    {
      const double x = -2 + 8.0 * k / 20;
      const double y = r.map.forward(x);
      EXPECT_NEAR(r.map.forward(r.map.inverse(y)), y, 1e-9) << c.expression << " x=" << x;
      // Where the curve is strictly monotone, x itself comes back.
      if (c.kind != Curve::Kind::Table || c.table.size() == 2)
      {
        EXPECT_NEAR(r.map.inverse(y), x, 1e-6) << static_cast<int>(c.kind) << c.expression;
      }
    }
  }
}

TEST(ChannelMap, InverseClampsToTheRange)
{
  const auto r = ChannelMap::make({ 0, 10 }, Curve{}, { 0, 1 });
  EXPECT_DOUBLE_EQ(r.map.inverse(2), 10);
  EXPECT_DOUBLE_EQ(r.map.inverse(-2), 0);
  const auto flat = ChannelMap::make({ 3, 10 }, Curve{}, { 5, 5 });
  EXPECT_DOUBLE_EQ(flat.map.inverse(5), 3);
}

TEST(ChannelMap, ZeroWidthRangeAndBadCurveAreErrors)
{
  EXPECT_FALSE(ChannelMap::make({ 1, 1 }, Curve{}, { 0, 1 }).ok());
  EXPECT_FALSE(ChannelMap::make({ 0, 1 }, expression("t +* 2"), { 0, 1 }).ok());
  EXPECT_FALSE(ChannelMap::make({ 0, INFINITY }, Curve{}, { 0, 1 }).ok());
}

TEST(ChannelMap, CopiesShareTheTapeAndEvaluateOnSeveralThreads)
{
  const auto r = ChannelMap::make({ 0, 1 }, expression("t*t"), { 0, 100 });
  ASSERT_TRUE(r.ok());
  std::vector<std::thread> threads;
  std::vector<int> wrong(4, 0);
  for (int k = 0; k < 4; ++k)
  {
    threads.emplace_back(
      [copy = r.map, &wrong, k]
      {
        for (int i = 0; i <= 1000; ++i)
        {
          const double x = i / 1000.0;
          wrong[k] += std::abs(copy.forward(x) - 100 * x * x) > 1e-9 ? 1 : 0;
        }
      });
  }
  for (auto& t : threads)
  {
    t.join();
  }
  for (int w : wrong)
  {
    EXPECT_EQ(w, 0);
  }
}

} // namespace
} // namespace frep::mapping
