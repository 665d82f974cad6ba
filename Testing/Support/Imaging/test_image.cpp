// Image: the colour conventions (linear inside, sRGB out), straight-alpha compositing and the
// premultiplied box filter of supersampling.
#include "Imaging/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace frep::imaging
{
namespace
{

TEST(Image, SrgbConversions)
{
  EXPECT_NEAR(linear_to_srgb(0.5F), 0.7354F, 1e-4);
  EXPECT_NEAR(srgb_to_linear(0.7354F), 0.5F, 1e-4);
  for (float v = 0.0F; v <= 1.0F; v += 0.0625F)
  {
    EXPECT_NEAR(srgb_to_linear(linear_to_srgb(v)), v, 1e-5);
  }
  const Rgba c = srgb_hex(0xff8000);
  EXPECT_FLOAT_EQ(c.r, 1.0F);
  EXPECT_NEAR(c.g, srgb_to_linear(128.0F / 255.0F), 1e-6);
  EXPECT_FLOAT_EQ(c.b, 0.0F);
}

TEST(Image, ToRgb8EncodesAndComposites)
{
  Image image(2, 1, { 0.5F, 0.0F, 1.0F, 1.0F });
  image.pixel(1, 0)[3] = 0.0F; // transparent: the background shows
  const std::vector<std::uint8_t> rgb = to_rgb8(image, { 1.0F, 1.0F, 1.0F, 1.0F });
  ASSERT_EQ(rgb.size(), 6U);
  EXPECT_EQ(rgb[0], 188); // linear 0.5 is sRGB 188
  EXPECT_EQ(rgb[1], 0);
  EXPECT_EQ(rgb[2], 255);
  EXPECT_EQ(rgb[3], 255);
  EXPECT_EQ(rgb[4], 255);
  EXPECT_EQ(rgb[5], 255);
  // Out-of-range and NaN values are clamped, not wrapped.
  Image odd(1, 1, { 2.0F, -1.0F, std::nanf(""), 1.0F });
  const std::vector<std::uint8_t> o = to_rgb8(odd);
  EXPECT_EQ(o[0], 255);
  EXPECT_EQ(o[1], 0);
  EXPECT_EQ(o[2], 0);
}

TEST(Image, CompositeOverWithOffsetAndClipping)
{
  Image target(4, 4, { 0, 0, 1, 1 });
  Image source(3, 3, { 1, 0, 0, 0.5F });
  composite_over(target, source, 2, -1); // only its lower-left 2 x 2 lands
  EXPECT_FLOAT_EQ(target.at(2, 0).r, 0.5F);
  EXPECT_FLOAT_EQ(target.at(2, 0).b, 0.5F);
  EXPECT_FLOAT_EQ(target.at(3, 1).r, 0.5F);
  EXPECT_FLOAT_EQ(target.at(1, 0).r, 0.0F); // left of it: untouched
  EXPECT_FLOAT_EQ(target.at(2, 2).r, 0.0F); // below it
  EXPECT_FLOAT_EQ(target.at(2, 0).a, 1.0F);
  // Over a transparent target the colour stays, alpha adds up.
  Image clear(1, 1);
  composite_over(clear, Image(1, 1, { 0.2F, 0.4F, 0.6F, 0.5F }), 0, 0, 0.5F);
  EXPECT_FLOAT_EQ(clear.at(0, 0).g, 0.4F);
  EXPECT_FLOAT_EQ(clear.at(0, 0).a, 0.25F);
}

TEST(Image, DownsampleAveragesPremultiplied)
{
  Image image(4, 2, { 1, 1, 1, 1 });
  image.pixel(1, 1)[3] = 0.0F;
  image.pixel(1, 1)[0] = 0.0F; // a transparent black sample must not darken the edge
  image.pixel(2, 0)[0] = 0.0F; // an opaque black one does
  const Image small = downsample(image, 2);
  ASSERT_EQ(small.width, 2);
  ASSERT_EQ(small.height, 1);
  EXPECT_FLOAT_EQ(small.at(0, 0).a, 0.75F);
  EXPECT_FLOAT_EQ(small.at(0, 0).r, 1.0F);
  EXPECT_FLOAT_EQ(small.at(1, 0).a, 1.0F);
  EXPECT_FLOAT_EQ(small.at(1, 0).r, 0.75F);
  EXPECT_EQ(downsample(Image(5, 5), 2).width, 2);
}

TEST(Image, WritePpm)
{
  const std::string path = ::testing::TempDir() + "frep_render_image.ppm";
  ASSERT_EQ(write_ppm(Image(3, 2, { 1, 0, 0, 1 }), path), "");
  std::ifstream in(path, std::ios::binary);
  std::string header((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(header.substr(0, 11), "P6\n3 2\n255\n");
  EXPECT_EQ(header.size(), 11U + 18U);
  std::remove(path.c_str());
  EXPECT_NE(write_ppm(Image(3, 2), "/nonexistent-dir/x.ppm"), "");
  EXPECT_NE(write_ppm(Image(), path), "");
}

} // namespace
} // namespace frep::imaging
