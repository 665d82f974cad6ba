// frepkit sweep PROFILE.hf --path X,Y,Z;X,Y,Z;...: the profile moved along the path as one
// HyperFun object of x[4] (Project/sweep_text.h), written to a file; `frepkit mesh OUT --library
// PROFILE.hf --project x4=0:1` then meshes the volume it sweeps.
#pragma once

#include "user_inputs.h"

#include <optional>
#include <string>

namespace CLI
{
class App;
}

namespace frepkit
{

struct SweepOptions
{
  UserInputs user; ///< the profile's own --library and --shape
  std::string profile;
  std::optional<std::string> object;
  std::string path;                 ///< "x,y,z;x,y,z;..."
  std::string curve = "polyline";   ///< polyline, catmull-rom
  std::string orient = "fixed";     ///< fixed, tangent
  bool closed = false;
  std::string name = "sweep";
  std::string output = "-";
};

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& options);

int run_sweep(const SweepOptions& options);

} // namespace frepkit
