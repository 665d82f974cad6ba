// The default object (Language/ast.h): my_model in any case, else the first object.
#include "Language/ast.h"
#include "Language/parser.h"

#include <gtest/gtest.h>

namespace frep
{
namespace
{

int default_of(const std::string& text)
{
  const ParseResult parsed = parse_program(text, "<test>");
  EXPECT_TRUE(parsed.ok()) << format_diagnostics(parsed.diagnostics);
  return parsed.program ? ast::select_default_object(*parsed.program) : -2;
}

TEST(DefaultObject, NameIsMyModel)
{
  EXPECT_EQ(ast::default_object_name, "my_model");
}

TEST(DefaultObject, MyModelElseTheFirst)
{
  EXPECT_EQ(default_of("first(x[3], a[1]) { first = 1; }\n"
                       "my_model(x[3], a[1]) { my_model = 2; }\n"),
    1);
  EXPECT_EQ(default_of("first(x[3], a[1]) { first = 1; }\n"
                       "My_Model(x[3], a[1]) { My_Model = 2; }\n"),
    1)
    << "any case";
  EXPECT_EQ(default_of("first(x[3], a[1]) { first = 1; }\n"
                       "second(x[3], a[1]) { second = 2; }\n"),
    0)
    << "no my_model: the first object";
  ast::Program empty;
  EXPECT_EQ(ast::select_default_object(empty), -1);
}

} // namespace
} // namespace frep
