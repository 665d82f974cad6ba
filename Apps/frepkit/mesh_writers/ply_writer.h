// PLY, binary little-endian: vertex x y z (float), nx ny nz (float) when the mesh has normals,
// red green blue (uchar) when it has colours; face "list uchar int vertex_indices".
#pragma once

#include "mesh_document.h"

#include <ostream>

namespace frepkit
{

void write_ply(const MeshDocument& mesh, std::ostream& out);

} // namespace frepkit
