// Internal: the colour of a ray-cast sample — Blinn-Phong under the mesh renderer's camera-fixed
// light kit (Imaging/lighting.h: Light, RenderStyle), so that a ray-cast and a meshed
// picture of the same shape look alike — and the checkerboard floor's pattern.
#pragma once

#include "Raycast/raycast.h"
#include "Raycast/detail/view_rays.h"

#include <array>
#include <vector>

namespace frep::raycast::detail
{

struct WorldLight
{
  Vec3 l{};              ///< towards the light, world, unit
  float diffuse = 0.0F;  ///< intensity
  float specular = 0.0F; ///< intensity * light specular * style specular
};

struct LightKit
{
  std::vector<WorldLight> lights; ///< the first is the key light (shadows)
  float ambient = 0.25F;
  float shininess = 40.0F;
};

/// The style's lights in world space for the camera frame of `view`.
LightKit world_lights(const imaging::RenderStyle& style, const ViewRays& view);

/// Lit colour of a surface point: `n` the unit outward normal, `v` the unit direction towards
/// the eye, `key_light` the fraction of the key light that reaches the point (shadows).
std::array<float, 3> shade(const LightKit& kit,
  const std::array<float, 3>& colour,
  const Vec3& n,
  const Vec3& v,
  float key_light,
  bool specular = true);

/// The floor's path binned by square, so that a sample looks only at the segments near it.
struct FloorIndex
{
  explicit FloorIndex(const Floor& floor);
  const Floor& floor;
  std::vector<std::vector<std::size_t>> segments; ///< per square (row-major): first points
};

/// The floor's colour at world (x, y), or false where the floor is not drawn.
bool floor_colour(const FloorIndex& index, double x, double y, std::array<float, 3>& colour);

} // namespace frep::raycast::detail
