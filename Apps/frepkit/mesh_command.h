// frepkit mesh MODEL.hf -o OUT: the surface F = iso of a model as a watertight, outward-oriented
// triangle mesh in the format of OUT's extension (.stl .obj .ply .wrl .pov .vtp).
#pragma once

#include "projection_option.h"
#include "user_inputs.h"
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace frepkit
{

struct MeshOptions
{
  UserInputs user; ///< --library, --shape
  ProjectionInput projection; ///< --project, --project-tolerance
  std::string model;
  std::string output;
  std::optional<std::string> object;
  std::vector<double> parameters;
  std::vector<std::string> box; ///< --box entries (parse_box)
  std::vector<std::int64_t> grid;
  double iso = 0;
  std::optional<std::string> axes; ///< --axes (formerly --map): X,Y,Z and fixed values
  bool ascii = false;
  bool no_cap = false;
  bool no_normals = false;
  int refine = 0;
  int threads = 0;
  bool quiet = false;
};

CLI::App* add_mesh_command(CLI::App& app, MeshOptions& options);

/// Returns the process exit code (0 ok, also for an empty mesh; user errors are thrown).
int run_mesh(const MeshOptions& options);

} // namespace frepkit
