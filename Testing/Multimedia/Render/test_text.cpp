// Text: UTF-8 decoding, font loading errors, ink only inside the reported box, anchors.
#include "Render/text.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace frep::render
{
namespace
{

TEST(Text, DecodeUtf8)
{
  EXPECT_EQ(decode_utf8("a\xC3\xA9\xC3\x97\xE2\x89\xA4\xE2\x80\xA6\xF0\x9F\x99\x82"),
    (std::vector<char32_t>{ U'a', 0xE9, 0xD7, 0x2264, 0x2026, 0x1F642 }));
  // Malformed: stray continuation, truncated sequence, overlong form, surrogate.
  EXPECT_EQ(decode_utf8("\x80z"), (std::vector<char32_t>{ 0xFFFD, U'z' }));
  EXPECT_EQ(decode_utf8("\xE2\x89z"), (std::vector<char32_t>{ 0xFFFD, U'z' }));
  EXPECT_EQ(decode_utf8("\xC0\xAF"), (std::vector<char32_t>{ 0xFFFD }));
  EXPECT_EQ(decode_utf8("\xED\xA0\x80"), (std::vector<char32_t>{ 0xFFFD }));
  EXPECT_EQ(decode_utf8("\xE2"), (std::vector<char32_t>{ 0xFFFD }));
}

TEST(Text, MissingFontIsAnError)
{
  const Font::LoadResult r = Font::load("/nonexistent/NoSuchFont.ttf");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("/nonexistent/NoSuchFont.ttf"), std::string::npos);
  // A file that is not a font.
  const std::string path = ::testing::TempDir() + "frep_render_not_a_font.ttf";
  std::ofstream(path) << "definitely not a font";
  const Font::LoadResult bad = Font::load(path);
  EXPECT_FALSE(bad.ok());
  EXPECT_FALSE(bad.error.empty());
  std::remove(path.c_str());
  // No candidate at all falls through to the defaults, which are on this machine.
  const std::vector<std::string> none = { "/nonexistent/a.ttf" };
  const Font::LoadResult fallback = Font::load_default(none);
  ASSERT_TRUE(fallback.ok()) << fallback.error;
  EXPECT_NE(fallback.font->family().find("DejaVu"), std::string::npos);
}

class TextDrawing : public ::testing::Test
{
protected:
  void SetUp() override
  {
    Font::LoadResult r = Font::load_default();
    ASSERT_TRUE(r.ok()) << r.error;
    font.emplace(std::move(*r.font));
  }
  std::optional<Font> font;
};

TEST_F(TextDrawing, InkStaysInsideTheReportedBox)
{
  const std::string text = "x\xE2\x82\x84 \xC3\x97 0.25 \xE2\x89\xA4 Qjy\xE2\x80\xA6";
  for (const Anchor anchor : { Anchor{ HAlign::Left, VAlign::Baseline },
         Anchor{ HAlign::Centre, VAlign::Middle },
         Anchor{ HAlign::Right, VAlign::Top },
         Anchor{ HAlign::Left, VAlign::Bottom } })
  {
    imaging::Image image(400, 120);
    const TextLayout l = draw_text(image, *font, 200.3, 60.6, text, 28.0, { 0, 0, 0, 1 }, anchor);
    ASSERT_FALSE(l.ink.empty());
    int inside = 0, outside = 0;
    for (int y = 0; y < image.height; ++y)
    {
      for (int x = 0; x < image.width; ++x)
      {
        if (image.at(x, y).a > 0.0F)
        {
          const bool in = x >= l.ink.x0 && x < l.ink.x1 && y >= l.ink.y0 && y < l.ink.y1;
          (in ? inside : outside)++;
        }
      }
    }
    EXPECT_GT(inside, 300);
    EXPECT_EQ(outside, 0);
    // The ink lies within the advance box give or take a pixel of side bearing.
    EXPECT_GE(l.ink.y0, l.box.y0 - 1);
    EXPECT_LE(l.ink.y1, l.box.y1 + 1);
    EXPECT_GE(l.ink.x0, l.box.x0 - 2);
    EXPECT_LE(l.ink.x1, l.box.x1 + 2);
    // Anchors (to the pixel the layout rounds to).
    const double cx = 0.5 * (l.box.x0 + l.box.x1);
    switch (anchor.h)
    {
      case HAlign::Left:
        EXPECT_NEAR(l.box.x0, 200.3, 0.51);
        break;
      case HAlign::Centre:
        EXPECT_NEAR(cx, 200.3, 0.51);
        break;
      case HAlign::Right:
        EXPECT_NEAR(l.box.x1, 200.3, 0.51);
        break;
    }
    switch (anchor.v)
    {
      case VAlign::Baseline:
        EXPECT_NEAR(l.baseline_y, 60.6, 0.51);
        break;
      case VAlign::Top:
        EXPECT_NEAR(l.box.y0, 60.6, 0.51);
        break;
      case VAlign::Middle:
        EXPECT_NEAR(0.5 * (l.box.y0 + l.box.y1), 60.6, 0.51);
        break;
      case VAlign::Bottom:
        EXPECT_NEAR(l.box.y1, 60.6, 0.51);
        break;
    }
  }
}

TEST_F(TextDrawing, ExtentScalesWithSizeAndLength)
{
  const TextExtent a = text_extent(*font, "frame 12", 20.0);
  const TextExtent b = text_extent(*font, "frame 12", 40.0);
  const TextExtent c = text_extent(*font, "frame 12 of 120", 20.0);
  EXPECT_GT(a.width, 40.0);
  EXPECT_NEAR(b.width / a.width, 2.0, 0.05);
  EXPECT_GT(c.width, a.width * 1.5);
  EXPECT_NEAR(a.ascent + a.descent, 20.0 * 1.16, 2.0); // DejaVu's line is about 1.16 em
  EXPECT_EQ(text_extent(*font, "", 20.0).width, 0.0);
  EXPECT_EQ(text_extent(*font, "abc", 0.0).width, 0.0);
  EXPECT_EQ(text_extent(*font, "abc", -3.0).width, 0.0);
  imaging::Image image(10, 10);
  draw_text(image, *font, -500, -500, "off the picture", 30, { 0, 0, 0, 1 });
  for (std::size_t i = 3; i < image.rgba.size(); i += 4)
  {
    EXPECT_EQ(image.rgba[i], 0.0F);
  }
}

} // namespace
} // namespace frep::render
