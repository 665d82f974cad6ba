// The .vm tape reader: the object it makes, values (sign flipped, every opcode), and errors with
// their line and column.
#include "Compiler/model.h"
#include "Eval/point_evaluator.h"
#include "Language/vm_reader.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frep
{
namespace
{

double value_at(const ParseResult& parsed, std::vector<double> x)
{
  const auto compiled = Model::compile(parsed.program, 0);
  EXPECT_TRUE(compiled.model);
  PointEvaluator point(compiled.model->tape());
  return point.value(x);
}

const char* unit_sphere = "# a sphere of radius 1, negative inside\n"
                          "_0 var-x\n"
                          "_1 square _0\n"
                          "_2 var-y\n"
                          "_3 square _2\n"
                          "_4 var-z\n"
                          "_5 square _4\n"
                          "_6 add _1 _3\n"
                          "_7 add _6 _5\n"
                          "_8 sqrt _7\n"
                          "_9 const 1\n"
                          "_a sub _8 _9\n";

TEST(VmReader, SphereIsOneObjectPositiveInside)
{
  const ParseResult parsed = parse_vm(unit_sphere, "sphere.vm");
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics.at(0).format();
  ASSERT_EQ(parsed.program->objects.size(), 1u);
  const ast::Object& o = parsed.program->objects[0];
  EXPECT_EQ(o.name, "my_model");
  EXPECT_EQ(o.x_dim, 3);
  EXPECT_EQ(o.scalars.size(), 11u);
  // F = -(|x| - 1), computed as the tape writes it.
  const double x = 0.3, y = -0.4, z = 0.5;
  const double expected = -(std::sqrt((x * x + y * y) + z * z) - 1.0);
  EXPECT_EQ(value_at(parsed, { x, y, z }), expected);
  EXPECT_GT(value_at(parsed, { 0, 0, 0 }), 0.0);
  EXPECT_LT(value_at(parsed, { 2, 0, 0 }), 0.0);
}

TEST(VmReader, EveryOpcodeAndTwoDimensions)
{
  const char* text = "a var-x\nb var-y\nc const -2.5\nd mul a b\ne div d c\nf min e a\n"
                     "g max f b\nh neg g\ni abs h\nj sub i c\r\nk add j a\n\n# done\n";
  const ParseResult parsed = parse_vm(text, "ops.vm");
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics.at(0).format();
  EXPECT_EQ(parsed.program->objects[0].x_dim, 2);
  const double a = 1.25, b = -0.75;
  const double e = (a * b) / -2.5;
  const double f = e < a ? e : a;
  const double g = f > b ? f : b;
  const double i = std::fabs(-g);
  const double k = (i - -2.5) + a;
  EXPECT_EQ(value_at(parsed, { a, b }), -k);
}

TEST(VmReader, ConstantsAreCorrectlyRoundedDoubles)
{
  const ParseResult parsed = parse_vm("c const 0.1\n", "c.vm");
  ASSERT_TRUE(parsed.ok());
  EXPECT_EQ(value_at(parsed, { 0.0 }), -0.1);
}

TEST(VmReader, ErrorsNameTheLineAndColumn)
{
  struct Case
  {
    const char* text;
    int line, column;
    const char* says;
  };
  const Case cases[] = {
    { "", 1, 1, "no instruction" },
    { "# only a comment\n", 1, 1, "no instruction" },
    { "_0 var-x\n_1 cube _0\n", 2, 4, "unknown opcode 'cube'" },
    { "_0 var-x\n_1 add _0\n", 2, 4, "takes 2 operands, found 1" },
    { "_0 var-x\n_1 neg _0 _0\n", 2, 11, "takes 1 operand, found 2" },
    { "_0 var-x\n_1 sqrt _9\n", 2, 9, "'_9' is not the name of an earlier instruction" },
    { "_0 var-x\n_0 var-y\n", 2, 1, "defined twice (first on line 1)" },
    { "_0 const 1.5x\n", 1, 10, "not a finite number" },
    { "_0 const inf\n", 1, 10, "not a finite number" },
    { "lonely\n", 1, 1, "expected NAME OPCODE" },
  };
  for (const Case& c : cases)
  {
    const ParseResult parsed = parse_vm(c.text, "bad.vm");
    ASSERT_FALSE(parsed.ok()) << c.text;
    ASSERT_EQ(parsed.diagnostics.size(), 1u);
    const Diagnostic& d = parsed.diagnostics[0];
    EXPECT_EQ(d.location.line, c.line) << c.text;
    EXPECT_EQ(d.location.column, c.column) << c.text;
    EXPECT_NE(d.message.find(c.says), std::string::npos) << d.message;
    EXPECT_EQ(d.file, "bad.vm");
  }
}

TEST(VmReader, RecognisesTheExtension)
{
  EXPECT_TRUE(is_vm_file("models/prospero.vm"));
  EXPECT_TRUE(is_vm_file("A.VM"));
  EXPECT_FALSE(is_vm_file("a.hf"));
  EXPECT_FALSE(is_vm_file("vm"));
  EXPECT_FALSE(is_vm_file("a.vmx"));
}

} // namespace
} // namespace frep
