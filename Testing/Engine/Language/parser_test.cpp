// Parser: AST shapes (precedence, associativity, conditions), name resolution, locations,
// diagnostics and recovery.
#include "Language/parser.h"

#include <gtest/gtest.h>

#include <string>

namespace frep
{
namespace
{

using namespace frep::ast;

/// Renders an expression as a fully parenthesized string to check the tree's shape.
std::string show(const Expr& e)
{
  struct Visitor
  {
    std::string operator()(const NumberExpr& n) const
    {
      std::string s = std::to_string(n.value);
      s.erase(s.find_last_not_of('0') + 1);
      if (!s.empty() && s.back() == '.')
      {
        s.pop_back();
      }
      return s;
    }
    std::string operator()(const ScalarExpr& s) const { return "$" + std::to_string(s.scalar); }
    std::string operator()(const ElementExpr& el) const
    {
      const char* names[] = { "x", "a", "s", "L" };
      return std::string(names[static_cast<int>(el.array.kind)]) + "[" + show(*el.index) + "]";
    }
    std::string operator()(const UnaryExpr& u) const
    {
      const char* ops[] = { "+", "-", "~" };
      return std::string("(") + ops[static_cast<int>(u.op)] + show(*u.operand) + ")";
    }
    std::string operator()(const BinaryExpr& b) const
    {
      const char* ops[] = { "+", "-", "*", "/", "^", "|", "&", "\\", "@" };
      return "(" + show(*b.lhs) + ops[static_cast<int>(b.op)] + show(*b.rhs) + ")";
    }
    std::string operator()(const CompareExpr& c) const
    {
      const char* ops[] = { "=", "/=", "<", "<=", ">", ">=" };
      return "(" + show(*c.lhs) + ops[static_cast<int>(c.op)] + show(*c.rhs) + ")";
    }
    std::string operator()(const LogicExpr& l) const
    {
      return "(" + show(*l.lhs) + (l.op == LogicOp::And ? " and " : " or ") + show(*l.rhs) + ")";
    }
    std::string operator()(const NotExpr& n) const { return "(not " + show(*n.operand) + ")"; }
    std::string operator()(const CallExpr& c) const
    {
      std::string s = std::string(function_info(c.function).name) + "(";
      for (std::size_t i = 0; i < c.args.size(); ++i)
      {
        if (i)
        {
          s += ",";
        }
        if (const auto* e = std::get_if<ExprPtr>(&c.args[i]))
        {
          s += show(**e);
        }
        else if (std::holds_alternative<ArrayName>(c.args[i]))
        {
          s += "<array>";
        }
      }
      return s + ")";
    }
    std::string operator()(const ObjectCallExpr& o) const
    {
      return "obj" + std::to_string(o.object) + (o.s ? "(x,a,s)" : "(x,a)");
    }
    std::string operator()(const UserCallExpr& u) const
    {
      return "user" + std::to_string(u.function) + "/" + std::to_string(u.args.size());
    }
  };
  return std::visit(Visitor{}, e.node);
}

ParseResult parse(const std::string& text)
{
  return parse_program(text, "<test>");
}

/// The final expression of a one-object program `m(x[3],a[1]){ BODY m = EXPR; }`.
std::string result_of(const std::string& expr, const std::string& body = "")
{
  const ParseResult r = parse("m(x[3], a[1]) { " + body + " m = " + expr + "; }");
  if (!r.ok())
  {
    return "ERROR " + r.diagnostics.front().format();
  }
  return show(*r.program->objects.at(0).result);
}

/// The condition of `if COND then endif;`.
std::string condition_of(const std::string& cond)
{
  const ParseResult r = parse("m(x[3], a[1]) { if " + cond + " then endif; m = 0; }");
  if (!r.ok())
  {
    return "ERROR " + r.diagnostics.front().format();
  }
  const auto& stmt = r.program->objects.at(0).body.at(0);
  return show(*std::get<IfStmt>(stmt.node).condition);
}

TEST(ParserPrecedence, UnaryBindsTighterThanPower)
{
  EXPECT_EQ(result_of("-2^2"), "((-2)^2)");
  EXPECT_EQ(result_of("-x[1]^2"), "((-x[1])^2)");
  EXPECT_EQ(result_of("~-+1"), "(~(-(+1)))");
}

TEST(ParserPrecedence, PowerIsLeftAssociative)
{
  EXPECT_EQ(result_of("2^3^2"), "((2^3)^2)");
}

TEST(ParserPrecedence, MultiplicativeOverAdditive)
{
  EXPECT_EQ(result_of("1+2*3"), "(1+(2*3))");
  EXPECT_EQ(result_of("8/2/2"), "((8/2)/2)");
  EXPECT_EQ(result_of("2*3^2"), "(2*(3^2))");
}

TEST(ParserPrecedence, AllAdditiveOperatorsShareOneLevel)
{
  EXPECT_EQ(result_of("1 + 2 | 3"), "((1+2)|3)");
  EXPECT_EQ(result_of("1 | 2 & 3"), "((1|2)&3)");
  EXPECT_EQ(result_of("1 & 2 \\ 3 @ 4 - 5"), "((((1&2)\\3)@4)-5)");
  EXPECT_EQ(result_of("1 - 2 * 3 | 4"), "((1-(2*3))|4)");
}

TEST(ParserPrecedence, Parentheses)
{
  EXPECT_EQ(result_of("(1+2)*3"), "((1+2)*3)");
  EXPECT_EQ(result_of("2^(3^2)"), "(2^(3^2))");
}

TEST(ParserConditions, AndOrSameLevelLeftAssociative)
{
  EXPECT_EQ(condition_of("1 or 2 and 3"), "((1 or 2) and 3)");
  EXPECT_EQ(condition_of("1 and 2 or 3"), "((1 and 2) or 3)");
}

TEST(ParserConditions, NotBindsToNextOperand)
{
  EXPECT_EQ(condition_of("not x[1] > 5"), "((not x[1])>5)");
  EXPECT_EQ(condition_of("not not 1"), "(not (not 1))");
}

TEST(ParserConditions, ComparisonsChainLeft)
{
  EXPECT_EQ(condition_of("1 < 2 = 1"), "((1<2)=1)");
  EXPECT_EQ(condition_of("x[1] + 1 >= 2 * 3"), "((x[1]+1)>=(2*3))");
}

TEST(ParserConditions, LeadingParenOpensABooleanGroup)
{
  EXPECT_EQ(condition_of("(x[1] <= 1) and (x[2] /= 2)"), "((x[1]<=1) and (x[2]/=2))");
  EXPECT_EQ(condition_of("2*(x[1]+1) > 0"), "((2*(x[1]+1))>0)");
  const std::string bad = condition_of("(x[1]+1)*2 > 0");
  EXPECT_NE(bad.find("Reserved word \"then\" expected"), std::string::npos) << bad;
}

TEST(ParserConditions, ComparisonIsNotAValue)
{
  const ParseResult r = parse("m(x[3], a[1]) { q = (x[1] > 0); m = q; }");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics.front().message.rfind("Right parenthes expected", 0), 0u);
}

TEST(ParserNames, ScalarsArraysAndCalls)
{
  const ParseResult r = parse(R"(
    Sph(x[3], a[1]) { Sph = a[1]^2 - x[1]^2 - x[2]^2 - x[3]^2; }
    Main(x[3], a[1], s[2])
    {
      array rad[1], v[3];
      rad[1] = 10.; v = [-9, +8, -9];
      q = 1;
      while q < 3 loop q = q + 1; endloop;
      if q = 3 then s[1] = 1; else s = [1, 2]; endif;
      Main = hfBlock(x, v, 18, 16, 18) \ Sph(x, rad) + q;
    })");
  ASSERT_TRUE(r.ok()) << format_diagnostics(r.diagnostics);
  ASSERT_EQ(r.program->objects.size(), 2u);
  const Object& main = r.program->objects[1];
  EXPECT_EQ(main.name, "main");
  EXPECT_EQ(main.s_dim, 2);
  ASSERT_EQ(main.arrays.size(), 2u);
  EXPECT_EQ(main.arrays[1].name, "v");
  EXPECT_EQ(main.arrays[1].size, 3);
  EXPECT_EQ(main.scalars, std::vector<std::string>{ "q" });
  ASSERT_EQ(main.body.size(), 5u);
  const auto& literal = std::get<AssignArray>(main.body[1].node);
  EXPECT_EQ(literal.values, (std::vector<double>{ -9, 8, -9 }));
  EXPECT_EQ(show(*main.result), "((hfblock(<array>,<array>,18,16,18)\\obj0(x,a))+$0)");
  EXPECT_EQ(main.result_location, (SourceLocation{ 10, 7 }));
}

TEST(ParserNames, ScalarDeclaredByFirstAssignmentInText)
{
  // Declared when its assignment starts: the right side may read it (a run-time error).
  EXPECT_TRUE(parse("m(x[3], a[1]) { q = q + 1; m = q; }").ok());
  const ParseResult r = parse("m(x[3], a[1]) { if x[1] > 0 then w = p; endif; p = 1; m = p; }");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics.front().location, (SourceLocation{ 1, 38 }));
  EXPECT_EQ(r.diagnostics.front().message.rfind(
              "Unassigned identificator used in expression (found \"p\")", 0),
    0u);
}

