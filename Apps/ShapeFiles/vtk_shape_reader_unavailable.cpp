// The VTK-free build: .vtp and .vti shapes need VTK (STL, OBJ and PLY do not).
#include "vtk_shape_reader.h"

namespace frepkit
{

bool vtk_shapes_available()
{
  return false;
}

std::string read_vtp_mesh(const std::string& path, frep::shapes::TriangleMesh&)
{
  return path + ": .vtp shapes need a frepkit built with VTK (FREPKIT_ENABLE_VTK=ON); this one "
                "reads .stl, .obj and .ply";
}

std::string read_vti_volume(const std::string& path, frep::shapes::VolumeGrid&)
{
  return path + ": .vti volumes need a frepkit built with VTK (FREPKIT_ENABLE_VTK=ON)";
}

} // namespace frepkit
