// Composed models (Compiler/combine.h): every operation bit-equal to the single HyperFun program
// written with the operator or library call, through the point and batch evaluators; the
// Cartesian product; specialisation of a composed model; error ids and messages of both
// operands (compiled guards and interpreted calls); s[]; interval enclosure; errors as values.
#include "Compiler/combine.h"
#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Semantics/detail/runtime_messages.h"
#include "Compiler/detail/tape_check.h"
#include "Language/parser.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace frep
{
namespace
{

std::shared_ptr<const Model> compile_text(const std::string& text,
  const std::string& file = "<test>")
{
  ParseResult parsed = parse_program(text, file);
  EXPECT_TRUE(parsed.ok()) << format_diagnostics(parsed.diagnostics);
  if (!parsed.ok())
  {
    return nullptr;
  }
  Model::CompileResult r = Model::compile(parsed.program, 0);
  EXPECT_TRUE(r.model) << format_diagnostics(r.diagnostics);
  return r.model;
}

bool same_bits(double a, double b)
{
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// `count` points of `dim` coordinates in [-3, 3], plus the special values every operation
/// must get right (0 and points on both surfaces).
std::vector<std::vector<double>> sample_points(int dim, int count, unsigned seed = 7)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::vector<std::vector<double>> points;
  points.push_back(std::vector<double>(static_cast<std::size_t>(dim), 0.0));
  for (int i = 0; i < count; ++i)
  {
    std::vector<double> p;
    for (int k = 0; k < dim; ++k)
    {
      p.push_back(u(rng));
    }
    points.push_back(std::move(p));
  }
  return points;
}

/// Every output of both tapes, at every point, with the point and the batch evaluators (both
/// SIMD levels at the extremes), is the same double; error ids agree as well.
void expect_same_tapes(const std::shared_ptr<const Tape>& expected,
  const std::shared_ptr<const Tape>& actual,
  const std::vector<std::vector<double>>& points)
{
  ASSERT_EQ(expected->input_count, actual->input_count);
  ASSERT_EQ(expected->outputs.size(), actual->outputs.size());
  eval::check_tape(*actual, "combine_test");
  PointEvaluator pe(expected);
  PointEvaluator pa(actual);
  std::vector<double> oe(expected->outputs.size());
  std::vector<double> oa(actual->outputs.size());
  for (const auto& p : points)
  {
    const int ee = pe.evaluate(p, oe);
    const int ea = pa.evaluate(p, oa);
    EXPECT_EQ(ee == 0, ea == 0);
    for (std::size_t k = 0; k < oe.size(); ++k)
    {
      EXPECT_TRUE(same_bits(oe[k], oa[k]) || (std::isnan(oe[k]) && std::isnan(oa[k])))
        << "output " << k << ": " << oe[k] << " vs " << oa[k] << " at (" << p[0] << ", ...)";
    }
  }

  // Batch: structure of arrays.
  const std::size_t n = points.size();
  std::vector<std::vector<double>> columns(expected->input_count, std::vector<double>(n));
  std::vector<const double*> inputs;
  for (std::size_t k = 0; k < columns.size(); ++k)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      columns[k][i] = points[i][k];
    }
    inputs.push_back(columns[k].data());
  }
  for (SimdLevel simd : { SimdLevel::Baseline, SimdLevel::Best })
  {
    BatchOptions options;
    options.simd = simd;
    options.threads = 2;
    options.block_size = 64; // several blocks
    BatchEvaluator be(expected, options);
    BatchEvaluator ba(actual, options);
    std::vector<double> ve(n), va(n);
    be.evaluate(inputs, n, ve.data());
    ba.evaluate(inputs, n, va.data());
    PointEvaluator check(actual);
    for (std::size_t i = 0; i < n; ++i)
    {
      EXPECT_TRUE(same_bits(ve[i], va[i]) || (std::isnan(ve[i]) && std::isnan(va[i])))
        << "batch point " << i << ": " << ve[i] << " vs " << va[i];
      EXPECT_TRUE(same_bits(va[i], check.value(points[i])) || std::isnan(va[i]))
        << "batch and point evaluators differ on the combined tape at point " << i;
    }
  }
}

