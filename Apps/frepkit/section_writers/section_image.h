// A sampled section: F (and s[]) on a regular 2-D or 3-D grid, and its picture.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace frepkit
{

struct SampledSection
{
  int axes = 2;                                   ///< 2 (an image) or 3 (a volume)
  std::array<std::int64_t, 3> samples{ 1, 1, 1 }; ///< per axis (1 on unused axes)
  std::array<double, 3> origin{ 0, 0, 0 };        ///< the first sample
  std::array<double, 3> spacing{ 1, 1, 1 };
  std::array<std::string, 3> axis_names{ "x1", "x2", "x3" }; ///< the model coordinates
  /// F per sample, x fastest, then y, then z; NaN where the model raised a run-time error.
  std::vector<double> values;
  /// s[1..m] per sample, same layout (empty when not sampled).
  std::vector<std::vector<double>> attributes;
  std::size_t failed = 0; ///< samples with a run-time error

  std::size_t count() const
  {
    return static_cast<std::size_t>(samples[0] * samples[1] * samples[2]);
  }
};

/// The picture of a 2-D section, RGB 8-bit, row 0 at the top (largest y: y points up), one
/// pixel per sample. Inside (F >= iso): the colour of s[1..3] when `colours` (clamped to
/// [0, 1]), else hfp's face green (50, 200, 80); outside: light grey (235); the contour: inside
/// pixels next to an outside pixel (4-neighbours) are drawn dark (30); samples whose evaluation
/// failed are magenta (255, 0, 255) so that they cannot be mistaken for the shape.
std::vector<std::uint8_t> render_section(const SampledSection& section, double iso, bool colours);

} // namespace frepkit
