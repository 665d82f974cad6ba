#include "Render/text.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <unordered_map>

namespace frep::render
{

std::vector<char32_t> decode_utf8(std::string_view s)
{
  std::vector<char32_t> out;
  out.reserve(s.size());
  constexpr char32_t kReplacement = 0xFFFD;
  std::size_t i = 0;
  while (i < s.size())
  {
    const auto b0 = static_cast<unsigned char>(s[i]);
    int length = 0;
    char32_t cp = 0;
    char32_t min = 0;
    if (b0 < 0x80)
    {
      out.push_back(b0);
      ++i;
      continue;
    }
    if ((b0 & 0xE0) == 0xC0)
    {
      length = 2, cp = b0 & 0x1F, min = 0x80;
    }
    else if ((b0 & 0xF0) == 0xE0)
    {
      length = 3, cp = b0 & 0x0F, min = 0x800;
    }
    else if ((b0 & 0xF8) == 0xF0)
    {
      length = 4, cp = b0 & 0x07, min = 0x10000;
    }
    else
    {
      out.push_back(kReplacement); // a stray continuation byte or an invalid lead byte
      ++i;
      continue;
    }
    int k = 1;
    for (; k < length && i + k < s.size(); ++k)
    {
      const auto b = static_cast<unsigned char>(s[i + k]);
      if ((b & 0xC0) != 0x80)
      {
        break;
      }
      cp = (cp << 6) | (b & 0x3F);
    }
    if (k < length)
    {
      out.push_back(kReplacement); // truncated: resume at the byte that broke the sequence
      i += k;
      continue;
    }
    // Overlong forms, surrogates and values beyond Unicode are not characters.
    out.push_back(cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) ? kReplacement : cp);
    i += length;
  }
  return out;
}

namespace
{

struct Glyph
{
  FT_UInt index = 0;
  long advance = 0; ///< 26.6 pixels, unhinted (even spacing at any size)
  int left = 0;     ///< bitmap offset from the pen, pixels, x right
  int top = 0;      ///< bitmap top above the baseline, pixels
  int width = 0;
  int rows = 0;
  std::vector<std::uint8_t> coverage;
};

} // namespace

struct Font::Impl
{
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  std::string path;
  long size = -1; ///< 26.6 pixels currently set on the face
  std::unordered_map<std::uint64_t, Glyph> cache;

  ~Impl()
  {
    if (face)
    {
      FT_Done_Face(face);
    }
    if (library)
    {
      FT_Done_FreeType(library);
    }
  }

  void set_size(long size64)
  {
    if (size64 != size)
    {
      FT_Set_Char_Size(face, 0, size64, 72, 72); // 72 dpi: 1 point = 1 pixel
      size = size64;
    }
  }

  const Glyph& glyph(char32_t cp, long size64)
  {
    const std::uint64_t key = (static_cast<std::uint64_t>(size64) << 21) | cp;
    if (const auto found = cache.find(key); found != cache.end())
    {
      return found->second;
    }
    set_size(size64);
    Glyph g;
    g.index = FT_Get_Char_Index(face, cp); // 0: the font's missing-glyph box
    // Light hinting: crisp horizontal stems, the design's shapes and spacing otherwise.
    if (FT_Load_Glyph(face, g.index, FT_LOAD_TARGET_LIGHT) == 0 &&
        FT_Render_Glyph(face->glyph, FT_RENDER_MODE_LIGHT) == 0)
    {
      const FT_GlyphSlot slot = face->glyph;
      g.advance = slot->linearHoriAdvance >> 10; // 16.16 -> 26.6
      const FT_Bitmap& bitmap = slot->bitmap;
      if (bitmap.pixel_mode == FT_PIXEL_MODE_GRAY && bitmap.buffer)
      {
        g.left = slot->bitmap_left;
        g.top = slot->bitmap_top;
        g.width = static_cast<int>(bitmap.width);
        g.rows = static_cast<int>(bitmap.rows);
        g.coverage.resize(static_cast<std::size_t>(g.width) * g.rows);
        const int pitch = std::abs(bitmap.pitch);
        for (int r = 0; r < g.rows; ++r)
        {
          // A negative pitch stores the rows bottom-up.
          const int source = bitmap.pitch >= 0 ? r : g.rows - 1 - r;
          std::copy_n(bitmap.buffer + static_cast<std::ptrdiff_t>(source) * pitch,
            g.width,
            g.coverage.begin() + static_cast<std::ptrdiff_t>(r) * g.width);
        }
      }
    }
    return cache.emplace(key, std::move(g)).first->second;
  }
};

