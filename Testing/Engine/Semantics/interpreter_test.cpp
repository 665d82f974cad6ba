// Unit tests of the reference interpreter (the conformance suite is the broad check; these pin
// the API contract: state between points, error reporting, object calls, robustness, threads).
#include "Semantics/interpreter.h"
#include "Semantics/detail/runtime_messages.h"
#include "Language/parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

namespace frep
{
namespace
{

std::shared_ptr<const ast::Program> parse(const std::string& text)
{
  ParseResult r = parse_program(text, "<test>");
  if (!r.ok())
  {
    ADD_FAILURE() << format_diagnostics(r.diagnostics);
    return nullptr;
  }
  return r.program;
}

Interpreter make(const std::string& text,
  const std::string& object = "my_model",
  const InterpreterOptions& options = {})
{
  auto program = parse(text);
  if (!program)
  {
    throw std::runtime_error("parse failed");
  }
  return Interpreter(program, ast::select_object(*program, object), options);
}

void expect_error(const PointResult& r, const std::string& message, int line, int column)
{
  ASSERT_TRUE(r.error.has_value()) << "expected " << message << ", got value " << r.value;
  EXPECT_EQ(r.error->message, message);
  EXPECT_EQ(r.error->location.line, line) << message;
  EXPECT_EQ(r.error->location.column, column) << message;
  EXPECT_FALSE(r.error->abort);
}

double value_of(const PointResult& r)
{
  EXPECT_FALSE(r.error.has_value()) << (r.error ? r.error->message : "");
  return r.value;
}

TEST(Interpreter, EvaluatesASphere)
{
  Interpreter in =
    make("my_model(x[3], a[1])\n{\n  my_model = a[1]^2 - x[1]^2 - x[2]^2 - x[3]^2;\n}\n");
  const double a[] = { 2 };
  in.set_parameters(a);
  const double p[] = { 1, 0, 0 };
  EXPECT_EQ(value_of(in.evaluate(p)), 3.0);
  const double q[] = { 0, 0, 0.5 };
  EXPECT_EQ(value_of(in.evaluate(q)), 3.75);
  EXPECT_EQ(in.object().name, "my_model");
}

TEST(Interpreter, SequenceKeepsAttributesUntilReset)
{
  // Reading s[1] before writing it gives the previous point's value (0 at first).
  Interpreter in = make("my_model(x[3], a[1], s[2])\n{\n  old = s[1];\n  s[1] = x[1];\n"
                        "  s[2] = old;\n  my_model = old;\n}\n");
  const double p1[] = { 1, 0, 0 };
  const double p2[] = { 2, 0, 0 };
  EXPECT_EQ(value_of(in.evaluate(p1)), 0.0);
  EXPECT_EQ(value_of(in.evaluate(p2)), 1.0);
  ASSERT_EQ(in.attributes().size(), 2u);
  EXPECT_EQ(in.attributes()[0], 2.0);
  EXPECT_EQ(in.attributes()[1], 1.0);
  in.reset_attributes(); // fresh mode
  EXPECT_EQ(value_of(in.evaluate(p1)), 0.0);
}

TEST(Interpreter, SequenceKeepsParametersWrittenByTheModel)
{
  // hfShift3D writes into a[] in place; the change persists to the next point.
  Interpreter in = make("my_model(x[3], a[3])\n{\n  t = hfShift3D(a, 1, 0, 0);\n"
                        "  my_model = a[1];\n}\n");
  const double a[] = { 10, 0, 0 };
  in.set_parameters(a);
  const double p[] = { 0, 0, 0 };
  EXPECT_EQ(value_of(in.evaluate(p)), 9.0);
  EXPECT_EQ(value_of(in.evaluate(p)), 8.0);
  EXPECT_EQ(in.parameters()[0], 8.0);
  in.set_parameters(a); // fresh mode sets a[] again
  EXPECT_EQ(value_of(in.evaluate(p)), 9.0);
}

TEST(Interpreter, LocalsAreUnsetAtEveryEvaluation)
{
  Interpreter in = make("my_model(x[3], a[1])\n{\n  if x[1] > 0 then v = 1; endif;\n"
                        "  my_model = v;\n}\n");
  const double yes[] = { 1, 0, 0 };
  const double no[] = { -1, 0, 0 };
  EXPECT_EQ(value_of(in.evaluate(yes)), 1.0);
  expect_error(in.evaluate(no), messages::kNotInitialized, 4, 14);
  EXPECT_EQ(value_of(in.evaluate(yes)), 1.0);
}

TEST(Interpreter, ReportsErrorsAtTheOriginalsPositions)
{
  Interpreter in = make("my_model(x[3], a[1])\n"
                        "{\n"
                        "  array v[2];\n"
                        "  v[1] = 5;\n"
                        "  q = 0;\n"
                        "  if x[2] = 1 then q = 1 / x[1]; endif;\n"
                        "  if x[2] = 2 then q = sqrt(x[1]); endif;\n"
                        "  if x[2] = 3 then q = v[x[1]]; endif;\n"
                        "  if x[2] = 4 then v[x[1] + 0] = 1; endif;\n"
                        "  if x[2] = 5 then q = v[2]; endif;\n"
                        "  if x[2] = 6 then q = x[1] ^ 0.5; endif;\n"
                        "  if x[2] = 7 then q = 1 / 0 + sqrt(-1); endif;\n"
                        "  my_model = q;\n"
                        "}\n");
  auto at = [&](double x1, double sub) { return in.evaluate(std::vector<double>{ x1, sub, 0 }); };
  expect_error(at(0, 1), messages::kDivisionByZero, 6, 26);
  expect_error(at(1e-7, 1), messages::kDivisionByZero, 6, 26);
  EXPECT_EQ(value_of(at(4, 1)), 0.25);
  expect_error(at(-1, 2), messages::kNegativeSqrt, 7, 24);
  expect_error(at(3, 3), messages::kIndexOutOfRange, 8, 28);    // read: the index's first code
  expect_error(at(3, 4), messages::kIndexOutOfRange, 9, 22);    // write: the index's first token
  expect_error(at(0, 5), messages::kUnassignedElement, 10, 24); // the array name
  expect_error(at(-8, 6), messages::kNegativePowerBase, 11, 29);
  // Right operand first: the square root fails before the division is attempted.
  expect_error(at(0, 7), messages::kNegativeSqrt, 12, 32);
  EXPECT_EQ(value_of(at(1, 3)), 5.0);
}

TEST(Interpreter, ConditionsDoNotShortCircuit)
{
  Interpreter in = make("my_model(x[3], a[1])\n{\n  q = 0;\n"
                        "  if 1 / x[1] > 0 or x[2] > 0 then q = 1; endif;\n  my_model = q;\n}\n");
  const double p[] = { 0, 1, 0 }; // the right operand is true, the left one still runs
  expect_error(in.evaluate(p), messages::kDivisionByZero, 4, 8);
}

TEST(Interpreter, BuiltinQuirks)
{
  Interpreter in = make("my_model(x[3], a[1], s[6])\n{\n  s = [0, 0, 0, 0, 0, 0];\n"
                        "  s[1] = sign(x[1]);\n  s[2] = mod(x[1], x[2]);\n  s[3] = int(x[1]);\n"
                        "  s[4] = frac(x[1]);\n  s[5] = max(x[1], x[2]);\n"
                        "  s[6] = atan2(x[1], x[2]);\n  my_model = 0;\n}\n");
  const double p[] = { -7.4, 3, 0 };
  value_of(in.evaluate(p));
  const auto s = in.attributes();
  EXPECT_EQ(s[0], 1.0); // sign() is always 1 in the original
  EXPECT_EQ(s[1], std::fmod(-7.0, 3.0));
  EXPECT_EQ(s[2], -7.0);
  EXPECT_EQ(s[3], -7.4 + 7.0);
  EXPECT_EQ(s[4], 3.0);
  EXPECT_EQ(s[5], std::atan2(-7.4, 3.0));
}

TEST(Interpreter, ObjectCallsCopyXAndAButCopyBackS)
{
  const std::string text = "helper(x[3], a[1], s[2])\n"
                           "{\n"
                           "  t = hfShift3D(x, 100, 0, 0);\n"
                           "  s[1] = s[1] + 1;\n"
                           "  s[2] = x[1];\n"
                           "  helper = x[1] + a[1];\n"
                           "}\n"
                           "my_model(x[3], a[1], s[2])\n"
                           "{\n"
                           "  array t[2];\n"
                           "  t = [10, 0];\n"
                           "  v = helper(x, a, t);\n"
                           "  s[1] = t[1];\n"
                           "  s[2] = t[2];\n"
                           "  my_model = v + x[1];\n"
                           "}\n";
  Interpreter in = make(text);
  const double a[] = { 0.5 };
  in.set_parameters(a);
  const double p[] = { 1, 0, 0 };
  // helper sees x[1] = 1 - 100 after its own shift; the caller's x[1] stays 1.
  EXPECT_EQ(value_of(in.evaluate(p)), (1.0 - 100.0 + 0.5) + 1.0);
  EXPECT_EQ(in.attributes()[0], 11.0);
  EXPECT_EQ(in.attributes()[1], -99.0);
}

TEST(Interpreter, OmittedThirdArgumentPassesTheCallersS)
{
  Interpreter in = make("helper(x[3], a[1])\n{\n  s[1] = s[1] + 5;\n  helper = s[1];\n}\n"
                        "my_model(x[3], a[1])\n{\n  s[1] = 2;\n  my_model = helper(x, a);\n}\n");
  const double p[] = { 0, 0, 0 };
  EXPECT_EQ(value_of(in.evaluate(p)), 7.0);
  EXPECT_EQ(in.attributes()[0], 7.0);
}

TEST(Interpreter, ErrorsInsideACalleeCarryTheCalleesPositions)
{
  Interpreter in = make("helper(x[3], a[1])\n{\n  helper = 1 / x[1];\n}\n"
                        "my_model(x[3], a[1])\n{\n  my_model = helper(x, a) + 1;\n}\n");
  const double p[] = { 0, 0, 0 };
  expect_error(in.evaluate(p), messages::kDivisionByZero, 3, 14);
}

TEST(Interpreter, UnassignedArraysPassedWhole)
{
  Interpreter in = make("helper(x[3], a[2])\n{\n  helper = a[1] + a[2];\n}\n"
                        "my_model(x[3], a[1])\n{\n  array p[2], c[3];\n  p[1] = 1;\n"
                        "  c[1] = 0; c[2] = 0;\n"
                        "  if x[1] > 0 then p[2] = 2; c[3] = 0; endif;\n"
                        "  q = 0;\n"
                        "  if x[2] = 0 then q = helper(x, p); endif;\n"
                        "  if x[2] = 1 then q = hfSphere(x, c, 2); endif;\n"
                        "  my_model = q;\n}\n");
  const double ok[] = { 1, 0, 0 };
  EXPECT_EQ(value_of(in.evaluate(ok)), 3.0);
  // Object call, s omitted: the original reports the a argument at the closing parenthesis.
  const double bad_object[] = { -1, 0, 0 };
  expect_error(in.evaluate(bad_object), messages::kUnassignedArray, 12, 35);
  // Library call: at the array's name.
  const double bad_library[] = { -1, 1, 0 };
  expect_error(in.evaluate(bad_library), messages::kUnassignedArray, 13, 36);
}

TEST(Interpreter, LoopIterationCap)
{
  InterpreterOptions options;
  options.max_loop_iterations = 1000;
  Interpreter in = make("my_model(x[3], a[1])\n{\n  i = 0;\n  while i < x[1] loop\n"
                        "    i = i + 1;\n  endloop;\n  my_model = i;\n}\n",
    "my_model",
    options);
  const double small[] = { 1000, 0, 0 };
  EXPECT_EQ(value_of(in.evaluate(small)), 1000.0);
  const double big[] = { 1001, 0, 0 };
  const PointResult r = in.evaluate(big);
  ASSERT_TRUE(r.error.has_value());
  EXPECT_EQ(r.error->message, kLoopLimitMessage);
  EXPECT_EQ(r.error->location.line, 4);
  EXPECT_EQ(r.error->location.column, 3);
  // The budget is per evaluation.
  EXPECT_EQ(value_of(in.evaluate(small)), 1000.0);
}

TEST(Interpreter, WrongPointSizesDoNotCrash)
{
  Interpreter in = make("my_model(x[3], a[2])\n{\n  my_model = x[1] + x[3] + a[2];\n}\n");
  const double few[] = { 1 };
  in.set_parameters(std::span<const double>());
  EXPECT_EQ(value_of(in.evaluate(few)), 1.0); // missing coordinates are 0
  const double many[] = { 1, 2, 3, 4, 5 };
  in.set_parameters(many);
  EXPECT_EQ(value_of(in.evaluate(many)), 1.0 + 3.0 + 2.0);
}

TEST(Interpreter, RejectsInvalidConstruction)
{
  auto program = parse("my_model(x[3], a[1])\n{\n  my_model = x[1];\n}\n");
  ASSERT_TRUE(program);
  EXPECT_THROW(Interpreter(nullptr, 0), std::invalid_argument);
  EXPECT_THROW(Interpreter(program, 1), std::invalid_argument);
  EXPECT_THROW(Interpreter(program, -1), std::invalid_argument);

  // A hand-made AST in which an object calls itself (the parser can never produce it).
  auto bad = std::make_shared<ast::Program>();
  ast::Object o;
  o.name = "loop";
  o.x_dim = 3;
  o.a_dim = 1;
  o.result = std::make_unique<ast::Expr>();
  ast::ObjectCallExpr call;
  call.object = 0;
  call.x.kind = ast::ArrayKind::X;
  call.a.kind = ast::ArrayKind::A;
  o.result->node = std::move(call);
  bad->objects.push_back(std::move(o));
  EXPECT_THROW(Interpreter(bad, 0), std::invalid_argument);

  // A scalar slot that does not exist.
  auto bad_slot = std::make_shared<ast::Program>();
  ast::Object p;
  p.name = "p";
  p.x_dim = 3;
  p.result = std::make_unique<ast::Expr>();
  p.result->node = ast::ScalarExpr{ 4 };
  bad_slot->objects.push_back(std::move(p));
  EXPECT_THROW(Interpreter(bad_slot, 0), std::invalid_argument);
}

TEST(Interpreter, IsMovable)
{
  Interpreter a = make("my_model(x[3], a[1])\n{\n  my_model = x[1] * 2;\n}\n");
  Interpreter b = std::move(a);
  const double p[] = { 2, 0, 0 };
  EXPECT_EQ(value_of(b.evaluate(p)), 4.0);
}

TEST(Interpreter, TwoThreadsOverOneProgramGiveIdenticalResults)
{
  auto program =
    parse("helper(x[3], a[1])\n{\n  array c[3];\n  c = [0.1, 0.2, 0.3];\n"
          "  helper = hfSphere(x, c, a[1]);\n}\n"
          "my_model(x[3], a[1], s[1])\n{\n  array xt[3];\n"
          "  xt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3];\n"
          "  t = hfRotate3DZ(xt, 0.3);\n  i = 0; acc = 0;\n"
          "  while i < 5 loop acc = acc + sin(xt[1] * i) | cos(xt[2]); i = i + 1; endloop;\n"
          "  s[1] = s[1] + 1;\n"
          "  my_model = helper(xt, a) & acc \\ (x[3] ^ 2 - 0.1);\n}\n");
  ASSERT_TRUE(program);
  const int index = ast::select_object(*program, "my_model");
  constexpr int kPoints = 20000;
  auto run = [&](std::vector<double>& out)
  {
    Interpreter in(program, index);
    const double a[] = { 1.5 };
    in.set_parameters(a);
    out.resize(kPoints);
    for (int i = 0; i < kPoints; ++i)
    {
      const double t = i * 0.001;
      const double p[] = { std::sin(t) * 2, std::cos(t * 1.3), t - 10 };
      const PointResult r = in.evaluate(p);
      out[i] = r.error ? -1e300 : r.value;
    }
    out.push_back(in.attributes()[0]); // s[1] counted the evaluations
  };
  std::vector<double> reference, first, second;
  run(reference);
  std::thread t1([&] { run(first); });
  std::thread t2([&] { run(second); });
  t1.join();
  t2.join();
  EXPECT_EQ(reference.back(), static_cast<double>(kPoints));
  EXPECT_EQ(first, reference);
  EXPECT_EQ(second, reference);
}

} // namespace
} // namespace frep
