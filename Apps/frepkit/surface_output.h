// The common end of `mesh` and a 3-D `slice`: extract the surface of a tape, write it to a file in
// a mesh format (atomically), print the warnings and the report.
#pragma once

#include "Mesh/surface.h"
#include "mesh_writers/mesh_format.h"

#include <chrono>
#include <memory>
#include <string>

namespace frepkit
{

struct SurfaceJob
{
  std::shared_ptr<const frep::Tape> tape; ///< 3 inputs
  frep::GridSpec grid;                    ///< 3 axes
  frep::mesh::ExtractOptions extract; ///< normals/attributes are decided here
  MeshFormat format = MeshFormat::Stl;
  bool ascii = false;
  bool normals = true;
  bool colours = false;    ///< colours from s[1..3]
  bool attributes = false; ///< the model sets s[] (arrays s1.. in .vtp)
  bool quiet = false;
  std::string output;
  std::string name;   ///< object name
  std::string source; ///< model file
  /// When the command started (the report's time includes reading and compiling the model).
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
};

/// Returns the exit code (0; an empty mesh is written with a warning). Throws UserError.
int write_surface_file(SurfaceJob job);

} // namespace frepkit
