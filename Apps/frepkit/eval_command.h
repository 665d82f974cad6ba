// frepkit eval MODEL.hf: evaluate a model at points read from a file or stdin.
#pragma once

#include "user_inputs.h"
#include <optional>
#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace frepkit
{

struct EvalOptions
{
  UserInputs user; ///< --library, --shape
  std::string model;
  std::optional<std::string> object;
  std::vector<double> parameters;
  std::string points = "-";
  std::string output = "-";
  bool attributes = false;
  bool hfp_errors = false;
  bool sequence = false;
  bool interpreter = false;
  int threads = 0;
};

CLI::App* add_eval_command(CLI::App& app, EvalOptions& options);

/// Returns the process exit code (0 ok; user errors are thrown as UserError).
int run_eval(const EvalOptions& options);

} // namespace frepkit
