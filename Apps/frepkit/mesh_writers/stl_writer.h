// STL, binary (the default for .stl: 84 + 50 bytes per triangle, little-endian floats) and ASCII.
// Facet normals come from the triangles' winding, which is outward.
#pragma once

#include "mesh_document.h"

#include <ostream>

namespace frepkit
{

void write_stl_binary(const MeshDocument& mesh, std::ostream& out);
void write_stl_ascii(const MeshDocument& mesh, std::ostream& out);

} // namespace frepkit
