#include "user_inputs.h"

#include "shape_files.h"
#include "user_error.h"

#include <CLI/CLI.hpp>

namespace frepkit
{

void add_user_input_options(CLI::App* command, UserInputs& inputs)
{
  command->add_option("--library", inputs.libraries,
    "A library the model may call: a HyperFun file (.hf) whose objects it calls like its own, "
    "or a shared object implementing frepkit_user.h whose functions it calls by name; "
    "repeatable")
    ->allow_extra_args(false);
  command->add_option("--shape", inputs.shapes,
    "name=FILE: a closed triangle mesh (.stl, .obj, .ply, .vtp: signed distance, >= 0 inside) "
    "or a volume (.vti[:ISO]: its scalars minus ISO) that the model calls as name(x); "
    "repeatable")
    ->allow_extra_args(false);
  command->add_flag("--unsigned-distance", inputs.unsigned_distance,
    "Accept open or non-manifold meshes for --shape: their F is minus the unsigned distance");
}

std::shared_ptr<const frep::UserFunctionRegistry> load_shape_inputs(const UserInputs& inputs)
{
  if (inputs.shapes.empty())
  {
    return nullptr;
  }
  auto registry = std::make_shared<frep::UserFunctionRegistry>();
  if (std::string e = add_user_inputs({}, inputs.shapes, inputs.unsigned_distance, *registry);
      !e.empty())
  {
    throw UserError(e);
  }
  return registry;
}

} // namespace frepkit
