// frepkit slice MODEL.hf --fix x4=0.5 -o OUT: a cross-section of an n-D model. The coordinates
// not fixed (or the --free list, in that order) drive the output's axes: 2 free give an image
// (.png), a sampled image (.vti) or contour lines (.vtp); 3 free give a mesh (any format of
// `frepkit mesh`) or a sampled volume (.vti).
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

struct SliceOptions
{
  UserInputs user; ///< --library, --shape
  ProjectionInput projection; ///< --project, --project-tolerance
  std::string model;
  std::string output;
  std::optional<std::string> object;
  std::vector<double> parameters;
  std::vector<std::string> fix;
  std::vector<std::string> free;
  std::vector<std::string> box; ///< --box entries (parse_box)
  std::vector<std::int64_t> grid;
  double iso = 0;
  bool ascii = false;
  bool no_cap = false;
  bool no_normals = false;
  int threads = 0;
  bool quiet = false;
};

CLI::App* add_slice_command(CLI::App& app, SliceOptions& options);

int run_slice(const SliceOptions& options);

} // namespace frepkit
