// .vtp meshes and .vti volumes for --shape: read with VTK when frepkit is built with it;
// without VTK these return an error saying so (the engine reads .stl/.obj/.ply itself).
#pragma once

#include "Shapes/triangle_mesh.h"
#include "Shapes/volume_field.h"

#include <string>

namespace frepkit
{

/// Whether this build reads .vtp and .vti.
bool vtk_shapes_available();

/// The polygons of a .vtp file as triangles (polygons fanned); empty error on success.
std::string read_vtp_mesh(const std::string& path, frep::shapes::TriangleMesh& mesh);

/// The active point scalars (first component) of a .vti file; an image without point scalars
/// is refused.
std::string read_vti_volume(const std::string& path, frep::shapes::VolumeGrid& grid);

} // namespace frepkit