namespace
{

long to_size64(double pixel_height)
{
  if (!(pixel_height > 0.0) || !std::isfinite(pixel_height))
  {
    return 0;
  }
  return std::lround(std::min(pixel_height, 2048.0) * 64.0);
}

struct PlacedGlyph
{
  const Glyph* glyph;
  int x; ///< pen position, whole pixels (relative to the layout's pen start)
};

// Pen positions of the glyphs relative to a pen at 0 (26.6 accumulation, rounded per glyph).
std::vector<PlacedGlyph> place(Font::Impl& impl, std::string_view utf8, long size64, long& width64)
{
  std::vector<PlacedGlyph> placed;
  width64 = 0;
  if (size64 <= 0)
  {
    return placed;
  }
  const bool kerning = FT_HAS_KERNING(impl.face);
  FT_UInt previous = 0;
  long pen = 0;
  for (const char32_t cp : decode_utf8(utf8))
  {
    const Glyph& g = impl.glyph(cp, size64);
    if (kerning && previous && g.index)
    {
      impl.set_size(size64);
      FT_Vector delta{};
      if (FT_Get_Kerning(impl.face, previous, g.index, FT_KERNING_UNFITTED, &delta) == 0)
      {
        pen += delta.x;
      }
    }
    placed.push_back({ &g, static_cast<int>((pen + 32) >> 6) });
    pen += g.advance;
    previous = g.index;
  }
  width64 = pen;
  return placed;
}

// FreeType's coverage is tuned for blending in gamma-encoded space, as every text renderer
// does: blended linearly, dark text on light ground comes out thin and grey at small sizes. So
// over an opaque pixel the mix is done on sRGB values; elsewhere it is a plain alpha blend.
void blend_glyph_pixel(imaging::Image& image, int x, int y, imaging::Rgba colour, float coverage)
{
  if (x < 0 || y < 0 || x >= image.width || y >= image.height)
  {
    return;
  }
  float* p = image.pixel(x, y);
  if (p[3] < 1.0F)
  {
    imaging::blend_pixel(image, x, y, colour, coverage);
    return;
  }
  const float k = std::clamp(coverage * colour.a, 0.0F, 1.0F);
  const float c[3] = { colour.r, colour.g, colour.b };
  for (int i = 0; i < 3; ++i)
  {
    p[i] = imaging::srgb_to_linear(
      imaging::linear_to_srgb(p[i]) * (1.0F - k) + imaging::linear_to_srgb(c[i]) * k);
  }
}

} // namespace

Font::Font(std::unique_ptr<Impl> impl)
  : impl_(std::move(impl))
{
}
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;
Font::~Font() = default;

Font::LoadResult Font::load(const std::string& path)
{
  LoadResult result;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
  {
    result.error = "font: no such file '" + path + "'";
    return result;
  }
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  if (FT_Init_FreeType(&impl->library) != 0)
  {
    impl->library = nullptr;
    result.error = "font: cannot start FreeType";
    return result;
  }
  if (const FT_Error e = FT_New_Face(impl->library, path.c_str(), 0, &impl->face); e != 0)
  {
    impl->face = nullptr;
    result.error =
      "font: '" + path + "' is not a font FreeType can read (error " + std::to_string(e) + ")";
    return result;
  }
  if (!FT_IS_SCALABLE(impl->face))
  {
    result.error =
      "font: '" + path + "' is a bitmap font; a scalable (TrueType/OpenType) font is needed";
    return result;
  }
  FT_Select_Charmap(impl->face, FT_ENCODING_UNICODE);
  result.font.emplace(Font(std::move(impl)));
  return result;
}

std::vector<std::string> Font::default_candidates()
{
  return {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",   // Debian, Ubuntu
    "/usr/share/fonts/TTF/DejaVuSans.ttf",               // Arch
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",            // Fedora, openSUSE
    "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf", // Fedora (newer)
    "/usr/local/share/fonts/dejavu/DejaVuSans.ttf",      // FreeBSD
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
    "/usr/share/fonts/truetype/freefont/FreeSans.ttf",
    "/Library/Fonts/Arial.ttf", // macOS
  };
}

Font::LoadResult Font::load_default(std::span<const std::string> extra_candidates)
{
  std::vector<std::string> candidates(extra_candidates.begin(), extra_candidates.end());
  for (std::string& c : default_candidates())
  {
    candidates.push_back(std::move(c));
  }
  std::string tried;
  for (const std::string& path : candidates)
  {
    LoadResult r = load(path);
    if (r.ok())
    {
      return r;
    }
    tried += "\n  " + r.error;
  }
  LoadResult failed;
  failed.error = "font: no usable font found (install fonts-dejavu-core); tried:" + tried;
  return failed;
}

