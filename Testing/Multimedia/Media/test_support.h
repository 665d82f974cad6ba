// Helpers for the media tests: a fresh output directory per test, and PNG frames written
// without any image library (the movie encoder must be fed real PNG files).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace frep::media::testing
{

/// FREP_MEDIA_TEST_OUTPUT_DIR/<suite>.<test>, emptied and created.
std::filesystem::path fresh_directory();

/// The names of the files in `directory` (not recursive), sorted.
std::vector<std::string> file_names(const std::filesystem::path& directory);

/// Writes an 8-bit RGB PNG of width x height filled with `rgb`, with a diagonal stripe so that
/// consecutive frames differ. Uncompressed (stored) deflate blocks: valid PNG, no zlib needed.
/// Returns false when the file cannot be written.
bool write_png(const std::filesystem::path& path,
  int width,
  int height,
  std::array<std::uint8_t, 3> rgb,
  int stripe_offset);

} // namespace frep::media::testing
