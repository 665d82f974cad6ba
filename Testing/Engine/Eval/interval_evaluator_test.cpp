#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"

#include "eval_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <numbers>
#include <cmath>
#include <limits>

namespace frep::test
{
namespace
{

constexpr double kInf = std::numeric_limits<double>::infinity();

Interval random_box(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 11);
  const double widths[] = { 0.0, 1e-7, 1e-3, 0.3, 2.0, 7.0, 50.0, 1e4 };
  const int k = kind(rng);
  if (k == 0)
  {
    return { unit(rng) * 5, kInf };
  }
  if (k == 1)
  {
    return { -kInf, unit(rng) * 5 };
  }
  if (k == 2)
  {
    return { -1e6, 1e6 };
  }
  const double centre = k < 5 ? std::round(unit(rng) * 4) : unit(rng) * 6;
  const double w = widths[std::uniform_int_distribution<int>(0, 7)(rng)] * (0.5 + unit(rng) / 2);
  const double lo = centre - w * (0.5 + unit(rng) / 2);
  return { lo, lo + w };
}

/// j = 0: the low end, 1: the high end, otherwise a random interior point.
double sample(const Interval& box, std::mt19937_64& rng, int j)
{
  if (j == 0)
  {
    return box.lo;
  }
  if (j == 1)
  {
    return box.hi;
  }
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double lo = std::isinf(box.lo) ? (std::isinf(box.hi) ? -1e6 : box.hi - 1e6) : box.lo;
  const double hi = std::isinf(box.hi) ? lo + 1e6 : box.hi;
  return std::clamp(lo + (hi - lo) * u(rng), lo, hi);
}

std::string show(const std::vector<Interval>& box, const std::vector<double>& x)
{
  std::string s;
  for (std::size_t k = 0; k < box.size(); ++k)
  {
    s += " x" + std::to_string(k) + "=" + std::to_string(x[k]) + " in [" +
         std::to_string(box[k].lo) + ", " + std::to_string(box[k].hi) + "]";
  }
  return s;
}

/// Every sampled point value lies in the enclosure (NaN only where it is the whole line), and
/// a sampled run-time error implies may_fail.
void expect_encloses(const std::shared_ptr<const Tape>& tape,
  const std::string& what,
  std::uint64_t seed,
  int boxes = 400,
  int samples = 25)
{
  IntervalEvaluator interval(tape);
  PointEvaluator point(tape);
  std::mt19937_64 rng(seed);
  std::vector<Interval> box(tape->input_count);
  std::vector<double> x(tape->input_count);
  std::vector<double> out(tape->outputs.size());
  for (int i = 0; i < boxes; ++i)
  {
    for (auto& b : box)
    {
      b = random_box(rng);
    }
    const IntervalResult r = interval.evaluate(box);
    ASSERT_LE(r.value.lo, r.value.hi) << what;
    for (int j = 0; j < samples; ++j)
    {
      for (std::size_t k = 0; k < x.size(); ++k)
      {
        // The first 8 samples are the corners of the box, then interior points.
        x[k] = sample(box[k], rng, (j < 8) ? ((j >> k) & 1) : 2);
      }
      const int error = point.evaluate(x, out);
      if (error != 0)
      {
        ASSERT_TRUE(r.may_fail) << what << ": a point fails but may_fail is false";
        continue;
      }
      const double v = out[0];
      if (std::isnan(v))
      {
        ASSERT_TRUE(r.value.lo == -kInf && r.value.hi == kInf)
          << what << ": NaN at" << show(box, x) << " but the enclosure is [" << r.value.lo << ", "
          << r.value.hi << "]";
        continue;
      }
      ASSERT_TRUE(r.value.contains(v)) << what << ": " << v << " at" << show(box, x) << " outside ["
                                       << r.value.lo << ", " << r.value.hi << "]";
    }
  }
}

TEST(IntervalEvaluator, EveryOpcodeEnclosesSampledValues)
{
  std::uint64_t seed = 100;
  for (const OpInfo& info : value_ops())
  {
    expect_encloses(single_op_tape(info.op), info.name, ++seed);
  }
}

TEST(IntervalEvaluator, HfPowIntEnclosesForAllExponents)
{
  for (int n = -7; n <= 7; ++n)
  {
    expect_encloses(single_op_tape(Opcode::HfPowInt, n), "HfPowInt " + std::to_string(n), 200 + n);
  }
}

TEST(IntervalEvaluator, HfPowWithConstantExponents)
{
  for (double e : { 2.0, 3.0, -2.0, 0.5, -1.5, 2.0000001, 0.0 })
  {
    TapeBuilder b(1);
    const auto x = b.input(0);
    const auto f = b.op(Opcode::HfPow, x, b.constant(e));
    expect_encloses(b.finish({ f }), "HfPow e=" + std::to_string(e), 300);
  }
}

TEST(IntervalEvaluator, ComposedModelWithErrorsEnclosesAndReportsMayFail)
{
  TapeBuilder b(3);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const auto z = b.input(2);
  b.error_if(b.op(Opcode::Lt, z, b.constant(-3)));
  const auto s1 = b.op(Opcode::Sub,
    b.constant(4),
    b.op(Opcode::Add, b.op(Opcode::Square, x), b.op(Opcode::HfPowInt, y, 0, 0, 2)));
  const auto s2 = b.op(Opcode::Sub, b.constant(1), b.op(Opcode::Abs, b.op(Opcode::Sin, z)));
  const auto u = b.op(Opcode::Union, s1, s2);
  const auto cut = b.op(Opcode::Intersect, u, b.op(Opcode::Neg, b.op(Opcode::Sub, x, y)));
  const auto f = b.op(Opcode::Select,
    b.op(Opcode::Gt, x, b.constant(0)),
    cut,
    b.op(Opcode::Max, s1, b.op(Opcode::Exp, b.op(Opcode::Neg, b.op(Opcode::Square, z)))));
  expect_encloses(b.finish({ f }), "model", 400, 2000, 30);
}

// The R-function rule is tight, which is what makes culling R-function models work.
TEST(IntervalEvaluator, RFunctionsAreTightByMonotonicity)
{
  TapeBuilder b(2);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const auto u = b.op(Opcode::Union, x, y);
  const auto i = b.op(Opcode::Intersect, x, y);
  IntervalEvaluator eu(b.finish({ u }));
  IntervalEvaluator ei(b.finish({ i }));
  const Interval box[2] = { { 1, 2 }, { -3, 4 } };
  const auto ru = eu.evaluate(box).value;
  const auto ri = ei.evaluate(box).value;
  EXPECT_NEAR(ru.lo, semantics::unite(1, -3), 1e-12);
  EXPECT_NEAR(ru.hi, semantics::unite(2, 4), 1e-12);
  EXPECT_NEAR(ri.lo, semantics::intersect(1, -3), 1e-12);
  EXPECT_NEAR(ri.hi, semantics::intersect(2, 4), 1e-12);
  EXPECT_FALSE(eu.evaluate(box).may_fail);
}

// A left-fold union of 20 spheres along x: a box away from all of them is certainly outside,
// one inside a sphere is certainly inside.
TEST(IntervalEvaluator, CullsAUnionOfSpheres)
{
  TapeBuilder b(3);
  const std::uint32_t in[3] = { b.input(0), b.input(1), b.input(2) };
  std::uint32_t acc = 0;
  for (int s = 0; s < 20; ++s)
  {
    std::uint32_t r2 = b.constant(0);
    for (int k = 0; k < 3; ++k)
    {
      const auto d = b.op(Opcode::Sub, in[k], b.constant(k == 0 ? s * 0.5 : 0.0));
      r2 = b.op(Opcode::Add, r2, b.op(Opcode::Square, d));
    }
    const auto sphere = b.op(Opcode::Sub, b.constant(0.04), r2);
    acc = s == 0 ? sphere : b.op(Opcode::Union, acc, sphere);
  }
  IntervalEvaluator eval(b.finish({ acc }));
  const Interval outside[3] = { { 3, 3.1 }, { 2, 2.1 }, { 0, 0.1 } };
  EXPECT_LT(eval.evaluate(outside).value.hi, 0);
  const Interval inside[3] = { { 4.49, 4.51 }, { -0.01, 0.01 }, { -0.01, 0.01 } };
  EXPECT_GT(eval.evaluate(inside).value.lo, 0);
}

TEST(IntervalEvaluator, DecidedComparisonsAndSelect)
{
  TapeBuilder b(1);
  const auto x = b.input(0);
  const auto c = b.op(Opcode::Lt, x, b.constant(0));
  const auto f = b.op(Opcode::Select, c, b.constant(-5), b.op(Opcode::Sin, x));
  IntervalEvaluator eval(b.finish({ f }));
  const Interval pos[1] = { { 0.1, 0.2 } };
  const auto r = eval.evaluate(pos).value;
  EXPECT_GE(r.lo, std::sin(0.1) - 1e-15);
  EXPECT_LE(r.hi, std::sin(0.2) + 1e-15);
  const Interval neg[1] = { { -2, -1 } };
  EXPECT_EQ(eval.evaluate(neg).value.lo, -5);
  EXPECT_EQ(eval.evaluate(neg).value.hi, -5);
  const Interval both[1] = { { -1, 2 } };
  EXPECT_EQ(eval.evaluate(both).value.lo, -5);
  EXPECT_EQ(eval.evaluate(both).value.hi, 1); // sin reaches its maximum at pi/2
}

TEST(IntervalEvaluator, MayFailOnlyWhereAConditionCanHold)
{
  TapeBuilder b(1);
  const auto x = b.input(0);
  b.error_if(b.op(Opcode::Lt, x, b.constant(0)));
  IntervalEvaluator eval(b.finish({ b.op(Opcode::Sqrt, x) }));
  const Interval safe[1] = { { 1, 4 } };
  const auto r = eval.evaluate(safe);
  EXPECT_FALSE(r.may_fail);
  EXPECT_LE(r.value.lo, 1);
  EXPECT_GE(r.value.hi, 2);
  EXPECT_LT(r.value.hi - r.value.lo, 1 + 1e-12);
  const Interval risky[1] = { { -1, 4 } };
  EXPECT_TRUE(eval.evaluate(risky).may_fail);
}

TEST(IntervalEvaluator, CallsAreUnknown)
{
  auto fn = std::make_shared<TestFunction>();
  TapeBuilder b(2);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const std::uint32_t o0 = b.tape.slot_count++;
  const std::uint32_t o1 = b.tape.slot_count++;
  b.tape.calls.push_back({ fn, { x, y }, { o0, o1 } });
  b.tape.code.push_back({ Opcode::Call, 0, 0, 0, 0, 0, 0 });
  IntervalEvaluator eval(b.finish({ b.op(Opcode::Add, o0, o1) }));
  const Interval box[2] = { { 0, 1 }, { 0, 1 } };
  const auto r = eval.evaluate(box);
  EXPECT_TRUE(r.may_fail);
  EXPECT_EQ(r.value.lo, -kInf);
  EXPECT_EQ(r.value.hi, kInf);
}

} // namespace
} // namespace frep::test