const std::string& Font::path() const
{
  return impl_->path;
}

std::string Font::family() const
{
  std::string name = impl_->face->family_name ? impl_->face->family_name : "";
  if (impl_->face->style_name)
  {
    name += std::string(" ") + impl_->face->style_name;
  }
  return name;
}

TextLayout Font::layout(double x,
  double y,
  std::string_view utf8,
  double pixel_height,
  Anchor anchor)
{
  TextLayout out;
  const long size64 = to_size64(pixel_height);
  long width64 = 0;
  const std::vector<PlacedGlyph> placed = place(*impl_, utf8, size64, width64);
  double ascent = 0.0, descent = 0.0;
  if (size64 > 0)
  {
    impl_->set_size(size64);
    ascent = impl_->face->size->metrics.ascender / 64.0;
    descent = -impl_->face->size->metrics.descender / 64.0;
  }
  const double width = width64 / 64.0;
  double pen_x = x;
  if (anchor.h == HAlign::Centre)
  {
    pen_x -= 0.5 * width;
  }
  else if (anchor.h == HAlign::Right)
  {
    pen_x -= width;
  }
  double baseline = y;
  switch (anchor.v)
  {
    case VAlign::Top:
      baseline += ascent;
      break;
    case VAlign::Middle:
      baseline += 0.5 * (ascent - descent);
      break;
    case VAlign::Bottom:
      baseline -= descent;
      break;
    case VAlign::Baseline:
      break;
  }
  // Whole pixels: hinted glyphs stay crisp.
  pen_x = std::round(pen_x);
  baseline = std::round(baseline);
  out.baseline_y = baseline;
  out.box = { pen_x, baseline - ascent, pen_x + width, baseline + descent };
  bool any = false;
  for (const PlacedGlyph& p : placed)
  {
    if (p.glyph->width == 0 || p.glyph->rows == 0)
    {
      continue;
    }
    const double gx0 = pen_x + p.x + p.glyph->left;
    const double gy0 = baseline - p.glyph->top;
    const PixelBox g{ gx0, gy0, gx0 + p.glyph->width, gy0 + p.glyph->rows };
    if (!any)
    {
      out.ink = g;
      any = true;
    }
    else
    {
      out.ink = { std::min(out.ink.x0, g.x0),
        std::min(out.ink.y0, g.y0),
        std::max(out.ink.x1, g.x1),
        std::max(out.ink.y1, g.y1) };
    }
  }
  if (!any)
  {
    out.ink = { pen_x, baseline, pen_x, baseline };
  }
  return out;
}

TextLayout Font::draw(imaging::Image& image,
  double x,
  double y,
  std::string_view utf8,
  double pixel_height,
  imaging::Rgba colour,
  Anchor anchor)
{
  const TextLayout out = layout(x, y, utf8, pixel_height, anchor);
  long width64 = 0;
  const std::vector<PlacedGlyph> placed = place(*impl_, utf8, to_size64(pixel_height), width64);
  const int pen_x = static_cast<int>(out.box.x0);
  const int baseline = static_cast<int>(out.baseline_y);
  for (const PlacedGlyph& p : placed)
  {
    const Glyph& g = *p.glyph;
    const int gx0 = pen_x + p.x + g.left;
    const int gy0 = baseline - g.top;
    for (int r = 0; r < g.rows; ++r)
    {
      const int py = gy0 + r;
      if (py < 0 || py >= image.height)
      {
        continue;
      }
      for (int c = 0; c < g.width; ++c)
      {
        const std::uint8_t coverage = g.coverage[static_cast<std::size_t>(r) * g.width + c];
        if (coverage != 0)
        {
          blend_glyph_pixel(image, gx0 + c, py, colour, coverage / 255.0F);
        }
      }
    }
  }
  return out;
}

TextExtent text_extent(Font& font, std::string_view utf8, double pixel_height)
{
  const TextLayout l = font.layout(0.0, 0.0, utf8, pixel_height, {});
  return { l.box.x1 - l.box.x0, -l.box.y0, l.box.y1, l.ink };
}

TextLayout draw_text(imaging::Image& image,
  Font& font,
  double x,
  double y,
  std::string_view utf8,
  double pixel_height,
  imaging::Rgba colour,
  Anchor anchor)
{
  return font.draw(image, x, y, utf8, pixel_height, colour, anchor);
}

} // namespace frep::render
