// Bad input never crashes: deep nesting, random bytes, truncated and mutated conformance files.
#include "test_support.h"

#include "Language/parser.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace frep
{
namespace
{

bool mentions(const ParseResult& r, const std::string& what)
{
  for (const Diagnostic& d : r.diagnostics)
  {
    if (d.message.find(what) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

TEST(ParserRobustness, HundredThousandNestedParentheses)
{
  const int n = 100000;
  const std::string expr = std::string(n, '(') + "1" + std::string(n, ')');
  const ParseResult r = parse_program("m(x[3], a[1]) { m = " + expr + "; }", "<deep>");
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(mentions(r, "Nesting too deep"));
  EXPECT_LE(r.diagnostics.size(), 3u);
}

TEST(ParserRobustness, DeepConditionsUnaryAndStatements)
{
  const int n = 100000;
  const std::string body_cond =
    "if " + std::string(n, '(') + "1 > 0" + std::string(n, ')') + " then endif;";
  EXPECT_TRUE(
    mentions(parse_program("m(x[3],a[1]){" + body_cond + " m = 1; }", "<c>"), "Nesting too deep"));
  std::string minuses; // "- - - ..." ("--" would start a comment)
  for (int i = 0; i < n; ++i)
  {
    minuses += "- ";
  }
  EXPECT_TRUE(
    mentions(parse_program("m(x[3],a[1]){ m = " + minuses + "1; }", "<u>"), "Nesting too deep"));
  std::string nots;
  for (int i = 0; i < n; ++i)
  {
    nots += "not ";
  }
  EXPECT_TRUE(mentions(parse_program("m(x[3],a[1]){ if " + nots + "1 then endif; m = 1; }", "<n>"),
    "Nesting too deep"));
  std::string ifs;
  for (int i = 0; i < 5000; ++i)
  {
    ifs += "if 1 then ";
  }
  EXPECT_TRUE(
    mentions(parse_program("m(x[3],a[1]){" + ifs + " m = 1; }", "<i>"), "Nesting too deep"));
}

TEST(ParserRobustness, LongFlatChainsAreBoundedToo)
{
  // A left-deep tree is as deep as a nested one for every later recursive pass.
  std::string sum = "1";
  for (int i = 0; i < 100000; ++i)
  {
    sum += "+1";
  }
  const ParseResult r = parse_program("m(x[3],a[1]){ m = " + sum + "; }", "<flat>");
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(mentions(r, "Nesting too deep"));
  ParseOptions generous;
  generous.max_nesting_depth = 300;
  std::string short_sum = "1";
  for (int i = 0; i < 250; ++i)
  {
    short_sum += "+1";
  }
  EXPECT_TRUE(parse_program("m(x[3],a[1]){ m = " + short_sum + "; }", "<f>", generous).ok());
}

TEST(ParserRobustness, RandomBytes)
{
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<int> length(0, 400);
  for (int i = 0; i < 2000; ++i)
  {
    std::string text(static_cast<std::size_t>(length(rng)), '\0');
    for (char& c : text)
    {
      c = static_cast<char>(byte(rng));
    }
    const ParseResult r = parse_program(text, "<random>");
    EXPECT_TRUE(r.ok() || !r.diagnostics.empty());
  }
}

TEST(ParserRobustness, RandomTokenSoup)
{
  const char* pieces[] = { "m",
    "(",
    ")",
    "x",
    "a",
    "s",
    "[",
    "]",
    "3",
    "1",
    "{",
    "}",
    ";",
    ",",
    "=",
    "+",
    "-",
    "*",
    "^",
    "if",
    "then",
    "else",
    "endif",
    "while",
    "loop",
    "endloop",
    "array",
    "not",
    "and",
    "or",
    "<",
    "q",
    "v",
    "hfSphere",
    "sqrt",
    "\"s\"",
    "0",
    "1e5",
    "\n",
    "-- c\n" };
  std::mt19937 rng(777);
  std::uniform_int_distribution<std::size_t> pick(0, std::size(pieces) - 1);
  for (int i = 0; i < 3000; ++i)
  {
    std::string text = "m(x[3], a[1]) {";
    const int n = static_cast<int>(rng() % 60);
    for (int k = 0; k < n; ++k)
    {
      text += pieces[pick(rng)];
      text += ' ';
    }
    const ParseResult r = parse_program(text, "<soup>");
    EXPECT_TRUE(r.ok() || !r.diagnostics.empty());
  }
}

TEST(ParserRobustness, TruncationsAndMutationsOfEveryConformanceFile)
{
  const auto cases = test::conformance_cases();
  ASSERT_FALSE(cases.empty());
  std::mt19937 rng(99);
  std::size_t parsed = 0;
  for (const auto& c : cases)
  {
    const std::string text = test::read_file(c.hf);
    const std::size_t step = std::max<std::size_t>(1, text.size() / 64);
    for (std::size_t cut = 0; cut <= text.size(); cut += step)
    {
      const ParseResult r = parse_program(std::string_view(text).substr(0, cut), "<cut>");
      EXPECT_TRUE(r.ok() || !r.diagnostics.empty());
      ++parsed;
    }
    for (int k = 0; k < 8 && !text.empty(); ++k)
    {
      std::string mutated = text;
      mutated[rng() % mutated.size()] = static_cast<char>(rng() % 256);
      const ParseResult r = parse_program(mutated, "<mutated>");
      EXPECT_TRUE(r.ok() || !r.diagnostics.empty());
      ++parsed;
    }
  }
  EXPECT_GT(parsed, cases.size() * 10);
}

TEST(ParserRobustness, NulBytesAndHugeNumbers)
{
  const std::string with_nul("m(x[3], a[1]) { m = 1; }\0garbage{{{", 35);
  EXPECT_TRUE(parse_program(with_nul, "<nul>").ok()); // the text ends at NUL, as in the original
  EXPECT_FALSE(parse_program(std::string("m(x[3]\0, a[1]) { m = 1; }", 25), "<nul>").ok());
  EXPECT_FALSE(parse_program("m(x[0e99999], a[1]) { m = 1; }", "<nan>").ok());
  EXPECT_TRUE(parse_program("m(x[3], a[1]) { m = 1e999999999999 - 0e99999; }", "<inf>").ok());
}

} // namespace
} // namespace frep