TEST(ParserNames, ObjectCallSizesAreChecked)
{
  const std::string callee = "c(x[3], a[2]) { c = 1; }\n";
  EXPECT_TRUE(parse(callee + "m(x[3], a[2]) { m = c(x, a); }").ok());
  const ParseResult r = parse(callee + "m(x[3], a[1]) { m = c(x, a); }");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics.front().location, (SourceLocation{ 2, 26 }));
  EXPECT_EQ(r.diagnostics.front().message.rfind("Wrong number of items in array", 0), 0u);
  // Forward references and recursion are not calls.
  EXPECT_FALSE(parse("m(x[3], a[1]) { m = m(x, a); }").ok());
}

TEST(ParserLocations, OperatorsNamesAndIndexPositions)
{
  const ParseResult r = parse("m(x[3], a[1])\n{\n  array v[3];\n  v[x[1]] = 2;\n"
                              "  m = v[k1(x)] + -sqrt(v[x[2]+1]);\n}");
  // k1 is unknown: an error at its position.
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics.front().location, (SourceLocation{ 5, 9 }));

  const ParseResult ok = parse("m(x[3], a[1])\n{\n  array v[3];\n  v[(x[1])] = 2;\n"
                               "  m = v[x[1]] + -sqrt(v[x[2]+1]);\n}");
  ASSERT_TRUE(ok.ok()) << format_diagnostics(ok.diagnostics);
  const Object& m = ok.program->objects[0];
  const auto& write = std::get<AssignElement>(m.body[0].node);
  EXPECT_EQ(write.index_end, (SourceLocation{ 4, 5 })); // the '(' opening the index
  const Expr& sum = *m.result;
  EXPECT_EQ(sum.location, (SourceLocation{ 5, 15 })); // '+'
  const auto& plus = std::get<BinaryExpr>(sum.node);
  const auto& read = std::get<ElementExpr>(plus.lhs->node);
  EXPECT_EQ(plus.lhs->location, (SourceLocation{ 5, 7 }));
  EXPECT_EQ(read.index_end, (SourceLocation{ 5, 11 }));     // the `1` of x[1]
  EXPECT_EQ(plus.rhs->location, (SourceLocation{ 5, 17 })); // unary '-'
  const auto& minus = std::get<UnaryExpr>(plus.rhs->node);
  EXPECT_EQ(minus.operand->location, (SourceLocation{ 5, 18 })); // sqrt
  const auto& call = std::get<CallExpr>(minus.operand->node);
  const auto& inner = std::get<ElementExpr>(std::get<ExprPtr>(call.args[0])->node);
  EXPECT_EQ(inner.index_end, (SourceLocation{ 5, 27 })); // the `2` of x[2], first of x[2]+1
}