// Two spheres with different centres; the radius comes from a[1] (fixed by the operand's
// specialisation) so that the operands' parameters are exercised too.
const char* BallA = "ball_a(x[3], a[1]) { ball_a = a[1]^2 - ((x[1] - 0.5)^2 + x[2]^2 + x[3]^2); }";
const char* BallB =
  "ball_b(x[3], a[1]) { ball_b = a[1]^2 - ((x[1] + 0.7)^2 + (x[2] - 0.2)^2 + x[3]^2); }";

std::string two_balls(const std::string& result)
{
  return "my_model(x[3], a[1]) {\n"
         "  s1 = 1.5^2 - ((x[1] - 0.5)^2 + x[2]^2 + x[3]^2);\n"
         "  s2 = 1.2^2 - ((x[1] + 0.7)^2 + (x[2] - 0.2)^2 + x[3]^2);\n"
         "  my_model = " +
         result + ";\n}\n";
}

Operand ball(const char* text, double radius)
{
  Operand o;
  o.model = compile_text(text);
  o.specialisation.parameters = { radius };
  return o;
}

std::shared_ptr<const Model> combine_balls(Operation op, OperationParameters p = {})
{
  CombineResult r = combine(op, ball(BallA, 1.5), ball(BallB, 1.2), p);
  EXPECT_TRUE(r.ok()) << r.error;
  return r.model;
}

TEST(CombineModel, SetOperationsEqualTheLanguageOperators)
{
  const auto points = sample_points(3, 600);
  const struct
  {
    Operation op;
    const char* expression;
  } cases[] = {
    { Operation::Union, "s1 | s2" },
    { Operation::Intersection, "s1 & s2" },
    { Operation::Difference, "s1 \\ s2" },
  };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(operation_name(c.op));
    auto combined = combine_balls(c.op);
    ASSERT_TRUE(combined);
    auto single = compile_text(two_balls(c.expression));
    ASSERT_TRUE(single);
    expect_same_tapes(single->tape(), combined->tape(), points);
  }
}

TEST(CombineModel, BlendsEqualTheLibraryFunctions)
{
  const auto points = sample_points(3, 600, 11);
  const OperationParameters p{ 0.5, 2.0, 0.7 };
  auto uni = combine_balls(Operation::BlendUnion, p);
  auto inter = combine_balls(Operation::BlendIntersection, p);
  ASSERT_TRUE(uni && inter);
  expect_same_tapes(
    compile_text(two_balls("hfBlendUni(s1, s2, 0.5, 2, 0.7)"))->tape(), uni->tape(), points);
  expect_same_tapes(
    compile_text(two_balls("hfBlendInt(s1, s2, 0.5, 2, 0.7)"))->tape(), inter->tape(), points);
  // The defaults are a0 = a1 = a2 = 1.
  expect_same_tapes(compile_text(two_balls("hfBlendUni(s1, s2, 1, 1, 1)"))->tape(),
    combine_balls(Operation::BlendUnion)->tape(),
    points);
}

TEST(CombineModel, DescribesItself)
{
  auto u = combine_balls(Operation::Union);
  ASSERT_TRUE(u);
  EXPECT_EQ(u->name(), "union(ball_a, ball_b)");
  EXPECT_EQ(u->x_dim(), 3);
  EXPECT_EQ(u->a_dim(), 0);
  EXPECT_EQ(u->s_dim(), 1); // an object without s[..] has s[1], as in the original
  EXPECT_EQ(u->program(), nullptr);
  EXPECT_EQ(u->object_index(), -1);
  EXPECT_TRUE(u->is_compiled());
  EXPECT_GT(u->node_count(), 0u);
  EXPECT_EQ(
    combine_balls(Operation::BlendIntersection)->name(), "blend_intersection(ball_a, ball_b)");
  EXPECT_FALSE(u->tape()->can_fail);
}

