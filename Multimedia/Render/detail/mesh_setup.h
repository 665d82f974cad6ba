// Internal to the mesh renderer: a mesh's triangles made ready for rasterisation — in camera
// space, clipped, projected to the supersampled picture and snapped to fixed point.
#pragma once

#include "Imaging/camera.h"
#include "Render/mesh_renderer.h"

#include <cstdint>
#include <string>
#include <vector>

namespace frep::render::detail
{

/// Sub-sample precision of the rasteriser: 8 bits (1/256 sample). Vertices are snapped to it,
/// and the edge functions are exact integers on the snapped positions (watertight).
constexpr int kSubpixelBits = 8;
constexpr std::int64_t kSubpixel = std::int64_t{ 1 } << kSubpixelBits;

/// Camera space here: x right, y up, z forward (depth, > 0 in front of the eye).
struct Projection
{
  imaging::CameraFrame frame;
  imaging::Vec3 eye;
  bool orthographic = false;
  double focal = 1.0; ///< samples per unit of x/z (perspective) or of x (orthographic)
  double cx = 0.0;    ///< the view centre, in samples
  double cy = 0.0;
  double near = 0.01;
  int width = 0; ///< samples
  int height = 0;

  Projection(const imaging::Camera& camera, int sample_width, int sample_height);
};

struct SetupVertex
{
  float weight; ///< perspective weight: 1 / depth (perspective) or 1 (orthographic)
  float key;    ///< depth-test key, linear in screen space, larger = nearer
  float n[3];   ///< camera-space normal (not necessarily unit; may be zero)
  float c[3];   ///< linear colour
};

struct SetupTriangle
{
  std::uint32_t v[3]; ///< vertex ids, ordered so that the fixed-point area is positive
  std::int32_t x[3];  ///< snapped positions, 1/kSubpixel samples
  std::int32_t y[3];
  std::int32_t y_min; ///< sample rows possibly covered (clamped to the picture)
  std::int32_t y_max;
  float facing[3]; ///< unit geometric normal towards the eye (shading fallback)
  bool back;       ///< the triangle's outside faces away from the eye
};

struct MeshSetup
{
  std::vector<SetupVertex> vertices;
  std::vector<SetupTriangle> triangles;
  double centre_depth = 0.0; ///< of the points' bounding box centre (layer ordering)
};

/// Transform, light-independent attributes, clipping and projection. Fills `report` (counts,
/// error); on error the setup is empty.
MeshSetup setup_mesh(const MeshInput& mesh,
  const Projection& projection,
  int threads,
  RenderReport& report);

} // namespace frep::render::detail
