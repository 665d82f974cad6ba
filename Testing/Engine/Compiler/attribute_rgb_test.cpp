// The s[] -> RGB rule (Compiler/attribute_rgb.h): the colour of known attribute values, the
// per-point layout, and which tapes count as setting colours.
#include "Compiler/attribute_rgb.h"
#include "Compiler/model.h"
#include "Language/parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace frep
{
namespace
{

std::shared_ptr<const Tape> tape_of(const std::string& text)
{
  ParseResult parsed = parse_program(text, "<test>");
  EXPECT_TRUE(parsed.ok()) << format_diagnostics(parsed.diagnostics);
  const int index = ast::select_default_object(*parsed.program);
  Model::CompileResult r = Model::compile(parsed.program, index);
  EXPECT_TRUE(r.model) << format_diagnostics(r.diagnostics);
  return r.model->tape();
}

TEST(AttributeRgb, KnownValues)
{
  const float in_range[] = { 0.25f, 0.5f, 1.0f };
  EXPECT_EQ(attribute_rgb(in_range, 3), (AttributeRgb{ 0.25f, 0.5f, 1.0f }));
  const float outside[] = { -2.0f, 7.5f, 0.75f };
  EXPECT_EQ(attribute_rgb(outside, 3), (AttributeRgb{ 0.0f, 1.0f, 0.75f })) << "clamped to [0, 1]";
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float failed[] = { nan, 0.5f, nan };
  EXPECT_EQ(attribute_rgb(failed, 3), (AttributeRgb{ 0.0f, 0.5f, 0.0f })) << "NaN is 0";
  const float inf = std::numeric_limits<float>::infinity();
  const float infinite[] = { inf, -inf, 0.0f };
  EXPECT_EQ(attribute_rgb(infinite, 3), (AttributeRgb{ 1.0f, 0.0f, 0.0f })) << "+-inf clamped";
  const float two[] = { 0.5f, 0.25f };
  EXPECT_EQ(attribute_rgb(two, 2), (AttributeRgb{ 0.5f, 0.25f, 0.0f })) << "missing blue is 0";
  const float five[] = { 0.1f, 0.2f, 0.3f, 0.9f, 0.9f };
  EXPECT_EQ(attribute_rgb(five, 5), (AttributeRgb{ 0.1f, 0.2f, 0.3f })) << "s[4..] ignored";
}

TEST(AttributeRgb, ColoursPerPoint)
{
  // Two points of four attributes each.
  const std::vector<float> attributes{ 1, 0, 0, 9, 0.5f, 2, -1, 9 };
  const std::vector<AttributeRgb> colours = attribute_colours(attributes, 4, 2);
  ASSERT_EQ(colours.size(), 2u);
  EXPECT_EQ(colours[0], (AttributeRgb{ 1, 0, 0 }));
  EXPECT_EQ(colours[1], (AttributeRgb{ 0.5f, 1, 0 }));
  EXPECT_TRUE(attribute_colours(attributes, 0, 2).empty()) << "no attributes";
  EXPECT_TRUE(attribute_colours(attributes, 4, 3).empty()) << "fewer values than points";
}

TEST(AttributeRgb, ColourBytes)
{
  EXPECT_EQ(colour_byte(0.0f), 0);
  EXPECT_EQ(colour_byte(0.5f), 128);
  EXPECT_EQ(colour_byte(1.0f), 255);
  EXPECT_EQ(colour_byte(-1.0f), 0);
  EXPECT_EQ(colour_byte(3.0f), 255);
  EXPECT_EQ(colour_byte(50.0f / 255.0f), 50);
}

TEST(AttributeRgb, WhichTapesSetColours)
{
  const auto coloured = tape_of("my_model(x[3], a[1], s[3]) { s[1] = 1; s[2] = x[1]; s[3] = 0; "
                                "my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }");
  EXPECT_TRUE(tape_sets_colours(*coloured, 3));
  EXPECT_TRUE(tape_sets_attributes(*coloured, 1));
  EXPECT_FALSE(tape_sets_colours(*coloured, 2)) << "colours need s[3]";

  const auto zeros = tape_of("my_model(x[3], a[1], s[3]) { s[1] = 0; s[2] = 0; s[3] = 0; "
                             "my_model = 1 - x[1]^2; }");
  EXPECT_FALSE(tape_sets_colours(*zeros, 3)) << "s[] set to the constant 0 only";

  const auto plain = tape_of("my_model(x[3], a[1]) { my_model = 1 - x[1]^2; }");
  EXPECT_FALSE(tape_sets_attributes(*plain, 1)) << "no s[] in the header: s[1] is 0";

  const auto blue = tape_of("my_model(x[3], a[1], s[3]) { s[3] = x[3]; my_model = 1 - x[1]^2; }");
  EXPECT_TRUE(tape_sets_colours(*blue, 3));
  EXPECT_FALSE(tape_sets_attributes(*blue, 2)) << "s[1] and s[2] are 0";
}

} // namespace
} // namespace frep
