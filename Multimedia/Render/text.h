// Anti-aliased text for the rendered pictures (cell labels, frame captions, the inset's axes):
// FreeType's 8-bit grayscale glyphs blended into the image by coverage. One line of UTF-8 per
// call; the pen position is kept in 1/64 pixel and each glyph lands on a whole pixel (hinted,
// crisp), with kerning where the font has it.
#pragma once

#include "Imaging/image.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace frep::render
{

/// Code points of UTF-8 text; malformed sequences become U+FFFD (never an error).
std::vector<char32_t> decode_utf8(std::string_view utf8);

enum class HAlign
{
  Left,
  Centre,
  Right
};
enum class VAlign
{
  Top,      ///< the font's ascender line at y
  Middle,   ///< halfway between ascender and descender
  Baseline, ///< the baseline at y
  Bottom    ///< the font's descender line at y
};
struct Anchor
{
  HAlign h = HAlign::Left;
  VAlign v = VAlign::Baseline;
};

/// Axis-aligned pixel box [x0, x1) x [y0, y1), y down.
struct PixelBox
{
  double x0 = 0.0;
  double y0 = 0.0;
  double x1 = 0.0;
  double y1 = 0.0;
  bool empty() const { return !(x1 > x0 && y1 > y0); }
};

/// Where a string goes when drawn at (x, y) with an anchor.
struct TextLayout
{
  /// The advance box: from the pen's start to its end horizontally, ascender to descender
  /// vertically. This is what the anchor aligns.
  PixelBox box;
  /// The pixels glyphs may touch (union of the glyph bitmaps): nothing is drawn outside it.
  PixelBox ink;
  double baseline_y = 0.0;
};

/// A TrueType/OpenType face with its own FreeType library instance and glyph cache (one per
/// pixel size and code point). Move-only; not safe to use from two threads at once.
class Font
{
public:
  struct LoadResult;

  /// Load the face in `path`. A missing or unreadable file is an error value.
  static LoadResult load(const std::string& path);
  /// The first font found of: each of `extra_candidates` in order, then
  /// /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf (Debian's fonts-dejavu-core) and the usual
  /// places of DejaVu Sans, Liberation Sans and FreeSans on other systems.
  static LoadResult load_default(std::span<const std::string> extra_candidates = {});
  /// The default search list (for messages and documentation).
  static std::vector<std::string> default_candidates();

  Font(Font&&) noexcept;
  Font& operator=(Font&&) noexcept;
  ~Font();

  const std::string& path() const;
  std::string family() const;

  /// Layout of `utf8` at `pixel_height` (the em size in pixels) anchored at (x, y).
  TextLayout layout(double x, double y, std::string_view utf8, double pixel_height, Anchor anchor);

  /// Draw it over `image` in `colour` (linear, straight alpha). Returns the layout.
  TextLayout draw(imaging::Image& image,
    double x,
    double y,
    std::string_view utf8,
    double pixel_height,
    imaging::Rgba colour,
    Anchor anchor);

  struct Impl;

private:
  explicit Font(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

struct Font::LoadResult
{
  std::optional<Font> font;
  std::string error; ///< why there is no font (which paths were tried)
  bool ok() const { return font.has_value(); }
};

/// The size of a string: advance width, and the font's ascender/descender at that size (both
/// positive: pixels above and below the baseline), plus its ink box relative to a pen at (0, 0).
struct TextExtent
{
  double width = 0.0;
  double ascent = 0.0;
  double descent = 0.0;
  PixelBox ink;
};
TextExtent text_extent(Font& font, std::string_view utf8, double pixel_height);

/// Free-function spelling of Font::draw.
TextLayout draw_text(imaging::Image& image,
  Font& font,
  double x,
  double y,
  std::string_view utf8,
  double pixel_height,
  imaging::Rgba colour,
  Anchor anchor = {});

} // namespace frep::render
