#include "Eval/point_evaluator.h"

#include "eval_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace frep::test
{
namespace
{

TEST(PointEvaluator, EveryOpcodeMatchesTheReferenceBitForBit)
{
  std::mt19937_64 rng(1);
  for (const OpInfo& info : value_ops())
  {
    PointEvaluator eval(single_op_tape(info.op));
    int checked = 0;
    for (int i = 0; i < 3000; ++i)
    {
      double x[3] = { random_value(rng), random_value(rng), random_value(rng) };
      if (info.op == Opcode::Select)
      {
        x[0] = (i % 3 == 0) ? 0.0 : x[0]; // the condition is a boolean slot, often 0
      }
      const double expected = reference(info.op, x[0], x[1], x[2]);
      const double got = eval.value(x);
      ASSERT_TRUE(same_bits(expected, got)) << info.name << "(" << x[0] << ", " << x[1] << ", "
                                            << x[2] << ") = " << got << ", expected " << expected;
      ++checked;
    }
    EXPECT_EQ(checked, 3000);
  }
}

TEST(PointEvaluator, SpecialValuesOnEveryOpcode)
{
  const auto& s = special_values();
  for (const OpInfo& info : value_ops())
  {
    PointEvaluator eval(single_op_tape(info.op));
    for (double a : s)
    {
      for (double b : s)
      {
        const double x[3] = { a, b, -b };
        ASSERT_TRUE(same_bits(reference(info.op, a, b, -b), eval.value(x)))
          << info.name << "(" << a << ", " << b << ")";
      }
    }
  }
}

TEST(PointEvaluator, HfPowIntAllExponents)
{
  std::mt19937_64 rng(2);
  for (int n = -25; n <= 25; ++n)
  {
    PointEvaluator eval(single_op_tape(Opcode::HfPowInt, n));
    for (int i = 0; i < 300; ++i)
    {
      const double x[3] = { random_value(rng), 0, 0 };
      ASSERT_TRUE(same_bits(semantics::hf_pow_int(x[0], n), eval.value(x))) << x[0] << "^" << n;
    }
  }
  const double tiny[3] = { 1e-7, 0, 0 };
  EXPECT_EQ(PointEvaluator(single_op_tape(Opcode::HfPowInt, -2)).value(tiny), 0.0);
}

TEST(PointEvaluator, ConstantsInputsAndSeveralOutputs)
{
  TapeBuilder b(2);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const auto k = b.constant(2.5);
  const auto s = b.op(Opcode::Mul, x, k);
  const auto t = b.op(Opcode::Sub, s, y);
  PointEvaluator eval(b.finish({ t, s, k }));
  double out[3] = {};
  const double in[2] = { 4, 1 };
  EXPECT_EQ(eval.evaluate(in, out), 0);
  EXPECT_EQ(out[0], 9.0);
  EXPECT_EQ(out[1], 10.0);
  EXPECT_EQ(out[2], 2.5);
}

// Sphere r=1 with two checks: ErrorIf(x < 0) raised first in program order (id 1), then
// ErrorIf(y < 0) (id 2). The first raised in program order wins, whatever the ids.
std::shared_ptr<const Tape> guarded_tape(bool reversed)
{
  TapeBuilder b(2);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const auto zero = b.constant(0);
  const auto cx = b.op(Opcode::Lt, x, zero);
  const auto cy = b.op(Opcode::Lt, y, zero);
  b.tape.errors = { { "x negative", {} }, { "y negative", {} } };
  b.tape.code.push_back({ Opcode::ErrorIf, 0, reversed ? cy : cx, 0, 0, reversed ? 2 : 1, 0 });
  b.tape.code.push_back({ Opcode::ErrorIf, 0, reversed ? cx : cy, 0, 0, reversed ? 1 : 2, 0 });
  b.tape.can_fail = true;
  const auto one = b.constant(1);
  const auto f =
    b.op(Opcode::Sub, one, b.op(Opcode::Add, b.op(Opcode::Square, x), b.op(Opcode::Square, y)));
  return b.finish({ f, x });
}

TEST(PointEvaluator, FirstErrorInProgramOrderWinsAndOutputsAreNaN)
{
  PointEvaluator eval(guarded_tape(false));
  double out[2] = {};
  const double ok[2] = { 0.5, 0.5 };
  EXPECT_EQ(eval.evaluate(ok, out), 0);
  EXPECT_EQ(out[0], 0.5);
  const double both[2] = { -1, -1 };
  EXPECT_EQ(eval.evaluate(both, out), 1);
  EXPECT_TRUE(std::isnan(out[0]));
  EXPECT_TRUE(std::isnan(out[1]));
  const double only_y[2] = { 1, -1 };
  EXPECT_EQ(eval.evaluate(only_y, out), 2);
  // After an error the next point is clean again.
  EXPECT_EQ(eval.evaluate(ok, out), 0);
  EXPECT_EQ(out[1], 0.5);

  PointEvaluator reversed(guarded_tape(true));
  EXPECT_EQ(reversed.evaluate(both, out), 2);
  EXPECT_TRUE(std::isnan(reversed.value(both)));
}

TEST(PointEvaluator, CallGathersScattersAndReportsErrors)
{
  auto fn = std::make_shared<TestFunction>();
  TapeBuilder b(2);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const std::uint32_t o0 = b.tape.slot_count++;
  const std::uint32_t o1 = b.tape.slot_count++;
  b.tape.calls.push_back({ fn, { y, x }, { o0, o1 } }); // note the order: (y, x)
  b.tape.code.push_back({ Opcode::Call, 0, 0, 0, 0, 0, 0 });
  b.tape.can_fail = true;
  const auto f = b.op(Opcode::Add, o0, o1);
  PointEvaluator eval(b.finish({ f }));
  EXPECT_EQ(fn->scratches.load(), 1);
  const double in[2] = { 3, 2 };
  EXPECT_EQ(eval.value(in), 2 * 3 + 1 + std::sin(2.0));
  double out[1];
  const double bad[2] = { 0, 6 }; // in0 of the call is y = 6 > 5
  EXPECT_EQ(eval.evaluate(bad, out), 1);
  EXPECT_TRUE(std::isnan(out[0]));
  EXPECT_EQ(fn->scratches.load(), 1); // made once, not per point
}

TEST(PointEvaluator, RefusesMalformedTapes)
{
  TapeBuilder b(1);
  const auto x = b.input(0);
  b.tape.code.push_back({ Opcode::Add, 0, x, 7, 0, 0, 0 }); // slot 7 does not exist
  EXPECT_THROW(PointEvaluator(b.finish({ x })), std::invalid_argument);
  TapeBuilder c(1);
  c.input(3); // input 3 of 1
  EXPECT_THROW(PointEvaluator(c.finish({ 0 })), std::invalid_argument);
  EXPECT_THROW(PointEvaluator(nullptr), std::invalid_argument);
}

} // namespace
} // namespace frep::test