TEST(CombineModel, CartesianProductOfDiscAndIntervalIsACylinder)
{
  Operand disc{ compile_text("disc(x[2], a[1]) { disc = 1 - (x[1]^2 + x[2]^2); }"), {} };
  Operand slab{ compile_text("slab(x[1], a[1]) { slab = (x[1] + 2) & (2 - x[1]); }"), {} };
  CombineResult r = combine(Operation::CartesianProduct, disc, slab);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.model->x_dim(), 3);
  EXPECT_EQ(r.model->name(), "product(disc, slab)");
  auto cylinder = compile_text(R"(my_model(x[3], a[1]) {
  d = 1 - (x[1]^2 + x[2]^2);
  h = (x[3] + 2) & (2 - x[3]);
  my_model = d @ h;
})");
  const auto points = sample_points(3, 600, 3);
  expect_same_tapes(cylinder->tape(), r.model->tape(), points);
  PointEvaluator pe(r.model->tape());
  EXPECT_GT(pe.value(std::vector<double>{ 0.0, 0.5, 1.9 }), 0.0); // inside
  EXPECT_LT(pe.value(std::vector<double>{ 0.0, 0.5, 2.1 }), 0.0); // above the top
  EXPECT_LT(pe.value(std::vector<double>{ 1.1, 0.0, 0.0 }), 0.0); // beside the disc

  // The operands' own free-coordinate order decides the result's coordinates: with the disc's
  // coordinates swapped (and its x[1] written differently) result coordinate 0 is disc x[2].
  Operand skew{ compile_text("skew(x[2], a[1]) { skew = 1 - (x[1]^2 + 4 * x[2]^2); }"), {} };
  skew.specialisation.input_order = { 1, 0 };
  CombineResult swapped = combine(Operation::CartesianProduct, skew, slab);
  ASSERT_TRUE(swapped.ok()) << swapped.error;
  auto written = compile_text(R"(my_model(x[3], a[1]) {
  d = 1 - (x[2]^2 + 4 * x[1]^2);
  h = (x[3] + 2) & (2 - x[3]);
  my_model = d @ h;
})");
  expect_same_tapes(written->tape(), swapped.model->tape(), points);
}

TEST(CombineModel, OperandSpecialisationFixesCoordinatesAndParameters)
{
  // A 4-D operand cut at x[4] = 0.25 is a 3-D operand.
  Operand morph{
    compile_text("morph(x[4], a[1]) { morph = a[1] - (x[1]^2 + x[2]^2 + x[3]^2) - x[4]; }"), {}
  };
  morph.specialisation.parameters = { 2.0 };
  morph.specialisation.fixed = { std::nullopt, std::nullopt, std::nullopt, 0.25 };
  CombineResult r = combine(Operation::Union, morph, ball(BallB, 1.2));
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.model->x_dim(), 3);
  auto single = compile_text(R"(my_model(x[3], a[1]) {
  s1 = 2 - (x[1]^2 + x[2]^2 + x[3]^2) - 0.25;
  s2 = 1.2^2 - ((x[1] + 0.7)^2 + (x[2] - 0.2)^2 + x[3]^2);
  my_model = s1 | s2;
})");
  expect_same_tapes(single->tape(), r.model->tape(), sample_points(3, 300, 5));
}

TEST(CombineModel, SpecialisingEqualsEvaluatingAtTheFixedValue)
{
  auto u = combine_balls(Operation::BlendUnion, { 0.3, 1.0, 1.0 });
  ASSERT_TRUE(u);
  PointEvaluator full(u->tape());
  // x2 fixed, the free ones in the order (x3, x1).
  Specialisation s;
  s.fixed = { std::nullopt, 0.3, std::nullopt };
  s.input_order = { 2, 0 };
  auto slice = u->specialise(s);
  ASSERT_EQ(slice->input_count, 2u);
  eval::check_tape(*slice, "combine_test");
  PointEvaluator cut(slice);
  for (const auto& p : sample_points(2, 300, 9))
  {
    const double v = full.value(std::vector<double>{ p[1], 0.3, p[0] });
    EXPECT_TRUE(same_bits(v, cut.value(p))) << v << " vs " << cut.value(p);
  }

  // The product with one operand's only coordinate fixed: that operand folds to a constant.
  Operand disc{ compile_text("disc(x[2], a[1]) { disc = 1 - (x[1]^2 + x[2]^2); }"), {} };
  Operand slab{ compile_text("slab(x[1], a[1]) { slab = (x[1] + 2) & (2 - x[1]); }"), {} };
  auto product = combine(Operation::CartesianProduct, disc, slab).model;
  ASSERT_TRUE(product);
  PointEvaluator cylinder(product->tape());
  for (double z : { -2.5, 0.0, 1.25 })
  {
    Specialisation at_z;
    at_z.fixed = { std::nullopt, std::nullopt, z };
    PointEvaluator section(product->specialise(at_z));
    Specialisation at_x;
    at_x.fixed = { z, std::nullopt, std::nullopt };
    PointEvaluator side(product->specialise(at_x));
    for (const auto& p : sample_points(2, 100, 13))
    {
      EXPECT_TRUE(
        same_bits(cylinder.value(std::vector<double>{ p[0], p[1], z }), section.value(p)));
      EXPECT_TRUE(same_bits(cylinder.value(std::vector<double>{ z, p[0], p[1] }), side.value(p)));
    }
  }
  // Every coordinate fixed: a constant tape.
  Specialisation all;
  all.fixed = { 0.1, 0.2, 0.3 };
  auto constant = u->specialise(all);
  EXPECT_EQ(constant->input_count, 0u);
  PointEvaluator pc(constant);
  EXPECT_TRUE(same_bits(pc.value({}), full.value(std::vector<double>{ 0.1, 0.2, 0.3 })));
  // Inconsistent sizes are programming errors, as for any model.
  Specialisation bad;
  bad.fixed.resize(4);
  EXPECT_THROW(u->specialise(bad), std::invalid_argument);
}

