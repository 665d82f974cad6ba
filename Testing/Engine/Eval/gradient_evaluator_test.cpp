#include "Eval/gradient_evaluator.h"
#include "Eval/point_evaluator.h"

#include "eval_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frep::test
{
namespace
{

/// Central differences of the point evaluator; false where the function is not smooth enough
/// around x (a step, kink or NaN inside the stencil) for the comparison to mean anything.
bool numeric_gradient(PointEvaluator& point, std::vector<double> x, std::vector<double>& g)
{
  const double f0 = point.value(x);
  for (std::size_t k = 0; k < x.size(); ++k)
  {
    const double h = 1e-6 * std::max(1.0, std::fabs(x[k]));
    const double xk = x[k];
    x[k] = xk + h;
    const double fp = point.value(x);
    x[k] = xk - h;
    const double fm = point.value(x);
    x[k] = xk + h / 2;
    const double fp2 = point.value(x);
    x[k] = xk;
    if (!std::isfinite(fp) || !std::isfinite(fm) || !std::isfinite(f0))
    {
      return false;
    }
    g[k] = (fp - fm) / (2 * h);
    // Smoothness check: the half-step one-sided slope must agree with the central one.
    const double one_sided = (fp2 - f0) / (h / 2);
    if (std::fabs(one_sided - g[k]) > 1e-3 * (1 + std::fabs(g[k])))
    {
      return false;
    }
  }
  return true;
}

void expect_gradient_matches(const std::shared_ptr<const Tape>& tape,
  const std::string& what,
  std::uint64_t seed,
  double range)
{
  GradientEvaluator grad(tape);
  PointEvaluator point(tape);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-range, range);
  const std::size_t n = tape->input_count;
  std::vector<double> x(n);
  std::vector<double> g(n);
  std::vector<double> numeric(n);
  int compared = 0;
  for (int i = 0; i < 2000; ++i)
  {
    for (auto& v : x)
    {
      v = u(rng);
    }
    if (what == "Select")
    {
      x[0] = i % 2; // a boolean condition
    }
    const double f = grad.evaluate(x, g);
    ASSERT_TRUE(same_bits(f, point.value(x))) << what << ": value differs from PointEvaluator";
    if (!numeric_gradient(point, x, numeric))
    {
      continue;
    }
    ++compared;
    for (std::size_t k = 0; k < n; ++k)
    {
      ASSERT_NEAR(g[k], numeric[k], 1e-4 * (1 + std::fabs(numeric[k])))
        << what << " d/dx" << k << " at (" << x[0] << ", " << (n > 1 ? x[1] : 0) << ")";
    }
  }
  EXPECT_GT(compared, 500) << what << ": too few smooth points compared";
}

TEST(GradientEvaluator, EveryOpcodeAgreesWithCentralDifferences)
{
  std::uint64_t seed = 500;
  for (const OpInfo& info : value_ops())
  {
    // Keep the arguments in the domains where the operation is defined and well scaled.
    double range = 3;
    switch (info.op)
    {
      case Opcode::Asin:
      case Opcode::Acos:
        range = 0.99;
        break;
      case Opcode::Exp:
      case Opcode::Sinh:
      case Opcode::Cosh:
        range = 5;
        break;
      default:
        break;
    }
    TapeBuilder b(3);
    std::uint32_t x0 = b.input(0);
    const auto x1 = b.input(1);
    const auto x2 = b.input(2);
    switch (info.op)
    {
      case Opcode::Sqrt:
      case Opcode::Log:
      case Opcode::Log10:
      case Opcode::Pow:
      case Opcode::HfPow:
        x0 = b.op(Opcode::Add, b.op(Opcode::Abs, x0), b.constant(0.1)); // positive base
        break;
      default:
        break;
    }
    expect_gradient_matches(b.finish({ b.op(info.op, x0, x1, x2) }), info.name, ++seed, range);
  }
}

TEST(GradientEvaluator, HfPowIntAndNegativeBases)
{
  for (int n : { -3, -2, -1, 0, 1, 2, 3, 5 })
  {
    expect_gradient_matches(single_op_tape(Opcode::HfPowInt, n), "HfPowInt", 600 + n, 3);
    TapeBuilder b(1);
    const auto x = b.input(0);
    const auto f = b.op(Opcode::HfPow, x, b.constant(n)); // integral: negative bases are fine
    expect_gradient_matches(b.finish({ f }), "HfPow int", 700 + n, 3);
  }
}

// An integral exponent beyond the int range: hf_round gives INT_MIN, the value is the constant
// 1 and its derivative 0. Negating INT_MIN was undefined behaviour (found by fuzz_hyperfun_eval
// under UBSan).
TEST(GradientEvaluator, HfPowBeyondTheIntRangeIsConstant)
{
  TapeBuilder b(2);
  const auto f = b.op(Opcode::HfPow, b.input(0), b.input(1));
  const auto tape = b.finish({ f });
  GradientEvaluator gradient(tape);
  PointEvaluator point(tape);
  for (const double e : { 3e9, -3e9, 1e300 })
  {
    const std::vector<double> x{ -1.5, e };
    std::vector<double> g(2);
    const double value = gradient.evaluate(x, g);
    EXPECT_EQ(value, point.value(x)) << "e = " << e;
    EXPECT_EQ(value, 1.0) << "e = " << e;
    EXPECT_EQ(g[0], 0.0) << "e = " << e;
    EXPECT_EQ(g[1], 0.0) << "e = " << e;
  }
}

TEST(GradientEvaluator, SphereGradientIsExact)
{
  TapeBuilder b(3);
  const std::uint32_t x[3] = { b.input(0), b.input(1), b.input(2) };
  std::uint32_t r2 = b.op(Opcode::Square, x[0]);
  r2 = b.op(Opcode::Add, r2, b.op(Opcode::Square, x[1]));
  r2 = b.op(Opcode::Add, r2, b.op(Opcode::Square, x[2]));
  GradientEvaluator grad(b.finish({ b.op(Opcode::Sub, b.constant(1), r2) }));
  const double p[3] = { 0.5, -0.25, 2 };
  double g[3];
  EXPECT_EQ(grad.evaluate(p, g), 1 - (0.25 + 0.0625 + 4));
  EXPECT_EQ(g[0], -1.0);
  EXPECT_EQ(g[1], 0.5);
  EXPECT_EQ(g[2], -4.0);
}

TEST(GradientEvaluator, CallsAreDifferentiatedNumerically)
{
  auto fn = std::make_shared<TestFunction>(); // out0 = in0 * in1 + 1, out1 = sin(in0)
  TapeBuilder b(2);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const auto x2 = b.op(Opcode::Square, x);
  const std::uint32_t o0 = b.tape.slot_count++;
  const std::uint32_t o1 = b.tape.slot_count++;
  b.tape.calls.push_back({ fn, { x2, y }, { o0, o1 } });
  b.tape.code.push_back({ Opcode::Call, 0, 0, 0, 0, 0, 0 });
  b.tape.can_fail = true;
  GradientEvaluator grad(b.finish({ b.op(Opcode::Add, o0, o1) }));
  // F = x² y + 1 + sin(x²): dF/dx = 2xy + 2x cos(x²), dF/dy = x².
  const double p[2] = { 1.3, -0.7 };
  double g[2];
  const double f = grad.evaluate(p, g);
  EXPECT_DOUBLE_EQ(f, 1.69 * -0.7 + 1 + std::sin(1.69));
  EXPECT_NEAR(g[0], 2 * 1.3 * -0.7 + 2 * 1.3 * std::cos(1.69), 1e-7);
  EXPECT_NEAR(g[1], 1.69, 1e-7);
  const double bad[2] = { 3, 0 }; // x² = 9 > 5: the call fails
  EXPECT_TRUE(std::isnan(grad.evaluate(bad, g)));
  EXPECT_TRUE(std::isnan(g[0]));
  EXPECT_EQ(fn->scratches.load(), 1);
}

TEST(GradientEvaluator, ErrorsGiveNaN)
{
  TapeBuilder b(1);
  const auto x = b.input(0);
  b.error_if(b.op(Opcode::Lt, x, b.constant(0)));
  GradientEvaluator grad(b.finish({ b.op(Opcode::Sqrt, x) }));
  double g[1];
  const double good[1] = { 4 };
  EXPECT_EQ(grad.evaluate(good, g), 2.0);
  EXPECT_EQ(g[0], 0.25);
  const double bad[1] = { -4 };
  EXPECT_TRUE(std::isnan(grad.evaluate(bad, g)));
  EXPECT_TRUE(std::isnan(g[0]));
}

} // namespace
} // namespace frep::test
