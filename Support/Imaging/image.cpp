#include "Imaging/image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>

namespace frep::imaging
{

float srgb_to_linear(float encoded)
{
  const float c = std::clamp(encoded, 0.0F, 1.0F);
  return c <= 0.04045F ? c / 12.92F : std::pow((c + 0.055F) / 1.055F, 2.4F);
}

float linear_to_srgb(float linear)
{
  const float c = std::clamp(linear, 0.0F, 1.0F);
  return c <= 0.0031308F ? 12.92F * c : 1.055F * std::pow(c, 1.0F / 2.4F) - 0.055F;
}

Rgba srgb(double r, double g, double b, double a)
{
  return { srgb_to_linear(static_cast<float>(r)),
    srgb_to_linear(static_cast<float>(g)),
    srgb_to_linear(static_cast<float>(b)),
    static_cast<float>(std::clamp(a, 0.0, 1.0)) };
}

Rgba srgb_hex(std::uint32_t rrggbb, double a)
{
  return srgb(
    ((rrggbb >> 16) & 0xFF) / 255.0, ((rrggbb >> 8) & 0xFF) / 255.0, (rrggbb & 0xFF) / 255.0, a);
}

Image::Image(int w, int h, Rgba colour)
  : width(std::max(w, 0))
  , height(std::max(h, 0))
{
  if (width == 0 || height == 0)
  {
    width = height = 0;
  }
  rgba.resize(static_cast<std::size_t>(width) * height * 4);
  fill(*this, colour);
}

Rgba Image::at(int x, int y) const
{
  const float* p = pixel(x, y);
  return { p[0], p[1], p[2], p[3] };
}

void fill(Image& image, Rgba colour)
{
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
  {
    image.rgba[i + 0] = colour.r;
    image.rgba[i + 1] = colour.g;
    image.rgba[i + 2] = colour.b;
    image.rgba[i + 3] = colour.a;
  }
}

namespace
{

// Straight-alpha over of (r, g, b, a) onto the pixel at p.
inline void over(float* p, float r, float g, float b, float a)
{
  if (!(a > 0.0F))
  {
    return;
  }
  const float keep = p[3] * (1.0F - a);
  const float out_a = a + keep;
  const float inv = 1.0F / out_a;
  p[0] = (r * a + p[0] * keep) * inv;
  p[1] = (g * a + p[1] * keep) * inv;
  p[2] = (b * a + p[2] * keep) * inv;
  p[3] = out_a;
}

} // namespace

void blend_pixel(Image& image, int x, int y, Rgba colour, float coverage)
{
  if (x < 0 || y < 0 || x >= image.width || y >= image.height)
  {
    return;
  }
  over(
    image.pixel(x, y), colour.r, colour.g, colour.b, colour.a * std::clamp(coverage, 0.0F, 1.0F));
}

void composite_over(Image& target, const Image& source, int x, int y, float opacity)
{
  const int x0 = std::max(0, x);
  const int y0 = std::max(0, y);
  const int x1 = std::min(target.width, x + source.width);
  const int y1 = std::min(target.height, y + source.height);
  const float k = std::clamp(opacity, 0.0F, 1.0F);
  for (int ty = y0; ty < y1; ++ty)
  {
    for (int tx = x0; tx < x1; ++tx)
    {
      const float* s = source.pixel(tx - x, ty - y);
      over(target.pixel(tx, ty), s[0], s[1], s[2], s[3] * k);
    }
  }
}

Image downsample(const Image& image, int factor)
{
  if (factor <= 1)
  {
    return image;
  }
  Image out(image.width / factor, image.height / factor);
  const float inv_n = 1.0F / static_cast<float>(factor * factor);
  for (int y = 0; y < out.height; ++y)
  {
    for (int x = 0; x < out.width; ++x)
    {
      float r = 0, g = 0, b = 0, a = 0;
      for (int sy = 0; sy < factor; ++sy)
      {
        const float* s = image.pixel(x * factor, y * factor + sy);
        for (int sx = 0; sx < factor; ++sx, s += 4)
        {
          r += s[0] * s[3];
          g += s[1] * s[3];
          b += s[2] * s[3];
          a += s[3];
        }
      }
      float* p = out.pixel(x, y);
      if (a > 0.0F)
      {
        p[0] = r / a;
        p[1] = g / a;
        p[2] = b / a;
      }
      p[3] = a * inv_n;
    }
  }
  return out;
}

namespace
{

// Linear [0, 1] -> 8-bit sRGB through a table: one pow per entry instead of per pixel. 16384
// entries keep the darkest steps (slope 12.92) within half a code value.
constexpr int kSrgbTableSize = 16384;

std::uint8_t encode8(const std::vector<std::uint8_t>& table, float linear)
{
  const float c = std::isnan(linear) ? 0.0F : std::clamp(linear, 0.0F, 1.0F);
  return table[static_cast<std::size_t>(c * (kSrgbTableSize - 1) + 0.5F)];
}

} // namespace

std::vector<std::uint8_t> to_rgb8(const Image& image, Rgba background)
{
  std::vector<std::uint8_t> table(kSrgbTableSize);
  for (int i = 0; i < kSrgbTableSize; ++i)
  {
    const float v = linear_to_srgb(static_cast<float>(i) / (kSrgbTableSize - 1));
    table[i] = static_cast<std::uint8_t>(std::lround(v * 255.0F));
  }
  std::vector<std::uint8_t> out(static_cast<std::size_t>(image.width) * image.height * 3);
  for (std::size_t i = 0, o = 0; o < out.size(); i += 4, o += 3)
  {
    const float* p = image.rgba.data() + i;
    const float a = std::clamp(p[3], 0.0F, 1.0F);
    out[o + 0] = encode8(table, p[0] * a + background.r * (1.0F - a));
    out[o + 1] = encode8(table, p[1] * a + background.g * (1.0F - a));
    out[o + 2] = encode8(table, p[2] * a + background.b * (1.0F - a));
  }
  return out;
}

std::string write_ppm(const Image& image, const std::string& path, Rgba background)
{
  if (image.empty())
  {
    return "write_ppm: the image is empty";
  }
  const std::vector<std::uint8_t> rgb = to_rgb8(image, background);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(
    std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!file)
  {
    return "write_ppm: cannot open '" + path + "' for writing";
  }
  std::fprintf(file.get(), "P6\n%d %d\n255\n", image.width, image.height);
  if (std::fwrite(rgb.data(), 1, rgb.size(), file.get()) != rgb.size())
  {
    return "write_ppm: cannot write '" + path + "'";
  }
  if (std::fclose(file.release()) != 0)
  {
    return "write_ppm: cannot finish '" + path + "'";
  }
  return {};
}

} // namespace frep::imaging
