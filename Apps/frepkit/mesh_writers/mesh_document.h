// What a mesh writer writes: the extracted surface plus what the formats around it need (a name,
// the box for a viewpoint, colours per point). Writers only read it.
#pragma once

#include "Mesh/surface.h"

#include <array>
#include <string>
#include <vector>

namespace frepkit
{

/// An RGB colour, components in [0, 1].
using Rgb = std::array<float, 3>;

struct MeshDocument
{
  const frep::mesh::Surface* surface = nullptr;
  /// One colour per point (frep::attribute_colours, Compiler/attribute_rgb.h), or empty: the
  /// formats then carry none.
  std::vector<Rgb> colours;
  std::string name = "frep"; ///< object name: VRML DEF, STL solid name, PLY/OBJ comment
  std::string source;        ///< the model file, for comments
  std::array<double, 3> box_lo{ -10, -10, -10 }; ///< the sampled box (viewpoint, lights)
  std::array<double, 3> box_hi{ 10, 10, 10 };
  /// Colour of uncoloured faces (VRML diffuseColor, POV texture): hfp's default 50,200,80.
  Rgb face_colour{ 50.0f / 255.0f, 200.0f / 255.0f, 80.0f / 255.0f };
  bool normals = true; ///< write the per-point normals when the surface has them

  /// The box of the grid's first three axes (fewer: the rest stay -10..10).
  void set_box(const frep::GridSpec& grid)
  {
    for (std::size_t k = 0; k < 3 && k < grid.axes.size(); ++k)
    {
      box_lo[k] = grid.axes[k].lo;
      box_hi[k] = grid.axes[k].hi;
    }
  }

  bool has_normals() const { return normals && !surface->normals.empty(); }
  bool has_colours() const { return !colours.empty(); }
};

} // namespace frepkit
