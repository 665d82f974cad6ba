#include "Mapping/colour_maps.h"

#include <gtest/gtest.h>

namespace frep::mapping
{
namespace
{

TEST(ColourMaps, NamesAndEnds)
{
  for (const char* name : { "viridis", "plasma", "coolwarm", "grey", "rainbow" })
  {
    EXPECT_TRUE(is_colour_map(name));
    EXPECT_TRUE(colour_map(name, 0.5).has_value());
    for (double v : { 0.0, 0.3, 1.0 })
    {
      const Rgb rgb = *colour_map(name, v);
      for (double c : rgb)
      {
        EXPECT_GE(c, 0.0);
        EXPECT_LE(c, 1.0);
      }
    }
  }
  EXPECT_FALSE(is_colour_map("red"));
  EXPECT_FALSE(colour_map("virdis", 0.5).has_value());
  EXPECT_EQ(colour_component("green"), 1);
  EXPECT_FALSE(colour_component("viridis").has_value());
  EXPECT_TRUE(is_colour_channel_name("blue"));
  EXPECT_NE(colour_channel_names().find("coolwarm"), std::string::npos);
}

TEST(ColourMaps, KnownColours)
{
  // viridis runs from dark purple to yellow; grey from black to white; rainbow blue to red.
  const Rgb v0 = *colour_map("viridis", 0);
  EXPECT_NEAR(v0[0], 0.267, 0.01);
  EXPECT_NEAR(v0[2], 0.329, 0.01);
  const Rgb v1 = *colour_map("viridis", 1);
  EXPECT_NEAR(v1[0], 0.993, 0.01);
  EXPECT_NEAR(v1[1], 0.906, 0.01);
  EXPECT_EQ(*colour_map("grey", 0.25), (Rgb{ 0.25, 0.25, 0.25 }));
  EXPECT_EQ(*colour_map("rainbow", 0), (Rgb{ 0, 0, 1 }));
  EXPECT_EQ(*colour_map("rainbow", 0.5), (Rgb{ 0, 1, 0 }));
  EXPECT_EQ(*colour_map("rainbow", 1), (Rgb{ 1, 0, 0 }));
  const Rgb mid = *colour_map("coolwarm", 0.5);
  EXPECT_NEAR(mid[0], mid[2], 1e-12); // neutral grey in the middle of the diverging map
  EXPECT_EQ(*colour_map("grey", -3), (Rgb{ 0, 0, 0 }));
}

TEST(ColourMaps, ViridisLightnessRises)
{
  double previous = -1;
  for (int k = 0; k <= 64; ++k)
  {
    const Rgb c = *colour_map("viridis", k / 64.0);
    const double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    EXPECT_GT(luma, previous);
    previous = luma;
  }
}

} // namespace
} // namespace frep::mapping
