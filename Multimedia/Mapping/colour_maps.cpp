#include "Mapping/colour_maps.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace frep::mapping
{
namespace
{

// Control points in 0..255 at v = k / (n - 1).
struct NamedMap
{
  std::string_view name;
  std::span<const std::array<double, 3>> points;
};

// matplotlib's viridis and plasma (van der Walt & Smith) at 9 even steps: the values
// matplotlib's tables give at 0, 1/8, ..., 1 (as R's viridisLite prints them).
constexpr std::array<std::array<double, 3>, 9> viridis{ {
  { 68, 1, 84 },
  { 71, 45, 123 },
  { 59, 82, 139 },
  { 44, 114, 142 },
  { 33, 144, 140 },
  { 39, 173, 129 },
  { 93, 200, 99 },
  { 170, 220, 50 },
  { 253, 231, 37 },
} };

constexpr std::array<std::array<double, 3>, 9> plasma{ {
  { 13, 8, 135 },
  { 76, 2, 161 },
  { 126, 3, 168 },
  { 169, 35, 149 },
  { 204, 70, 120 },
  { 229, 107, 93 },
  { 248, 148, 65 },
  { 253, 195, 40 },
  { 240, 249, 33 },
} };

// Moreland's diverging "cool to warm" map (ParaView's default), 9 of his tabulated points.
constexpr std::array<std::array<double, 3>, 9> coolwarm{ {
  { 59, 76, 192 },
  { 98, 130, 234 },
  { 141, 176, 254 },
  { 184, 208, 249 },
  { 221, 221, 221 },
  { 245, 196, 173 },
  { 244, 154, 123 },
  { 222, 96, 77 },
  { 180, 4, 38 },
} };

constexpr std::array<std::array<double, 3>, 2> grey{ {
  { 0, 0, 0 },
  { 255, 255, 255 },
} };

// Full-saturation hue from blue (240 degrees) down to red (0 degrees); at these 9 points linear
// interpolation is exactly the HSV ramp (each piece changes one component linearly).
constexpr std::array<std::array<double, 3>, 9> rainbow{ {
  { 0, 0, 255 },
  { 0, 127.5, 255 },
  { 0, 255, 255 },
  { 0, 255, 127.5 },
  { 0, 255, 0 },
  { 127.5, 255, 0 },
  { 255, 255, 0 },
  { 255, 127.5, 0 },
  { 255, 0, 0 },
} };

constexpr std::array<NamedMap, 5> maps{ {
  { "viridis", viridis },
  { "plasma", plasma },
  { "coolwarm", coolwarm },
  { "grey", grey },
  { "rainbow", rainbow },
} };

constexpr std::array<std::string_view, 3> components{ "red", "green", "blue" };

const NamedMap* find_map(std::string_view name)
{
  for (const NamedMap& m : maps)
  {
    if (m.name == name)
    {
      return &m;
    }
  }
  return nullptr;
}

} // namespace

bool is_colour_map(std::string_view name)
{
  return find_map(name) != nullptr;
}

std::optional<Rgb> colour_map(std::string_view name, double v)
{
  const NamedMap* m = find_map(name);
  if (!m)
  {
    return std::nullopt;
  }
  v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0);
  const std::size_t last = m->points.size() - 1;
  const double position = v * static_cast<double>(last);
  const std::size_t k = std::min(static_cast<std::size_t>(position), last - 1);
  const double f = position - static_cast<double>(k);
  Rgb rgb;
  for (int c = 0; c < 3; ++c)
  {
    const double a = m->points[k][c];
    const double b = m->points[k + 1][c];
    rgb[c] = (a + f * (b - a)) / 255.0;
  }
  return rgb;
}

std::optional<int> colour_component(std::string_view name)
{
  for (std::size_t c = 0; c < components.size(); ++c)
  {
    if (components[c] == name)
    {
      return static_cast<int>(c);
    }
  }
  return std::nullopt;
}

bool is_colour_channel_name(std::string_view name)
{
  return is_colour_map(name) || colour_component(name).has_value();
}

std::string colour_channel_names()
{
  std::string names;
  for (const NamedMap& m : maps)
  {
    names += std::string(m.name) + ", ";
  }
  for (std::string_view c : components)
  {
    names += std::string(c) + (c == components.back() ? "" : ", ");
  }
  return names;
}

} // namespace frep::mapping
