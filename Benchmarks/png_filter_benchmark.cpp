// The row filters of frepkit's RGB PNG writer (Apps/frepkit/section_writers/png_writer.cpp):
// libpng's default (it tries all five filters on every row and keeps the best) against Sub or Up
// only, both at the writer's zlib level 3, on pictures you give it (the demo's frames and
// spreadsheet: `frepkit demo homotopic -O DIR`, then DIR/frames/frame_00000.png and
// DIR/spreadsheet.png). Encoding goes to memory; reading the file is not timed.
//
// Usage: frep_png_filter_benchmark PICTURE.png... [--repeat 11]
// Prints per picture the median encoding time and the size for each filter choice.
#include <png.h>

#include <algorithm>
#include <chrono>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace
{

struct Picture
{
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

bool read_rgb(const std::string& path, Picture& picture)
{
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str()))
  {
    std::cerr << path << ": " << image.message << "\n";
    return false;
  }
  image.format = PNG_FORMAT_RGB;
  picture.width = image.width;
  picture.height = image.height;
  picture.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, picture.rgb.data(), 0, nullptr))
  {
    std::cerr << path << ": " << image.message << "\n";
    return false;
  }
  return true;
}

void append(png_structp png, png_bytep data, png_size_t length)
{
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

void no_flush(png_structp) {}

/// The writer's settings (level 3, RGB, no interlace); `filters` 0 keeps libpng's default.
/// Returns the encoded size, 0 on a libpng error.
std::size_t encode(const Picture& p, int filters, std::vector<std::uint8_t>& out)
{
  out.clear();
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info || setjmp(png_jmpbuf(png)))
  {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return 0;
  }
  png_set_write_fn(png, &out, append, no_flush);
  png_set_compression_level(png, 3);
  png_set_IHDR(png, info, p.width, p.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
    PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (filters != 0)
  {
    png_set_filter(png, PNG_FILTER_TYPE_BASE, filters);
  }
  png_write_info(png, info);
  for (std::uint32_t y = 0; y < p.height; ++y)
  {
    png_write_row(png, p.rgb.data() + std::size_t{ 3 } * p.width * y);
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out.size();
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> files;
  int repeat = 11;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc)
    {
      repeat = std::max(1, std::stoi(argv[++i]));
    }
    else
    {
      files.push_back(a);
    }
  }
  if (files.empty())
  {
    std::cerr << "usage: frep_png_filter_benchmark PICTURE.png... [--repeat N]\n";
    return 1;
  }
  const struct
  {
    const char* name;
    int filters;
  } choices[] = { { "all five (libpng's default)", 0 },
    { "Sub or Up (frepkit)", PNG_FILTER_SUB | PNG_FILTER_UP } };
  std::vector<std::uint8_t> buffer;
  for (const std::string& file : files)
  {
    Picture picture;
    if (!read_rgb(file, picture))
    {
      return 1;
    }
    for (const auto& choice : choices)
    {
      std::vector<double> ms;
      std::size_t bytes = 0;
      for (int r = 0; r < repeat; ++r)
      {
        const auto t0 = std::chrono::steady_clock::now();
        bytes = encode(picture, choice.filters, buffer);
        ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      }
      if (bytes == 0)
      {
        std::cerr << file << ": libpng failed to encode\n";
        return 1;
      }
      std::sort(ms.begin(), ms.end());
      std::printf("%s (%ux%u), %s: median %.1f ms of %d, %zu bytes\n", file.c_str(),
        picture.width, picture.height, choice.name, ms[ms.size() / 2], repeat, bytes);
    }
  }
  return 0;
}
