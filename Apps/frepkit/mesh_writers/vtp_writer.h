// VTK XML PolyData (.vtp) through VTK's vtkXMLPolyDataWriter: triangles (a 3-D surface) or line
// segments (a 2-D contour), point arrays "Normals" (when present), "s1".."sN" (the model's
// attributes), "Colors" (uchar RGB, when the mesh has colours). Builds without VTK
// (FREPKIT_ENABLE_VTK off) throw a UserError saying the format is not available.
#pragma once

#include "mesh_document.h"

#include <ostream>

namespace frepkit
{

void write_vtp(const MeshDocument& mesh, std::ostream& out);

} // namespace frepkit
