// PNG through libpng, written into the caller's stream (a temporary file put in place when
// complete: Support/Durable). Builds without libpng throw PngError saying so.
#pragma once

#include "Imaging/image.h"

#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace frep::imaging
{

/// A picture that could not be encoded or written, or PNG output missing from this build.
struct PngError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// `rgb`: width * height * 3 bytes, row 0 at the top. Pictures of at most 256 colours are
/// written with a palette (the same pixels once decoded). Throws PngError.
void write_png(std::ostream& out,
  std::int64_t width,
  std::int64_t height,
  const std::vector<std::uint8_t>& rgb);

/// The picture in 8-bit sRGB (to_rgb8).
void write_png(std::ostream& out, const Image& image);

} // namespace frep::imaging
