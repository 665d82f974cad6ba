// What a model may call besides the library: user libraries (--library FILE, frepkit_user.h)
// and external shapes (--shape name=FILE, a mesh or a volume as a function name(x)). Shared by
// the subcommands that read models (check, eval, mesh, slice, map).
#pragma once

#include "Language/user_functions.h"

#include <memory>
#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace frepkit
{

struct UserInputs
{
  /// --library FILE (repeatable): HyperFun library files (.hf) and shared libraries
  std::vector<std::string> libraries;
  std::vector<std::string> shapes;    ///< --shape name=FILE (repeatable)
  bool unsigned_distance = false;     ///< --unsigned-distance: open meshes allowed
};

/// Adds --library, --shape and --unsigned-distance to a subcommand.
void add_user_input_options(CLI::App* command, UserInputs& inputs);

/// The registry of the --shape functions, or null when none is given (the --library files are
/// loaded by the engine's load_model, frep::LoadOptions::libraries). Throws UserError naming the
/// shape file when one cannot be read.
std::shared_ptr<const frep::UserFunctionRegistry> load_shape_inputs(const UserInputs& inputs);

} // namespace frepkit