TEST(ParserStructure, EmptyAndCommentOnlyFiles)
{
  for (const char* text : { "", "  \n\t", "-- nothing here\n-- at all" })
  {
    const ParseResult r = parse(text);
    ASSERT_TRUE(r.ok()) << text;
    EXPECT_TRUE(r.program->objects.empty());
  }
}

TEST(ParserStructure, HeaderSizesAndOptionalS)
{
  const ParseResult r = parse("m(x[2.5], a[0]) { m = 1; } n(x[1], a[1.4], s[3]) { n = 1; }");
  ASSERT_TRUE(r.ok()) << format_diagnostics(r.diagnostics);
  EXPECT_EQ(r.program->objects[0].x_dim, 3); // HF_round: half up
  EXPECT_EQ(r.program->objects[0].a_dim, 0);
  EXPECT_EQ(r.program->objects[0].s_dim, 1);
  EXPECT_EQ(r.program->objects[1].a_dim, 1);
  EXPECT_EQ(r.program->objects[1].s_dim, 3);
}

TEST(ParserStructure, HugeArraySizesAreRefused)
{
  for (const char* size : { "1e7", "1000001", "1e300", "123456789012345678901234567890" })
  {
    const ParseResult decl = parse(std::string("m(x[3], a[1]) { array v[") + size + "]; m = 1; }");
    ASSERT_FALSE(decl.ok()) << size;
    EXPECT_NE(decl.diagnostics.front().message.find("too large"), std::string::npos);
    const ParseResult header = parse(std::string("m(x[") + size + "], a[1]) { m = 1; }");
    ASSERT_FALSE(header.ok()) << size;
  }
  EXPECT_TRUE(parse("m(x[3], a[1]) { array v[1000000]; m = 1; }").ok());
  for (const char* size : { "0", "0.4", "-3" })
  {
    EXPECT_FALSE(parse(std::string("m(x[3], a[1]) { array v[") + size + "]; m = 1; }").ok());
  }
}

