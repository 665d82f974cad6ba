#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace frep::media::testing
{
namespace
{

std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc = 0)
{
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i)
  {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::uint32_t adler32(const std::vector<std::uint8_t>& data)
{
  std::uint32_t a = 1;
  std::uint32_t b = 0;
  for (const std::uint8_t byte : data)
  {
    a = (a + byte) % 65521u;
    b = (b + a) % 65521u;
  }
  return (b << 16) | a;
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t value)
{
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<std::uint8_t>(value >> shift));
}

void chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data)
{
  put32(out, static_cast<std::uint32_t>(data.size()));
  std::vector<std::uint8_t> body(type, type + 4);
  body.insert(body.end(), data.begin(), data.end());
  out.insert(out.end(), body.begin(), body.end());
  put32(out, crc32(body.data(), body.size()));
}

} // namespace

std::filesystem::path fresh_directory()
{
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path directory =
    std::filesystem::path(FREP_MEDIA_TEST_OUTPUT_DIR) /
    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

std::vector<std::string> file_names(const std::filesystem::path& directory)
{
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool write_png(const std::filesystem::path& path,
  int width,
  int height,
  std::array<std::uint8_t, 3> rgb,
  int stripe_offset)
{
  std::vector<std::uint8_t> raw; // filter byte 0 (none) + RGB per row
  for (int y = 0; y < height; ++y)
  {
    raw.push_back(0);
    for (int x = 0; x < width; ++x)
    {
      const bool stripe = (x + y + stripe_offset) % 16 < 3;
      for (int c = 0; c < 3; ++c)
        raw.push_back(stripe ? static_cast<std::uint8_t>(255 - rgb[c]) : rgb[c]);
    }
  }
  std::vector<std::uint8_t> zlib{ 0x78, 0x01 }; // deflate, 32K window, no dictionary
  for (std::size_t start = 0; start < raw.size() || start == 0; start += 65535)
  {
    const std::size_t length = std::min<std::size_t>(65535, raw.size() - start);
    const bool last = start + length >= raw.size();
    zlib.push_back(last ? 1 : 0); // BFINAL, BTYPE = 00 (stored)
    zlib.push_back(static_cast<std::uint8_t>(length));
    zlib.push_back(static_cast<std::uint8_t>(length >> 8));
    zlib.push_back(static_cast<std::uint8_t>(~length));
    zlib.push_back(static_cast<std::uint8_t>(~length >> 8));
    zlib.insert(zlib.end(), raw.begin() + start, raw.begin() + start + length);
    if (last)
      break;
  }
  put32(zlib, adler32(raw));

  std::vector<std::uint8_t> png{ 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n' };
  std::vector<std::uint8_t> header;
  put32(header, static_cast<std::uint32_t>(width));
  put32(header, static_cast<std::uint32_t>(height));
  header.insert(header.end(), { 8, 2, 0, 0, 0 }); // 8-bit, RGB, deflate, adaptive, no interlace
  chunk(png, "IHDR", header);
  chunk(png, "IDAT", zlib);
  chunk(png, "IEND", {});
  std::ofstream file(path, std::ios::binary);
  file.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  return static_cast<bool>(file);
}

} // namespace frep::media::testing
