// PNG through libpng, written into the caller's stream (a temporary file renamed when complete).
// Builds without libpng report it as not available.
#pragma once

#include <cstdint>
#include <ostream>
#include <vector>

namespace frepkit
{

/// `rgb`: width * height * 3 bytes, row 0 at the top.
void write_png(std::ostream& out,
  std::int64_t width,
  std::int64_t height,
  const std::vector<std::uint8_t>& rgb);

} // namespace frepkit
