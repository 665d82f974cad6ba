// User primitives (Language/user_functions.h): registration rules, parser diagnostics that know
// a user function's arity and kinds, and its forms through every evaluator — point, batch,
// interval (enclosure or the whole line), gradient (exact or differences), the interpreter —
// with a failing or throwing function as a run-time error of that point only.
#include "Compiler/combine.h"
#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Language/parser.h"
#include "Semantics/interpreter.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <stdexcept>

namespace frep
{
namespace
{

// ball(x, r) = r^2 - |x|^2 over a 3-item array, with an exact enclosure and gradient.
UserFunction ball(bool with_interval, bool with_gradient)
{
  UserFunction f;
  f.name = "Ball";
  f.kinds = { ArgKind::Array, ArgKind::Real };
  f.array_sizes = { 3, 0 };
  f.point = [](std::span<const UserArgument> a, double& v)
  {
    const double* x = a[0].values;
    v = a[1].values[0] * a[1].values[0] - (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    return true;
  };
  if (with_interval)
  {
    f.interval = [](std::span<const UserIntervalArgument> a, double& lo, double& hi, bool& fails)
    {
      double sq_lo = 0;
      double sq_hi = 0;
      for (int k = 0; k < 3; ++k)
      {
        const double l = a[0].lo[k];
        const double h = a[0].hi[k];
        const double m = std::max(l * l, h * h);
        sq_lo += (l <= 0 && h >= 0) ? 0.0 : std::min(l * l, h * h);
        sq_hi += m;
      }
      const double r = std::max(std::fabs(a[1].lo[0]), std::fabs(a[1].hi[0]));
      const double r_lo = (a[1].lo[0] <= 0 && a[1].hi[0] >= 0)
        ? 0.0
        : std::min(std::fabs(a[1].lo[0]), std::fabs(a[1].hi[0]));
      lo = std::nextafter(r_lo * r_lo - sq_hi, -INFINITY);
      hi = std::nextafter(r * r - sq_lo, INFINITY);
      fails = false;
      return true;
    };
  }
  if (with_gradient)
  {
    f.gradient = [](std::span<const UserArgument> a, double& v, std::span<double> g)
    {
      const double* x = a[0].values;
      const double r = a[1].values[0];
      v = r * r - (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      g[0] = -2 * x[0];
      g[1] = -2 * x[1];
      g[2] = -2 * x[2];
      g[3] = 2 * r;
      return true;
    };
  }
  return f;
}

BatchOptions two_threads()
{
  BatchOptions o;
  o.threads = 2;
  return o;
}
BatchOptions one_thread()
{
  BatchOptions o;
  o.threads = 1;
  return o;
}

std::shared_ptr<const UserFunctionRegistry> registry_with(UserFunction f)
{
  auto r = std::make_shared<UserFunctionRegistry>();
  EXPECT_EQ(r->add(std::move(f)), "");
  return r;
}

ParseResult parse(const std::string& text, std::shared_ptr<const UserFunctionRegistry> users)
{
  ParseOptions options;
  options.user_functions = std::move(users);
  return parse_program(text, "<test>", options);
}

std::shared_ptr<const Model> compile(const std::string& text,
  std::shared_ptr<const UserFunctionRegistry> users)
{
  ParseResult p = parse(text, std::move(users));
  EXPECT_TRUE(p.ok()) << format_diagnostics(p.diagnostics);
  if (!p.ok())
  {
    return nullptr;
  }
  Model::CompileResult r = Model::compile(p.program, ast::select_default_object(*p.program));
  EXPECT_TRUE(r.model) << format_diagnostics(r.diagnostics);
  return r.model;
}

const char* kBallModel =
  "m(x[3], a[1]) { array c[3]; c = [3, 0, 0]; m = ball(x, 2) | hfSphere(x, c, 0.5); }";

TEST(UserFunctions, RegistrationIsRefusedWithAReason)
{
  UserFunctionRegistry r;
  EXPECT_EQ(r.add(ball(false, false)), "");
  EXPECT_NE(r.add(ball(false, false)).find("registered twice"), std::string::npos);
  UserFunction lib = ball(false, false);
  lib.name = "hfSphere";
  EXPECT_NE(r.add(lib).find("library function"), std::string::npos);
  UserFunction builtin = ball(false, false);
  builtin.name = "SQRT";
  EXPECT_NE(r.add(builtin).find("library function"), std::string::npos);
  UserFunction word = ball(false, false);
  word.name = "while";
  EXPECT_NE(r.add(word).find("word of the language"), std::string::npos);
  UserFunction bad = ball(false, false);
  bad.name = "2ball";
  EXPECT_NE(r.add(bad).find("letters, digits"), std::string::npos);
  UserFunction none = ball(false, false);
  none.name = "nopoint";
  none.point = nullptr;
  EXPECT_NE(r.add(none).find("no point form"), std::string::npos);
  UserFunction many = ball(false, false);
  many.name = "many";
  many.kinds.assign(11, ArgKind::Real);
  many.array_sizes.clear();
  EXPECT_NE(r.add(many).find("at most 10"), std::string::npos);
  UserFunction sizes = ball(false, false);
  sizes.name = "sizes";
  sizes.array_sizes = { 3 };
  EXPECT_NE(r.add(sizes).find("array sizes"), std::string::npos);
  EXPECT_EQ(r.size(), 1);
  EXPECT_EQ(r.find("BALL"), 0) << "lookup ignores case";
}

TEST(UserFunctions, DiagnosticsKnowTheArity)
{
  const auto users = registry_with(ball(false, false));
  const auto message = [&](const std::string& body)
  {
    ParseResult p = parse("m(x[3], a[1]) { m = " + body + "; }", users);
    EXPECT_FALSE(p.ok()) << body;
    return p.ok() ? std::string() : p.diagnostics.front().message;
  };
  EXPECT_NE(message("ball(x)").find("takes 2 arguments, Ball(array[3], real), but 1 given"),
    std::string::npos)
    << message("ball(x)");
  EXPECT_NE(message("ball(x, 1, 2)").find("but 3 given"), std::string::npos)
    << message("ball(x, 1, 2)");
  EXPECT_NE(message("ball(1, 2)").find("must be an array name"), std::string::npos);
  EXPECT_NE(message("ball(a, 2)").find("must have 3 items, it has 1"), std::string::npos);
  EXPECT_NE(message("cube(x, 2)").find("Unknown function 'cube'"), std::string::npos);
  // Without user functions the original's message stays.
  ParseResult p = parse_program("m(x[3], a[1]) { m = ball(x, 2); }", "<test>");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.diagnostics.front().message.find("Unassigned identificator"), std::string::npos);
}

TEST(UserFunctions, EveryEvaluatorUsesThePointForm)
{
  const auto model = compile(kBallModel, registry_with(ball(false, false)));
  ASSERT_TRUE(model);
  const auto tape = model->tape();
  PointEvaluator point(tape);
  const auto expected = [](double x, double y, double z)
  {
    const double a = 4 - (x * x + y * y + z * z);
    const double b = 0.25 - ((x - 3) * (x - 3) + y * y + z * z);
    return a + b + std::sqrt(a * a + b * b);
  };
  const double p[3] = { 0.5, -1, 0.25 };
  EXPECT_DOUBLE_EQ(point.value(p), expected(0.5, -1, 0.25));

  std::vector<double> xs, ys, zs;
  for (int i = 0; i < 1000; ++i)
  {
    xs.push_back(-3 + 0.007 * i);
    ys.push_back(std::sin(i * 0.1));
    zs.push_back(0.3);
  }
  const double* rows[3] = { xs.data(), ys.data(), zs.data() };
  std::vector<double> values(1000);
  BatchEvaluator batch(tape, two_threads());
  EXPECT_EQ(batch.evaluate(rows, 1000, values.data()), 0u);
  for (int i = 0; i < 1000; ++i)
  {
    const double q[3] = { xs[i], ys[i], zs[i] };
    ASSERT_EQ(values[i], point.value(q)) << i;
  }

  Interpreter interpreter(model->program(), model->object_index());
  const PointResult r = interpreter.evaluate(p);
  ASSERT_FALSE(r.error);
  EXPECT_DOUBLE_EQ(r.value, expected(0.5, -1, 0.25));
}

TEST(UserFunctions, WithoutAnIntervalFormTheEnclosureIsTheWholeLine)
{
  const auto model = compile("m(x[3], a[1]) { m = ball(x, 2); }", registry_with(ball(false, false)));
  ASSERT_TRUE(model);
  IntervalEvaluator iv(model->tape());
  const Interval box[3] = { { 5, 6 }, { 5, 6 }, { 5, 6 } };
  const IntervalResult r = iv.evaluate(box);
  EXPECT_TRUE(std::isinf(r.value.lo) && std::isinf(r.value.hi));
}

TEST(UserFunctions, TheIntervalFormCullsAndEnclosesTheValues)
{
  const auto model = compile(kBallModel, registry_with(ball(true, false)));
  ASSERT_TRUE(model);
  IntervalEvaluator iv(model->tape());
  const Interval far[3] = { { 5, 6 }, { 5, 6 }, { 5, 6 } };
  const IntervalResult r = iv.evaluate(far);
  EXPECT_LT(r.value.hi, 0) << "far from both balls the box is culled";
  EXPECT_FALSE(r.may_fail);
  PointEvaluator point(model->tape());
  const Interval near[3] = { { -0.5, 2.5 }, { -1, 1 }, { 0, 0.5 } };
  const IntervalResult n = iv.evaluate(near);
  for (double x = -0.5; x <= 2.5; x += 0.25)
  {
    for (double y = -1; y <= 1; y += 0.25)
    {
      const double q[3] = { x, y, 0.25 };
      const double v = point.value(q);
      EXPECT_LE(n.value.lo, v);
      EXPECT_GE(n.value.hi, v);
    }
  }
  // A composed model keeps the enclosure (its calls are wrapped to renumber errors).
  const auto other = compile("n(x[3], a[1]) { array c[3]; c = [0, 9, 0]; n = hfSphere(x, c, 1); }", nullptr);
  CombineResult c = combine(Operation::Union, Operand{ model, {} }, Operand{ other, {} });
  ASSERT_TRUE(c.ok()) << c.error;
  IntervalEvaluator civ(c.model->tape());
  EXPECT_LT(civ.evaluate(far).value.hi, 0);
}

TEST(UserFunctions, TheGradientFormIsUsedWhenGiven)
{
  std::atomic<int> gradient_calls{ 0 };
  UserFunction f = ball(false, true);
  auto inner = f.gradient;
  f.gradient = [&gradient_calls, inner](std::span<const UserArgument> a, double& v, std::span<double> g)
  {
    ++gradient_calls;
    return inner(a, v, g);
  };
  const auto exact = compile("m(x[3], a[1]) { m = ball(x, 2); }", registry_with(f));
  const auto differenced =
    compile("m(x[3], a[1]) { m = ball(x, 2); }", registry_with(ball(false, false)));
  ASSERT_TRUE(exact && differenced);
  GradientEvaluator ge(exact->tape());
  GradientEvaluator gd(differenced->tape());
  const double p[3] = { 0.5, -1, 0.25 };
  double g1[3], g2[3];
  EXPECT_DOUBLE_EQ(ge.evaluate(p, g1), 4 - (0.25 + 1 + 0.0625));
  gd.evaluate(p, g2);
  EXPECT_EQ(gradient_calls.load(), 1);
  EXPECT_EQ(g1[0], -1.0) << "exact";
  EXPECT_EQ(g1[1], 2.0);
  EXPECT_EQ(g1[2], -0.5);
  EXPECT_NEAR(g2[0], -1.0, 1e-6) << "central differences";
}

TEST(UserFunctions, AFailureOrAThrowIsAnErrorOfThatPoint)
{
  UserFunction f;
  f.name = "picky";
  f.kinds = { ArgKind::Real };
  f.point = [](std::span<const UserArgument> a, double& v)
  {
    const double t = a[0].values[0];
    if (t > 1)
    {
      throw std::runtime_error("too big");
    }
    v = 1 - t;
    return t >= -1; // below -1 it fails quietly
  };
  const auto model = compile("m(x[3], a[1]) { m = picky(x[1]); }", registry_with(f));
  ASSERT_TRUE(model);
  PointEvaluator point(model->tape());
  std::vector<double> out(1);
  const double ok[3] = { 0.5, 0, 0 };
  EXPECT_EQ(point.evaluate(ok, out), 0);
  EXPECT_EQ(out[0], 0.5);
  const double big[3] = { 2, 0, 0 };
  const int id = point.evaluate(big, out);
  ASSERT_GT(id, 0);
  EXPECT_EQ(model->tape()->errors[static_cast<std::size_t>(id - 1)].message,
    "User function picky failed");
  EXPECT_EQ(model->tape()->errors[static_cast<std::size_t>(id - 1)].location.line, 1);
  const double small[3] = { -2, 0, 0 };
  EXPECT_EQ(point.evaluate(small, out), id);

  const double xs[4] = { 0.5, 2, -2, 0 };
  const double zeros[4] = { 0, 0, 0, 0 };
  const double* rows[3] = { xs, zeros, zeros };
  double values[4];
  std::uint32_t errors[4];
  BatchEvaluator batch(model->tape(), one_thread());
  EXPECT_EQ(batch.evaluate(rows, 4, values, errors), 2u);
  EXPECT_EQ(errors[0], 0u);
  EXPECT_EQ(errors[1], static_cast<std::uint32_t>(id));
  EXPECT_EQ(errors[2], static_cast<std::uint32_t>(id));
  EXPECT_EQ(values[3], 1.0);
  EXPECT_TRUE(std::isnan(values[1]));

  Interpreter interpreter(model->program(), model->object_index());
  const PointResult r = interpreter.evaluate(big);
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->message, "User function picky failed");
}

TEST(UserFunctions, ABranchNotTakenDoesNotCallIt)
{
  UserFunction f;
  f.name = "never";
  f.kinds = { ArgKind::Real };
  f.point = [](std::span<const UserArgument>, double&) -> bool { throw std::runtime_error("x"); };
  const auto model = compile(
    "m(x[3], a[1]) { if x[1] > 100 then t = never(x[2]); else t = 1; endif; m = t; }",
    registry_with(f));
  ASSERT_TRUE(model);
  PointEvaluator point(model->tape());
  const double p[3] = { 0, 0, 0 };
  EXPECT_EQ(point.value(p), 1.0);
}

TEST(UserFunctions, TheBatchFormTakesWholeBlocks)
{
  std::atomic<int> batch_calls{ 0 };
  UserFunction f;
  f.name = "twice";
  f.kinds = { ArgKind::Real };
  f.point = [](std::span<const UserArgument> a, double& v)
  {
    v = 2 * a[0].values[0];
    return true;
  };
  f.batch = [&batch_calls](std::span<const UserBatchArgument> a, int n, double* v, unsigned char* failed)
  {
    ++batch_calls;
    for (int i = 0; i < n; ++i)
    {
      v[i] = 2 * a[0].values[i];
      failed[i] = a[0].values[i] < 0;
    }
  };
  const auto model = compile("m(x[3], a[1]) { m = twice(x[1]) + x[2]; }", registry_with(f));
  ASSERT_TRUE(model);
  std::vector<double> xs(600), ys(600, 1.0), zs(600, 0.0), values(600);
  for (int i = 0; i < 600; ++i)
  {
    xs[i] = i - 10;
  }
  const double* rows[3] = { xs.data(), ys.data(), zs.data() };
  BatchEvaluator batch(model->tape(), one_thread());
  EXPECT_EQ(batch.evaluate(rows, 600, values.data()), 10u) << "x < 0 fails in the batch form";
  EXPECT_EQ(values[100], 2.0 * 90 + 1);
  EXPECT_GE(batch_calls.load(), 3) << "one call per block of 256";
  EXPECT_LE(batch_calls.load(), 4);
}

} // namespace
} // namespace frep
