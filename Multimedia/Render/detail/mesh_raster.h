// Internal to the mesh renderer: the visibility pass (which triangle is nearest at each sample)
// and the shading of a visible sample.
#pragma once

#include "Render/detail/mesh_setup.h"

#include <cstdint>
#include <vector>

namespace frep::render::detail
{

constexpr std::uint32_t kNoTriangle = 0xFFFFFFFFU;

/// Per sample: the nearest depth key so far and its triangle (an index into the setup's
/// triangles), kNoTriangle where none.
struct Visibility
{
  int width = 0;
  int height = 0;
  std::vector<float> key;
  std::vector<std::uint32_t> triangle;

  Visibility() = default;
  Visibility(int w, int h);
};

/// Rasterise setup.triangles[first, end) into `visibility` (nearer keys win; ties keep what is
/// there, so earlier triangles win). Deterministic for any thread count.
void rasterise(Visibility& visibility, const MeshSetup& setup, std::size_t first, int threads);

/// A light in the internal camera space (z forward), unit direction towards the light.
struct ShadingLight
{
  float l[3];
  float diffuse;
  float specular;
};

struct Shading
{
  std::vector<ShadingLight> lights;
  float ambient = 0.25F;
  float shininess = 40.0F;
  float back_face_factor = 0.8F;
  bool integer_shininess = true;

  Shading(const imaging::RenderStyle& style);
};

/// The shaded linear colour (clamped to [0, 1]) of triangle t at sample (sx, sy) (its centre).
void shade_sample(const MeshSetup& setup,
  std::uint32_t t,
  int sx,
  int sy,
  const Projection& pr,
  const Shading& shading,
  float rgb[3]);

} // namespace frep::render::detail
