#include "Imaging/lighting.h"

namespace frep::imaging
{

std::vector<Light> default_lights()
{
  return {
    { { -0.45, 0.55, 0.70 }, 0.70, 1.0 },  // key: upper left, in front
    { { 0.60, -0.25, 0.75 }, 0.30, 0.25 }, // fill: lower right, softer, barely glossy
    { { 0.0, 0.60, -0.80 }, 0.15, 0.0 },   // rim: from behind the top, lifts silhouettes
  };
}

} // namespace frep::imaging