TEST(CombineModel, CombinedModelsCombineAgain)
{
  auto u = combine_balls(Operation::Union);
  Operand third{
    compile_text("third(x[3], a[1]) { third = 1 - ((x[1] - 2)^2 + x[2]^2 + x[3]^2); }"), {}
  };
  CombineResult r = combine(Operation::Difference, Operand{ u, {} }, third);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.model->name(), "difference(union(ball_a, ball_b), third)");
  auto single = compile_text(two_balls("s1 | s2 \\ (1 - ((x[1] - 2)^2 + x[2]^2 + x[3]^2))"));
  expect_same_tapes(single->tape(), r.model->tape(), sample_points(3, 400, 17));
}

TEST(CombineModel, ErrorsOfBothOperandsKeepTheirMessages)
{
  // A fails where x1 < 0 (square root), B where x2 <= 0 (log).
  Operand a{ compile_text("fa(x[2], a[1]) {\n  fa = 1 - sqrt(x[1]);\n}", "a.hf"), {} };
  Operand b{ compile_text("fb(x[2], a[1]) {\n  t = 2;\n  fb = log(x[2]) - t;\n}", "b.hf"), {} };
  CombineResult r = combine(Operation::Union, a, b);
  ASSERT_TRUE(r.ok()) << r.error;
  auto tape = r.model->tape();
  EXPECT_TRUE(tape->can_fail);
  PointEvaluator pe(tape);
  std::vector<double> out(1);
  const auto message = [&](std::vector<double> p) -> std::string
  {
    const int id = pe.evaluate(p, out);
    if (id <= 0 || static_cast<std::size_t>(id) > tape->errors.size())
    {
      return "none";
    }
    const TapeError& e = tape->errors[static_cast<std::size_t>(id - 1)];
    return e.message + " @" + e.file + ":" + std::to_string(e.location.line);
  };
  EXPECT_EQ(message({ 1.0, 1.0 }), "none");
  EXPECT_EQ(message({ -1.0, 1.0 }), std::string(messages::kNegativeSqrt) + " @a.hf:2");
  EXPECT_EQ(message({ 1.0, -1.0 }), std::string(messages::kNegativeLog) + " @b.hf:3");
  // Both fail: the right operand is evaluated first, as the original evaluates `A | B`.
  EXPECT_EQ(message({ -1.0, -1.0 }), std::string(messages::kNegativeLog) + " @b.hf:3");
  EXPECT_TRUE(std::isnan(out[0]));

  // The batch evaluator reports the same ids.
  const std::vector<double> x1{ 1.0, -1.0, 1.0, -1.0 };
  const std::vector<double> x2{ 1.0, 1.0, -1.0, -1.0 };
  const double* columns[] = { x1.data(), x2.data() };
  std::vector<double> values(4);
  std::vector<std::uint32_t> ids(4);
  BatchEvaluator be(tape);
  EXPECT_EQ(be.evaluate(columns, 4, values.data(), ids.data()), 3u);
  for (std::size_t i = 0; i < 4; ++i)
  {
    EXPECT_EQ(static_cast<int>(ids[i]), pe.evaluate(std::vector<double>{ x1[i], x2[i] }, out));
  }
}

