// frepkit check MODEL.hf: parse and check a model, report every diagnostic, list the objects.
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

struct CheckOptions
{
  UserInputs user; ///< --library, --shape
  std::string model;
  std::optional<std::string> object;
};

/// Registers the subcommand; `run` is set to the function that executes it.
CLI::App* add_check_command(CLI::App& app, CheckOptions& options);

/// Returns the process exit code (0 ok, 1 the model has errors).
int run_check(const CheckOptions& options);

} // namespace frepkit
