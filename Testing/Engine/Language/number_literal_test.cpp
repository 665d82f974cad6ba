// Number literal values: the exact doubles the original's scanner computes, checked against
// lexical/number_literal_values of the conformance suite (the model returns the literal).
#include "test_support.h"

#include "Language/detail/number_literal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <regex>
#include <sstream>

namespace frep
{
namespace
{

TEST(NumberLiteral, KnownDeviationsFromCorrectRounding)
{
  EXPECT_EQ(*number_literal_value("1e5"), 1.0 * std::exp(5.0 * std::log(10.0)));
  EXPECT_NE(*number_literal_value("1e5"), 100000.0);
  EXPECT_EQ(*number_literal_value("100000"), 100000.0);
  EXPECT_EQ(*number_literal_value("1.5e-3"), 0.0014999999999999992);
  // The exponent bug: -12 is scanned as -1*10+2 = -8.
  EXPECT_EQ(*number_literal_value("1e-12"), *number_literal_value("1e-8"));
  EXPECT_EQ(*number_literal_value("1e-15"), *number_literal_value("1e-5"));
  EXPECT_FALSE(number_literal_value("05"));
  EXPECT_FALSE(number_literal_value("1e0"));
  EXPECT_FALSE(number_literal_value("1e"));
  EXPECT_FALSE(number_literal_value("."));
  EXPECT_EQ(*number_literal_value("1."), 1.0);
  EXPECT_EQ(*number_literal_value(".5"), 0.5);
}

TEST(NumberLiteral, MatchesTheOriginalOnEveryConformanceLiteral)
{
  const auto dir = test::conformance_dir() / "lexical";
  const std::string program = test::read_file(dir / "number_literal_values.hf");
  const std::string expected = test::read_file(dir / "number_literal_values.expected");
  ASSERT_FALSE(program.empty());

  // "if a[1] = K then v = LITERAL; endif;" -> K -> (sign, literal)
  std::map<int, std::pair<bool, std::string>> literals;
  const std::regex case_line(R"(if a\[1\] = (\d+) then v = (-?)([0-9.eE+\-]+); endif;)");
  std::istringstream program_lines(program);
  std::string line;
  while (std::getline(program_lines, line))
  {
    std::smatch m;
    if (std::regex_search(line, m, case_line))
    {
      literals[std::stoi(m[1])] = { m[2] == "-", m[3] };
    }
  }
  ASSERT_GE(literals.size(), 40u);

  // "eval x 0 0 0 a K => value V s ..."
  const std::regex eval_line(R"(eval x \S+ \S+ \S+ a (\S+) => value (\S+))");
  std::istringstream expected_lines(expected);
  int checked = 0;
  while (std::getline(expected_lines, line))
  {
    std::smatch m;
    if (!std::regex_search(line, m, eval_line))
    {
      continue;
    }
    const int k = static_cast<int>(std::strtod(m[1].str().c_str(), nullptr));
    const auto found = literals.find(k);
    if (found == literals.end())
    {
      continue; // the default value of the model, no literal selected
    }
    const double want = std::strtod(m[2].str().c_str(), nullptr);
    const auto value = number_literal_value(found->second.second);
    ASSERT_TRUE(value.has_value()) << found->second.second;
    const double got = found->second.first ? -*value : *value;
    if (std::isnan(want))
    {
      EXPECT_TRUE(std::isnan(got)) << found->second.second;
    }
    else
    {
      EXPECT_EQ(got, want) << "literal " << found->second.second << " (case " << k << ")";
    }
    ++checked;
  }
  EXPECT_GE(checked, 40);
}

} // namespace
} // namespace frep
