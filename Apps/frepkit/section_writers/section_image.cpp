#include "section_image.h"

#include <algorithm>
#include <cmath>

namespace frepkit
{
namespace
{

std::uint8_t to_byte(double component)
{
  if (std::isnan(component))
  {
    return 0;
  }
  return static_cast<std::uint8_t>(std::lround(std::clamp(component, 0.0, 1.0) * 255.0));
}

} // namespace

std::vector<std::uint8_t> render_section(const SampledSection& section, double iso, bool colours)
{
  const std::int64_t width = section.samples[0];
  const std::int64_t height = section.samples[1];
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width * height * 3));
  auto inside = [&](std::int64_t i, std::int64_t j)
  { return section.values[static_cast<std::size_t>(i + width * j)] >= iso; };
  const bool use_colours = colours && section.attributes.size() >= 3;

  for (std::int64_t j = 0; j < height; ++j)
  {
    // Image rows run top to bottom; y runs bottom to top.
    std::uint8_t* row = rgb.data() + static_cast<std::size_t>((height - 1 - j) * width * 3);
    for (std::int64_t i = 0; i < width; ++i)
    {
      const std::size_t sample = static_cast<std::size_t>(i + width * j);
      std::uint8_t* pixel = row + 3 * i;
      const double value = section.values[sample];
      if (std::isnan(value))
      {
        pixel[0] = 255;
        pixel[1] = 0;
        pixel[2] = 255;
        continue;
      }
      if (value < iso)
      {
        pixel[0] = pixel[1] = pixel[2] = 235;
        continue;
      }
      const bool edge = (i > 0 && !inside(i - 1, j)) || (i + 1 < width && !inside(i + 1, j)) ||
                        (j > 0 && !inside(i, j - 1)) || (j + 1 < height && !inside(i, j + 1));
      if (edge)
      {
        pixel[0] = pixel[1] = pixel[2] = 30;
      }
      else if (use_colours)
      {
        for (int c = 0; c < 3; ++c)
        {
          pixel[c] = to_byte(section.attributes[static_cast<std::size_t>(c)][sample]);
        }
      }
      else
      {
        pixel[0] = 50;
        pixel[1] = 200;
        pixel[2] = 80;
      }
    }
  }
  return rgb;
}

} // namespace frepkit
