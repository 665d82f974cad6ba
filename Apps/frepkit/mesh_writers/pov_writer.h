// POV-Ray scene (.pov, hfp -pov): hfp's camera and eight lights at the box corners, and the mesh
// as one mesh2 object (shared vertices, per-point normals; with colours a texture per point,
// interpolated over each triangle, where hfp gave each triangle the average of its corners).
// Uncoloured meshes use the face colour (hfp: a fixed green close to its default face colour).
#pragma once

#include "mesh_document.h"

#include <ostream>

namespace frepkit
{

void write_pov(const MeshDocument& mesh, std::ostream& out);

} // namespace frepkit
