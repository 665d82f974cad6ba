// Triangle meshes from files without VTK: STL (binary and ASCII), Wavefront OBJ and PLY
// (ASCII, binary little and big endian). STL has no shared points: equal coordinates are merged
// so that edges can be counted. Errors come back as values; no input crashes or throws.
#pragma once

#include "Shapes/triangle_mesh.h"

#include <string>
#include <string_view>

namespace frep::shapes
{

struct MeshReadResult
{
  TriangleMesh mesh;
  std::string error; ///< "FILE: ..." when the file cannot be read
  bool ok() const { return error.empty(); }
};

/// By extension (.stl, .obj, .ply, any case).
MeshReadResult read_mesh_file(const std::string& path);

MeshReadResult read_stl(std::string_view bytes);
MeshReadResult read_obj(std::string_view text);
MeshReadResult read_ply(std::string_view bytes);

/// Whether the extension is one read_mesh_file reads.
bool is_mesh_file(const std::string& path);

} // namespace frep::shapes
