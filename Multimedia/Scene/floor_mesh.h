// The floor scene (floor_scene.h) for meshed pictures: the checkerboard, the path and the
// section's shadow as triangle meshes for the mesh renderer, so that the paper's Fig. 8 can be
// drawn by either method. The shadow is the section's mesh flattened onto the floor along the
// key light (a planar projected shadow: exact for a flat floor, as the ray caster's is).
#pragma once

#include "Raycast/raycast.h"
#include "Imaging/camera.h"
#include "Render/mesh_renderer.h"

#include "Mesh/surface.h"

#include <cstdint>
#include <vector>

namespace frep::mapping
{

/// Triangles with their own storage, to hand to render::MeshInput.
struct OwnedMesh
{
  std::vector<double> points;
  std::vector<std::uint32_t> triangles;
  std::vector<float> normals;
  std::vector<float> colours; ///< linear RGB per point (empty: one colour)
  render::MeshInput input(const std::array<float, 3>& colour, double opacity = 1.0) const;
};

/// The board's squares (flat colours) and the path as a ribbon just above it.
OwnedMesh floor_board(const raycast::Floor& floor);

/// `surface` (world space) flattened onto the floor along the key light of `style` seen from
/// `camera`, a hair above the board. Empty when the light does not come from above.
OwnedMesh floor_shadow(const raycast::Floor& floor,
  const mesh::Surface& surface,
  const imaging::Camera& camera,
  const imaging::RenderStyle& style);

} // namespace frep::mapping