TEST(ParserDiagnostics, MessageStartsWithTheOriginalTextAndSaysWhatWasFound)
{
  const ParseResult r = parse("m(x[3], a[1]) { if x[1] > 0 q = 1; endif; m = 1; }");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics.front().message, "Reserved word \"then\" expected (found \"q\")");
  EXPECT_EQ(r.diagnostics.front().location, (SourceLocation{ 1, 29 }));
}

TEST(ParserDiagnostics, RecoversAndReportsLaterErrors)
{
  const ParseResult r = parse("m(x[3], a[1])\n{\n  q = 1 +;\n  w = );\n  m = q;\n}\n"
                              "n(x[3], a[1])\n{\n  n = zz;\n}\n");
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 3u) << format_diagnostics(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].location, (SourceLocation{ 3, 10 }));
  EXPECT_EQ(r.diagnostics[1].location, (SourceLocation{ 4, 7 }));
  EXPECT_EQ(r.diagnostics[2].location, (SourceLocation{ 9, 7 }));
  EXPECT_EQ(r.diagnostics[2].file, "<test>");
}

TEST(ParserDiagnostics, NoCascadeAfterABadIfCondition)
{
  const ParseResult r =
    parse("m(x[3], a[1])\n{\n  if x[1] > then\n    q = 1;\n  endif;\n  m = 1;\n}\n");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics.size(), 1u) << format_diagnostics(r.diagnostics);
}

TEST(ParserDiagnostics, CrLfFilesParseByDefault)
{
  const std::string text = "my_model(x[3], a[1])\r\n{\r\n  -- comment\r\n  my_model = 1;\r\n}\r\n";
  EXPECT_TRUE(parse(text).ok());
  ParseOptions strict;
  strict.accept_carriage_return = false;
  const ParseResult r = parse_program(text, "<crlf>", strict);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics.front().location, (SourceLocation{ 1, 21 }));
  EXPECT_EQ(r.diagnostics.front().message.rfind("Left brace expected", 0), 0u);
}

} // namespace
} // namespace frep
