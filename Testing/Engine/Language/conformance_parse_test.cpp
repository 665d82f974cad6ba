// Data-driven check of the parser against every case of the conformance suite: acceptance,
// selected object and sizes, and for rejected files the first diagnostic's line, column and
// message (which must start with the original's text).
#include "test_support.h"

#include "Language/ast.h"
#include "Language/parser.h"

#include <gtest/gtest.h>

#include <iostream>
#include <sstream>

namespace frep
{
namespace
{

struct Expectation
{
  std::string object = "my_model";
  std::string parse; ///< the `parse ...` line without the word "parse "
};

Expectation read_expectation(const std::string& text)
{
  Expectation e;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.rfind("object ", 0) == 0)
    {
      e.object = line.substr(7);
    }
    else if (line.rfind("parse ", 0) == 0)
    {
      e.parse = line.substr(6);
    }
  }
  return e;
}

/// Empty when the parse result agrees with the expectation, else what differs.
std::string compare(const Expectation& e, const ParseResult& result, bool& line_mismatch)
{
  std::istringstream in(e.parse);
  std::string kind;
  in >> kind;
  std::ostringstream problem;
  if (kind == "ok" || kind == "none")
  {
    if (!result.ok())
    {
      line_mismatch = true;
      problem << "expected parse " << e.parse << ", got error "
              << result.diagnostics.front().format();
      return problem.str();
    }
    if (kind == "none")
    {
      if (!result.program->objects.empty())
      {
        problem << "expected no object, got " << result.program->objects.size();
      }
      return problem.str();
    }
    std::string name;
    int x = 0, a = 0, s = 0;
    in >> name >> x >> a >> s;
    const int selected = ast::select_object(*result.program, e.object, ast::NameMatch::Exact);
    if (selected < 0)
    {
      return "no object selected";
    }
    const ast::Object& object = result.program->objects[static_cast<std::size_t>(selected)];
    if (object.name != name || object.x_dim != x || object.a_dim != a || object.s_dim != s)
    {
      problem << "expected " << name << ' ' << x << ' ' << a << ' ' << s << ", got " << object.name
              << ' ' << object.x_dim << ' ' << object.a_dim << ' ' << object.s_dim;
    }
    return problem.str();
  }
  if (kind != "error")
  {
    return "unreadable expectation: " + e.parse;
  }
  int line = 0, column = 0;
  in >> line >> column;
  std::string message;
  std::getline(in, message);
  if (!message.empty() && message.front() == ' ')
  {
    message.erase(0, 1);
  }
  if (result.ok())
  {
    line_mismatch = true;
    problem << "expected error " << line << ':' << column << ' ' << message
            << ", but the file parsed";
    return problem.str();
  }
  const Diagnostic& first = result.diagnostics.front();
  if (first.location.line != line)
  {
    line_mismatch = true;
  }
  if (first.location.line != line || first.location.column != column ||
      first.message.rfind(message, 0) != 0)
  {
    problem << "expected " << line << ':' << column << ' ' << message << ", got "
            << first.location.line << ':' << first.location.column << ' ' << first.message;
  }
  return problem.str();
}

TEST(ConformanceParse, EveryCaseMatchesTheOriginal)
{
  const auto cases = test::conformance_cases();
  ASSERT_EQ(cases.size(), 291u) << "conformance suite not found under " << test::conformance_dir();
  ParseOptions options;
  options.accept_carriage_return = false; // the original's behaviour
  int matched = 0;
  int line_or_acceptance_mismatches = 0;
  std::ostringstream report;
  for (const auto& c : cases)
  {
    const Expectation e = read_expectation(test::read_file(c.expected));
    const ParseResult result =
      parse_program(test::read_file(c.hf), c.category + "/" + c.name + ".hf", options);
    bool line_mismatch = false;
    const std::string problem = compare(e, result, line_mismatch);
    if (problem.empty())
    {
      ++matched;
    }
    else
    {
      report << "  " << c.category << '/' << c.name << ": " << problem << '\n';
      if (line_mismatch)
      {
        ++line_or_acceptance_mismatches;
      }
    }
  }
  std::cout << "[conformance parse] " << matched << " / " << cases.size()
            << " cases match (acceptance, line, column, message); " << line_or_acceptance_mismatches
            << " differ in acceptance or line\n"
            << report.str();
  EXPECT_EQ(line_or_acceptance_mismatches, 0) << report.str();
  EXPECT_EQ(matched, static_cast<int>(cases.size())) << report.str();
}

} // namespace
} // namespace frep
