// The --shape name=FILE[:ISO] of both applications: a mesh (signed distance, or unsigned when
// asked) or a volume (.vti, iso value after a colon: name=ct.vti:0.5) as the function name(x).
#include "shape_files.h"

#include "Language/user_library.h"
#include "Shapes/mesh_readers.h"
#include "Shapes/shape_functions.h"
#include "vtk_shape_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <iterator>

namespace frepkit
{
namespace
{

bool ends_with(std::string s, const std::string& suffix)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// The bytes of a file, or "" when it cannot be read.
std::string bytes_of(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return in ? std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>())
            : std::string();
}

/// The file of a shape spec name=FILE[:ISO] (the ISO suffix is part of the spec, keyed anyway).
std::string shape_file_bytes(const std::string& spec)
{
  const std::size_t eq = spec.find('=');
  const std::string file = eq == std::string::npos ? spec : spec.substr(eq + 1);
  std::string bytes = bytes_of(file);
  if (const std::size_t colon = file.rfind(':'); bytes.empty() && colon != std::string::npos)
  {
    bytes = bytes_of(file.substr(0, colon));
  }
  return bytes;
}

} // namespace

std::string user_inputs_key(const std::vector<std::string>& libraries,
  const std::vector<std::string>& shapes, bool unsigned_distance)
{
  std::string key;
  for (const std::string& library : libraries)
  {
    key += '\0' + library + '\0' + bytes_of(library);
  }
  for (const std::string& shape : shapes)
  {
    key += '\0' + shape + '\0' + shape_file_bytes(shape);
  }
  key += '\0';
  key += unsigned_distance ? "unsigned" : "signed";
  return key;
}

std::string add_shape_file(
  const std::string& spec, bool unsigned_distance, frep::UserFunctionRegistry& registry)
{
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
  {
    return spec + ": expected name=FILE (e.g. bunny=bunny.stl)";
  }
  const std::string name = spec.substr(0, eq);
  std::string path = spec.substr(eq + 1);
  const std::string label = name + ": ";
  double iso = 0;
  if (const auto colon = path.rfind(':'); colon != std::string::npos &&
      ends_with(path.substr(0, colon), ".vti"))
  {
    const std::string number = path.substr(colon + 1);
    const auto r = std::from_chars(number.data(), number.data() + number.size(), iso);
    if (r.ec != std::errc() || r.ptr != number.data() + number.size())
    {
      return label + "the iso value '" + number + "' is not a number";
    }
    path = path.substr(0, colon);
  }
  std::string added;
  if (ends_with(path, ".vti"))
  {
    frep::shapes::VolumeGrid grid;
    if (std::string e = read_vti_volume(path, grid); !e.empty())
    {
      return label + e;
    }
    auto field = frep::shapes::VolumeField::build(std::move(grid), iso);
    if (!field.field)
    {
      return label + path + ": " + field.error;
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
        return label + e;
      }
    }
    else if (frep::shapes::is_mesh_file(path))
    {
      frep::shapes::MeshReadResult r = frep::shapes::read_mesh_file(path);
      if (!r.ok())
      {
        return label + r.error;
      }
      mesh = std::move(r.mesh);
    }
    else
    {
      return label + path + ": not a shape file (.stl, .obj, .ply, .vtp, .vti)";
    }
    auto distance = frep::shapes::MeshDistance::build(std::move(mesh), !unsigned_distance);
    if (!distance.distance)
    {
      return label + path + ": " + distance.error;
    }
    added = registry.add(frep::shapes::mesh_function(name, distance.distance));
  }
  if (!added.empty())
  {
    return label + added;
  }
  return {};
}

std::string add_user_inputs(const std::vector<std::string>& libraries,
  const std::vector<std::string>& shapes, bool unsigned_distance,
  frep::UserFunctionRegistry& registry)
{
  for (const std::string& path : libraries)
  {
    if (const frep::UserLibraryResult r = frep::load_user_library(path, registry); !r.ok())
    {
      return r.error;
    }
  }
  for (const std::string& spec : shapes)
  {
    if (std::string e = add_shape_file(spec, unsigned_distance, registry); !e.empty())
    {
      return "--shape " + e;
    }
  }
  return {};
}

} // namespace frepkit
