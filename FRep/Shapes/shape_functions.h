// External shapes as user functions name(x) over a 3-item array: a mesh's distance, a volume's
// field, or any point function (a VTK implicit function, through Sources/). Each brings the
// interval and gradient forms it can, so meshing culls and normals are exact.
#pragma once

#include "Language/user_functions.h"
#include "Shapes/mesh_distance.h"
#include "Shapes/volume_field.h"

#include <functional>
#include <memory>
#include <string>

namespace frep::shapes
{

/// name(x): the mesh's F (signed or not, see MeshDistance), with its enclosure and gradient.
UserFunction mesh_function(const std::string& name, std::shared_ptr<const MeshDistance> mesh);

/// name(x): the volume's F (see VolumeField), with its enclosure and gradient.
UserFunction volume_function(const std::string& name, std::shared_ptr<const VolumeField> volume);

/// name(x) from a point function (which must be thread-safe); no enclosure (the whole line),
/// gradient by differences.
UserFunction point_function(const std::string& name,
  std::function<double(const std::array<double, 3>&)> f);

/// A one-object program "name_model(x[3], a[1]) { name_model = name(x); }" that makes any of these a
/// model of its own (what vtkPolyDataToFRep and the others output).
std::string wrapper_program(const std::string& name);

} // namespace frep::shapes
