// PNG with libpng, in the process. (It was OpenImageIO in a dlopened module: its start-up, which
// loads every image-format library it has, cost about 0.45 s per run that wrote a picture, more
// than sampling a 1024^2 image; libpng is one small library and the encoder is the same zlib.)
#include "Imaging/png_writer.h"

#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <vector>
#include <string>

namespace frep::imaging
{
namespace
{

struct Sink
{
  std::ostream* out = nullptr;
  bool failed = false;
  char message[256] = "";
};

void write_bytes(png_structp png, png_bytep data, png_size_t length)
{
  auto* sink = static_cast<Sink*>(png_get_io_ptr(png));
  sink->out->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
  sink->failed = sink->failed || !*sink->out;
}

void flush_bytes(png_structp png)
{
  static_cast<Sink*>(png_get_io_ptr(png))->out->flush();
}

void on_error(png_structp png, png_const_charp message)
{
  auto* sink = static_cast<Sink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

/// A picture of at most 256 colours as palette indices (sign images, contour plots: two or three
/// colours): a third of the bytes to compress, the same pixels once decoded.
struct Indexed
{
  std::vector<png_color> palette;
  std::vector<std::uint8_t> indices;
};

/// The palette form of `rgb`, or false as soon as a 257th colour appears (shaded pictures,
/// after a few rows at most).
bool index_colours(const std::uint8_t* rgb, std::size_t pixels, Indexed& out)
{
  // Open addressing on the 24-bit colour: 1024 slots for at most 256 colours.
  constexpr std::uint32_t kEmpty = 0xffffffffu;
  std::vector<std::uint32_t> keys(1024, kEmpty);
  std::vector<std::uint8_t> slot_index(1024, 0);
  out.indices.resize(pixels);
  std::uint32_t last = kEmpty;
  std::uint8_t last_index = 0;
  for (std::size_t p = 0; p < pixels; ++p)
  {
    const std::uint8_t* c = rgb + 3 * p;
    const std::uint32_t key = (std::uint32_t(c[0]) << 16) | (std::uint32_t(c[1]) << 8) | c[2];
    if (key != last)
    {
      std::uint32_t h = (key * 2654435761u) >> 22;
      while (keys[h] != kEmpty && keys[h] != key)
      {
        h = (h + 1) & 1023u;
      }
      if (keys[h] == kEmpty)
      {
        if (out.palette.size() == 256)
        {
          return false;
        }
        keys[h] = key;
        slot_index[h] = static_cast<std::uint8_t>(out.palette.size());
        out.palette.push_back({ c[0], c[1], c[2] });
      }
      last = key;
      last_index = slot_index[h];
    }
    out.indices[p] = last_index;
  }
  return true;
}

/// The libpng calls, in a function with only trivial locals (libpng reports errors by longjmp).
/// `indexed`: the picture as palette indices, or null for RGB rows.
bool encode(Sink& sink, std::int64_t width, std::int64_t height, const std::uint8_t* rgb,
  const Indexed* indexed)
{
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, on_error, on_warning);
  if (!png)
  {
    std::snprintf(sink.message, sizeof sink.message, "libpng could not start");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png)))
  {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return false;
  }
  png_set_write_fn(png, &sink, write_bytes, flush_bytes);
  // zlib level 3 instead of 6: frames are large flat areas; 30% less encoding time for files 20%
  // larger (measured on the demo's frames with the earlier encoder, the same zlib).
  png_set_compression_level(png, 3);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
    indexed ? PNG_COLOR_TYPE_PALETTE : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
    PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (indexed)
  {
    png_set_PLTE(png, info, const_cast<png_colorp>(indexed->palette.data()),
      static_cast<int>(indexed->palette.size()));
  }
  else
  {
    // Rows filtered by Sub or Up only, not libpng's trial of all five filters per row: a demo
    // frame encodes in 8.4 ms instead of 15.4 (3.7 % fewer bytes), the spreadsheet in 39 ms
    // instead of 64 for 2.5 % more bytes (Benchmarks/png_filter_benchmark.cpp on the demo's
    // PNGs, zlib level 3). (Palette pictures keep libpng's default: no filter.)
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB | PNG_FILTER_UP);
  }
  png_text software{};
  software.compression = PNG_TEXT_COMPRESSION_NONE;
  software.key = const_cast<png_charp>("Software");
  software.text = const_cast<png_charp>("frepkit");
  png_set_text(png, info, &software, 1);
  png_write_info(png, info);
  for (std::int64_t y = 0; y < height; ++y)
  {
    png_write_row(png,
      indexed ? const_cast<png_bytep>(indexed->indices.data() + y * width)
              : const_cast<png_bytep>(rgb + y * width * 3));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

} // namespace

void write_png(std::ostream& out, std::int64_t width, std::int64_t height,
  const std::vector<std::uint8_t>& rgb)
{
  if (width <= 0 || height <= 0 || width > 0x7fffffff || height > 0x7fffffff ||
    rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
  {
    throw PngError("PNG: the picture's size does not match its pixels");
  }
  Sink sink;
  sink.out = &out;
  Indexed indexed;
  const bool few_colours = index_colours(rgb.data(), rgb.size() / 3, indexed);
  if (!encode(sink, width, height, rgb.data(), few_colours ? &indexed : nullptr))
  {
    throw PngError(std::string("libpng could not encode the PNG: ") + sink.message);
  }
  if (sink.failed)
  {
    throw PngError("PNG: writing the file failed");
  }
}

void write_png(std::ostream& out, const Image& image)
{
  write_png(out, image.width, image.height, to_rgb8(image));
}

} // namespace frep::imaging
