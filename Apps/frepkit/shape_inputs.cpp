// --shape name=FILE: a mesh (signed distance, or unsigned with --unsigned-distance) or a volume
// (.vti, iso value after a colon: name=ct.vti:0.5) registered as the user function name(x).
#include "user_inputs.h"

#include "Shapes/mesh_readers.h"
#include "Shapes/shape_functions.h"
#include "shape_readers/vtk_shape_reader.h"
#include "user_error.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace frepkit
{
namespace
{

bool ends_with(std::string s, const std::string& suffix)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

void add_shape_input(const std::string& spec, bool unsigned_distance,
  frep::UserFunctionRegistry& registry)
{
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
  {
    throw UserError("--shape " + spec + ": expected name=FILE (e.g. bunny=bunny.stl)");
  }
  const std::string name = spec.substr(0, eq);
  std::string path = spec.substr(eq + 1);
  const std::string label = "--shape " + name + ": ";
  double iso = 0;
  if (const auto colon = path.rfind(':'); colon != std::string::npos &&
      ends_with(path.substr(0, colon), ".vti"))
  {
    const std::string number = path.substr(colon + 1);
    const auto r = std::from_chars(number.data(), number.data() + number.size(), iso);
    if (r.ec != std::errc() || r.ptr != number.data() + number.size())
    {
      throw UserError(label + "the iso value '" + number + "' is not a number");
    }
    path = path.substr(0, colon);
  }
  std::string added;
  if (ends_with(path, ".vti"))
  {
    frep::shapes::VolumeGrid grid;
    if (std::string e = read_vti_volume(path, grid); !e.empty())
    {
      throw UserError(label + e);
    }
    auto field = frep::shapes::VolumeField::build(std::move(grid), iso);
    if (!field.field)
    {
      throw UserError(label + path + ": " + field.error);
    }
    added = registry.add(frep::shapes::volume_function(name, field.field));
  }
  else
  {
    frep::shapes::TriangleMesh mesh;
    if (ends_with(path, ".vtp"))
    {
      if (std::string e = read_vtp_mesh(path, mesh); !e.empty())
      {
        throw UserError(label + e);
      }
    }
    else if (frep::shapes::is_mesh_file(path))
    {
      frep::shapes::MeshReadResult r = frep::shapes::read_mesh_file(path);
      if (!r.ok())
      {
        throw UserError(label + r.error);
      }
      mesh = std::move(r.mesh);
    }
    else
    {
      throw UserError(label + path + ": not a shape file (.stl, .obj, .ply, .vtp, .vti)");
    }
    auto distance = frep::shapes::MeshDistance::build(std::move(mesh), !unsigned_distance);
    if (!distance.distance)
    {
      throw UserError(label + path + ": " + distance.error);
    }
    added = registry.add(frep::shapes::mesh_function(name, distance.distance));
  }
  if (!added.empty())
  {
    throw UserError(label + added);
  }
}

} // namespace frepkit
