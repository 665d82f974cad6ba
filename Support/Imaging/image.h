// A float RGBA picture and the few operations both renderers (the mesh renderer, the ray caster)
// need on it: fill, alpha-over compositing, box-filter downsampling (supersampling
// anti-aliasing) and 8-bit output.
//
// Colour convention (every picture of FRepKit): every colour value is LINEAR light in [0, 1]
// (not sRGB-encoded), so shading, blending and downsampling average light correctly and edges do
// not look too dark or too thin. Alpha is STRAIGHT (colour not multiplied by alpha). sRGB
// encoding happens once, on output (`to_rgb8`). Colours picked as sRGB values (a palette, a
// colour map, #rrggbb) are converted on input with `srgb()` / `srgb_to_linear()`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace frep::imaging
{

/// A linear-light colour with straight alpha.
struct Rgba
{
  float r = 0.0F;
  float g = 0.0F;
  float b = 0.0F;
  float a = 1.0F;
};

/// sRGB-encoded component (0..1) to linear light, and back (IEC 61966-2-1 curve).
float srgb_to_linear(float encoded);
float linear_to_srgb(float linear);

/// The linear colour of an sRGB-encoded colour given in 0..1 components ...
Rgba srgb(double r, double g, double b, double a = 1.0);
/// ... or as 0xRRGGBB (e.g. srgb_hex(0x1f77b4)).
Rgba srgb_hex(std::uint32_t rrggbb, double a = 1.0);

/// Row-major, top row first: pixel (x, y) is rgba[4 * (y * width + x) + 0..3].
struct Image
{
  int width = 0;
  int height = 0;
  std::vector<float> rgba;

  Image() = default;
  /// A width x height picture of one colour (transparent black by default). Negative sizes
  /// give an empty picture.
  Image(int width, int height, Rgba colour = { 0, 0, 0, 0 });

  bool empty() const { return width <= 0 || height <= 0; }
  float* pixel(int x, int y) { return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x); }
  const float* pixel(int x, int y) const
  {
    return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x);
  }
  Rgba at(int x, int y) const;
};

void fill(Image& image, Rgba colour);

/// Straight-alpha "over": blend `colour` with weight `coverage` (0..1, e.g. an anti-aliasing
/// coverage) over pixel (x, y). Outside the picture: nothing.
void blend_pixel(Image& image, int x, int y, Rgba colour, float coverage = 1.0F);

/// Composite `source` over `target` with the source's top-left corner at (x, y) of the target
/// (may be negative or partly outside: the overlap only), multiplying the source alpha by
/// `opacity`.
void composite_over(Image& target, const Image& source, int x, int y, float opacity = 1.0F);

/// Box-filter downsampling by an integer factor (>= 1): each output pixel averages a
/// factor x factor block, weighted by alpha (premultiplied averaging, so transparent samples do
/// not darken edges). Sizes not divisible by the factor drop the partial blocks.
Image downsample(const Image& image, int factor);

/// 8-bit sRGB rows, top row first, 3 bytes per pixel, after compositing over `background`
/// (opaque, linear). Values outside [0, 1] are clamped.
std::vector<std::uint8_t> to_rgb8(const Image& image, Rgba background = { 0, 0, 0, 1 });

/// Binary PPM (P6) of `to_rgb8(image, background)`: no dependency, any viewer or `oiiotool`
/// converts it. Returns an error message, empty on success.
std::string write_ppm(const Image& image,
  const std::string& path,
  Rgba background = { 0, 0, 0, 1 });

} // namespace frep::imaging