TEST(CombineModel, InterpretedOperandsReportTheirErrorsThroughTheJoinedTable)
{
  // A loop on x cannot be compiled: the operand's tape is one call to the interpreter, whose
  // error ids are those of its own table; after the join they must name the same errors.
  Operand a{ compile_text(R"(looped(x[2], a[1])
{
  n = 0; v = x[1];
  while v > 1 loop
    v = v / 2; n = n + 1;
  endloop;
  looped = sqrt(x[2]) - n;
})"),
    {} };
  ASSERT_FALSE(a.model->is_compiled());
  Operand b{ compile_text("fb(x[2], a[1]) {\n  fb = 1 / x[1];\n}"), {} };
  for (Operation op : { Operation::Intersection, Operation::BlendUnion })
  {
    CombineResult r = combine(op, a, b);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_FALSE(r.model->is_compiled());
    EXPECT_NE(r.model->fallback_reason().find("looped"), std::string::npos);
    auto tape = r.model->tape();
    PointEvaluator pe(tape);
    std::vector<double> out(1);
    const int sqrt_error = pe.evaluate(std::vector<double>{ 10.0, -1.0 }, out);
    ASSERT_GT(sqrt_error, 0);
    EXPECT_EQ(
      tape->errors[static_cast<std::size_t>(sqrt_error - 1)].message, messages::kNegativeSqrt);
    EXPECT_EQ(tape->errors[static_cast<std::size_t>(sqrt_error - 1)].location.line, 7);
    const int division = pe.evaluate(std::vector<double>{ 0.0, 1.0 }, out);
    ASSERT_GT(division, 0);
    EXPECT_EQ(
      tape->errors[static_cast<std::size_t>(division - 1)].message, messages::kDivisionByZero);
    // Values where nothing fails: the interpreted operand gives n = 4 for x1 = 10.
    EXPECT_EQ(pe.evaluate(std::vector<double>{ 10.0, 4.0 }, out), 0);
    auto reference = compile_text(
      std::string("my_model(x[2], a[1]) { s1 = 2 - 4; s2 = 1 / 10; "
                  "my_model = ") +
      (op == Operation::Intersection ? "s1 & s2" : "hfBlendUni(s1, s2, 1, 1, 1)") + "; }");
    PointEvaluator pr(reference->tape());
    EXPECT_TRUE(same_bits(out[0], pr.value(std::vector<double>{ 0.0, 0.0 })));

    // Nested: the call is wrapped once more, its ids still land on the right entries.
    Operand c{ compile_text("fc(x[2], a[1]) {\n\n  fc = log(x[1] + 5);\n}"), {} };
    CombineResult nested = combine(Operation::Union, c, Operand{ r.model, {} });
    ASSERT_TRUE(nested.ok()) << nested.error;
    auto nested_tape = nested.model->tape();
    PointEvaluator pn(nested_tape);
    const int id = pn.evaluate(std::vector<double>{ 10.0, -1.0 }, out);
    ASSERT_GT(id, 0);
    EXPECT_EQ(
      nested_tape->errors[static_cast<std::size_t>(id - 1)].message, messages::kNegativeSqrt);
    const int log_id = pn.evaluate(std::vector<double>{ -6.0, 1.0 }, out);
    ASSERT_GT(log_id, 0);
    EXPECT_EQ(nested_tape->errors[static_cast<std::size_t>(log_id - 1)].location.line, 3);
  }
}

