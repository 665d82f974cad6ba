// Wavefront OBJ: "v x y z" (followed by "r g b" in [0, 1] when the mesh has colours, the common
// extension MeshLab, Blender and trimesh read), "vn" per point when the mesh has normals, and
// "f a//a b//b c//c" with 1-based indices.
#pragma once

#include "mesh_document.h"

#include <ostream>

namespace frepkit
{

void write_obj(const MeshDocument& mesh, std::ostream& out);

} // namespace frepkit
