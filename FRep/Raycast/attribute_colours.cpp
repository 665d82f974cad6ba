#include "Raycast/raycast.h"

#include "Compiler/attribute_rgb.h"
#include "Imaging/image.h"

#include <algorithm>

namespace frep::raycast
{

ColourFunction attribute_colours()
{
  return [](const std::array<double, 3>&, std::span<const double> outputs)
  {
    // The mesher stores s[] as floats: the same rounding, so both methods colour alike.
    const std::size_t count = outputs.empty() ? 0 : std::min<std::size_t>(3, outputs.size() - 1);
    std::array<float, 3> s{ 0.0F, 0.0F, 0.0F };
    for (std::size_t i = 0; i < count; ++i)
    {
      s[i] = static_cast<float>(outputs[1 + i]);
    }
    const AttributeRgb rgb = attribute_rgb(s.data(), count);
    return std::array<float, 3>{ imaging::srgb_to_linear(rgb[0]), imaging::srgb_to_linear(rgb[1]),
      imaging::srgb_to_linear(rgb[2]) };
  };
}

} // namespace frep::raycast