TEST(CombineModel, AttributesFollowTheGreaterOperand)
{
  Operand a{ compile_text(R"(painted_a(x[3], a[1], s[2])
{
  s[1] = 10 + x[1]; s[2] = 20;
  painted_a = 1 - (x[1]^2 + x[2]^2 + x[3]^2);
})"),
    {} };
  Operand b{ compile_text(R"(painted_b(x[3], a[1], s[1])
{
  s[1] = 30;
  painted_b = 1 - ((x[1] - 1)^2 + x[2]^2 + x[3]^2);
})"),
    {} };
  ASSERT_EQ(a.model->s_dim(), 2);
  ASSERT_EQ(b.model->s_dim(), 1);
  CombineResult r = combine(Operation::Union, a, b);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.model->s_dim(), 2);
  auto tape = r.model->tape();
  ASSERT_EQ(tape->outputs.size(), 3u);
  PointEvaluator pe(tape);
  std::vector<double> out(3);
  // Near A's centre F_A > F_B: A's s[].
  ASSERT_EQ(pe.evaluate(std::vector<double>{ -0.25, 0.0, 0.0 }, out), 0);
  EXPECT_EQ(out[1], 9.75);
  EXPECT_EQ(out[2], 20.0);
  // Near B's centre: B's s[1], and 0 beyond B's s_dim.
  ASSERT_EQ(pe.evaluate(std::vector<double>{ 1.25, 0.0, 0.0 }, out), 0);
  EXPECT_EQ(out[1], 30.0);
  EXPECT_EQ(out[2], 0.0);
  // Half way F_A == F_B: A's.
  ASSERT_EQ(pe.evaluate(std::vector<double>{ 0.5, 0.0, 0.0 }, out), 0);
  EXPECT_EQ(out[1], 10.5);
  // The product follows the same rule.
  Operand line{ compile_text("line(x[1], a[1], s[1]) { s[1] = 7; line = 1 - x[1]^2; }"), {} };
  CombineResult p = combine(Operation::CartesianProduct, line, b);
  ASSERT_TRUE(p.ok()) << p.error;
  EXPECT_EQ(p.model->x_dim(), 4);
  EXPECT_EQ(p.model->s_dim(), 1);
  PointEvaluator pp(p.model->tape());
  std::vector<double> out2(2);
  ASSERT_EQ(pp.evaluate(std::vector<double>{ 0.0, 1.0, 0.0, 0.0 }, out2), 0); // 1 >= 1: line's
  EXPECT_EQ(out2[1], 7.0);
  ASSERT_EQ(pp.evaluate(std::vector<double>{ 0.9, 1.0, 0.0, 0.0 }, out2), 0);
  EXPECT_EQ(out2[1], 30.0);
}

TEST(CombineModel, IntervalsEncloseSampledValues)
{
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (Operation op : { Operation::Union,
         Operation::Intersection,
         Operation::Difference,
         Operation::BlendUnion,
         Operation::BlendIntersection })
  {
    SCOPED_TRACE(operation_name(op));
    auto model = combine_balls(op, { 0.5, 2.0, 0.7 });
    ASSERT_TRUE(model);
    auto tape = model->tape();
    IntervalEvaluator ie(tape);
    PointEvaluator pe(tape);
    for (int box = 0; box < 60; ++box)
    {
      std::vector<Interval> b(3);
      for (Interval& i : b)
      {
        const double c = u(rng);
        const double half = 0.05 + unit(rng);
        i = Interval{ c - half, c + half };
      }
      const IntervalResult r = ie.evaluate(b);
      EXPECT_FALSE(r.may_fail);
      for (int k = 0; k < 40; ++k)
      {
        std::vector<double> p;
        for (const Interval& i : b)
        {
          p.push_back(i.lo + (i.hi - i.lo) * unit(rng));
        }
        const double v = pe.value(p);
        EXPECT_TRUE(r.value.contains(v))
          << v << " not in [" << r.value.lo << ", " << r.value.hi << "]";
      }
    }
  }
}