namespace frep::test
{
namespace
{

// Boxes inside boxes, three levels deep, each evaluated with its parent's freeze: the enclosure
// holds F at points of the box (the freeze is sound; it need not contain the full evaluation's
// enclosure, since the rules' rounding margins are not monotone in their operands' widths),
// decided maxima keep it exactly the full evaluation's, and most of the tape is skipped near one
// ball.
TEST(IntervalFreeze, NestedBoxesEncloseTheFullEvaluationAndSkipMostOfTheTape)
{
  std::mt19937_64 rng(5);
  for (const Opcode join : { Opcode::Max, Opcode::Union })
  {
    const auto tape = ring_of_balls(join, 40, 8.0);
    IntervalEvaluator frozen(tape), full(tape);
    PointEvaluator point(tape);
    std::size_t skipped = 0, boxes = 0;
    for (int trial = 0; trial < 200; ++trial)
    {
      std::uniform_real_distribution<double> where(-10, 8);
      std::vector<Interval> box{ { where(rng), 0 }, { where(rng), 0 }, { -1, 1 } };
      box[0].hi = box[0].lo + 2;
      box[1].hi = box[1].lo + 2;
      std::deque<IntervalFreeze> freezes(4);
      const IntervalFreeze* outer = nullptr;
      for (int level = 0; level < 4; ++level)
      {
        const IntervalResult got = frozen.evaluate(box, {}, outer, &freezes[level]);
        const IntervalResult want = full.evaluate(box);
        for (int p = 0; p < 20; ++p)
        {
          std::vector<double> at(3), out(1);
          for (int k = 0; k < 3; ++k)
          {
            at[k] = std::uniform_real_distribution<double>(box[k].lo, box[k].hi)(rng);
          }
          point.evaluate(at, out);
          ASSERT_LE(got.value.lo, out[0]) << trial << " level " << level;
          ASSERT_GE(got.value.hi, out[0]) << trial << " level " << level;
        }
        if (join == Opcode::Max)
        {
          EXPECT_EQ(got.value.lo, want.value.lo); // decided max: the loser does not matter
          EXPECT_EQ(got.value.hi, want.value.hi);
        }
        ASSERT_TRUE(frozen.make_freeze(outer, freezes[level]));
        skipped += freezes[level].skipped;
        ++boxes;
        outer = &freezes[level];
        for (auto& side : box) // a random quarter (an eighth) inside
        {
          const double half = (side.hi - side.lo) / 2;
          side.lo += std::uniform_int_distribution<int>(0, 1)(rng) * half;
          side.hi = side.lo + half;
        }
      }
    }
    EXPECT_GT(double(skipped) / double(boxes * tape->code.size()), 0.5) << opcode_name(join);
  }
}

// A dominated value that something else also reads stays evaluated: the other reader would see
// the outer box's looser enclosure.
TEST(IntervalFreeze, AValueAlsoReadElsewhereIsNotFrozen)
{
  for (const bool shared : { false, true })
  {
    TapeBuilder b(2);
    const auto x = b.input(0), y = b.input(1);
    const auto low = b.op(Opcode::Sub, b.op(Opcode::Mul, y, y), b.constant(10)); // in [-10, -9]
    auto f = b.op(Opcode::Max, x, low);
    if (shared)
    {
      f = b.op(Opcode::Add, f, low);
    }
    const auto tape = b.finish({ f });
    IntervalEvaluator evaluator(tape);
    IntervalFreeze freeze;
    const std::vector<Interval> box{ { 0, 1 }, { 0, 1 } };
    evaluator.evaluate(box, {}, nullptr, &freeze);
    ASSERT_TRUE(evaluator.make_freeze(nullptr, freeze));
    EXPECT_EQ(freeze.frozen, shared ? 0u : 1u);
    const std::vector<Interval> inner{ { 0.5, 1 }, { 0.5, 1 } };
    IntervalFreeze scratch;
    const IntervalResult got = evaluator.evaluate(inner, {}, &freeze, &scratch);
    const IntervalResult want = evaluator.evaluate(inner);
    EXPECT_EQ(got.value.lo, want.value.lo);
    EXPECT_EQ(got.value.hi, want.value.hi);
  }
}

} // namespace
} // namespace frep::test
