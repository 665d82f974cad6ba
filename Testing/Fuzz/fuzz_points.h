// Deterministic evaluation points for a fuzz input: a small PRNG seeded from the input's bytes,
// so every run of the same input (libFuzzer, the replay test, a reproduction by hand) sees the
// same points, and a mutation of the text also moves the points.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>

namespace frep_fuzz
{

class PointSource
{
public:
  explicit PointSource(std::string_view bytes)
  {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a
    for (const char c : bytes)
    {
      h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    }
    state_ = h;
  }

  std::uint64_t next()
  {
    // splitmix64
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }

  /// A coordinate: mostly ordinary values of a modelling box, sometimes the values where
  /// functions misbehave (0, -0, integers for floor/mod, tiny and huge magnitudes, infinities).
  double coordinate()
  {
    static constexpr std::array<double, 10> special{ 0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, -1e300,
      1e300, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
    const std::uint64_t r = next();
    switch (r % 4)
    {
      case 0:
        return special[(r >> 8) % special.size()];
      case 1:
        return static_cast<double>(static_cast<int>((r >> 8) % 9) - 4);
      default:
        return -12.0 + 24.0 * static_cast<double>(r >> 11) * 0x1.0p-53;
    }
  }

private:
  std::uint64_t state_;
};

} // namespace frep_fuzz