TEST(CombineModel, BadOperandsAreErrorValues)
{
  Operand ball3 = ball(BallA, 1.0);
  Operand disc{ compile_text("disc(x[2], a[1]) { disc = 1 - (x[1]^2 + x[2]^2); }"), {} };
  for (Operation op : { Operation::Union,
         Operation::Intersection,
         Operation::Difference,
         Operation::BlendUnion,
         Operation::BlendIntersection })
  {
    CombineResult r;
    EXPECT_NO_THROW(r = combine(op, ball3, disc));
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("same number of free coordinates"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("ball_a has 3 and disc has 2"), std::string::npos) << r.error;
  }
  // Fixing one of the ball's coordinates makes the dimensions match.
  Operand cut = ball3;
  cut.specialisation.fixed = { std::nullopt, std::nullopt, 0.5 };
  EXPECT_TRUE(combine(Operation::Union, cut, disc).ok());
  // The product takes any dimensions.
  EXPECT_TRUE(combine(Operation::CartesianProduct, ball3, disc).ok());

  CombineResult empty = combine(Operation::Union, Operand{}, disc);
  EXPECT_FALSE(empty.ok());
  EXPECT_NE(empty.error.find("operand A has no model"), std::string::npos) << empty.error;
  EXPECT_FALSE(combine(Operation::CartesianProduct, disc, Operand{}).ok());

  Operand wrong = disc;
  wrong.specialisation.input_order = { 0, 0 };
  CombineResult bad = combine(Operation::CartesianProduct, disc, wrong);
  EXPECT_FALSE(bad.ok());
  EXPECT_NE(bad.error.find("operand B (disc)"), std::string::npos) << bad.error;
  wrong.specialisation = {};
  wrong.specialisation.fixed.resize(3);
  EXPECT_FALSE(combine(Operation::Union, wrong, disc).ok());
}

// compose: F(g_1(y), g_2(y)) is, bit for bit, the program that calls F on the g's values (the
// same operations on the same doubles); fixing a coordinate of the composed model fixes it in the
// g's; a coordinate may feed F directly or be read by nothing; every misuse is refused.
TEST(ComposeModel, EqualsTheProgramThatCallsTheOuterModelOnTheFunctions)
{
  const auto f = compile_text("f(x[2], a[1]) { f = a[1] - (x[1]*x[1] + x[2]*x[2]); }");
  const auto g = compile_text("g(x[3], a[1]) { g = sin(x[3]) + x[2]; }");
  const auto expected = compile_text(
    "e(x[3], a[1]) { my = sin(x[3]) + x[2]; e = 2 - (x[1]*x[1] + my*my); }");
  Operand outer{ f, {} };
  outer.specialisation.parameters = { 2.0 };
  const CombineResult composed =
    compose(outer, { CoordinateFunction{ 0, {} }, CoordinateFunction{ -1, Operand{ g, {} } } }, 3);
  ASSERT_TRUE(composed.ok()) << composed.error;
  EXPECT_EQ(composed.model->name(), "compose(f)");
  EXPECT_EQ(composed.model->x_dim(), 3);
  expect_same_tapes(expected->tape(), composed.model->tape(), sample_points(3, 300));

  Specialisation fixed; // x3 fixed at 0.7: the g's see it too
  fixed.fixed = { std::nullopt, std::nullopt, 0.7 };
  expect_same_tapes(expected->specialise(fixed), composed.model->specialise(fixed),
    sample_points(2, 100, 11));
  IntervalEvaluator intervals(composed.model->tape());
  const Interval box[3] = { { -0.1, 0.1 }, { -0.1, 0.1 }, { -0.1, 0.1 } };
  const IntervalResult r = intervals.evaluate(box);
  const double lowest = 2.0 - (0.01 + std::pow(std::sin(0.1) + 0.1, 2)); // at a corner
  EXPECT_LE(r.value.lo, lowest); // sound, and as tight as the composed tape makes it
  EXPECT_GE(r.value.lo, lowest - 0.05);
  EXPECT_GE(r.value.hi, 2.0);

  const auto refused = [&](Operand o, std::vector<CoordinateFunction> c, int x_dim,
                         const char* why)
  {
    const CombineResult bad = compose(std::move(o), std::move(c), x_dim);
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(bad.error.find(why), std::string::npos) << bad.error;
  };
  const CoordinateFunction x1{ 0, {} }, gy{ -1, Operand{ g, {} } };
  refused(Operand{}, { x1, x1 }, 3, "outer model is missing");
  refused(outer, { x1 }, 3, "has 2 free coordinates but 1 are given");
  refused(outer, { x1, CoordinateFunction{ 3, {} } }, 3, "is x4, not one of x1..x3");
  refused(outer, { x1, gy }, 2, "(g) has 3 free coordinates, the composed model 2");
  refused(outer, { x1, x1 }, 0, "at least one coordinate");
}

} // namespace
} // namespace frep
