// frepkit: FRepKit's command-line tool. Exit codes: 0 ok, 1 user error, 2 internal error.
#include "check_command.h"
#include "eval_command.h"
#include "user_error.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

int main(int argc, char** argv)
{
  CLI::App app{ "frepkit: function-representation (FRep) modelling in any number of dimensions. "
                "Models are HyperFun programs (value-compatible with the original interpreter)." };
  app.set_version_flag("--version", std::string("frepkit ") + FREPKIT_VERSION);
  app.require_subcommand(1);

  frepkit::CheckOptions check_options;
  frepkit::EvalOptions eval_options;
  CLI::App* check = frepkit::add_check_command(app, check_options);
  CLI::App* eval = frepkit::add_eval_command(app, eval_options);

  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    const int code = app.exit(e);
    return code == 0 ? 0 : 1;
  }

  try
  {
    if (check->parsed())
    {
      return frepkit::run_check(check_options);
    }
    if (eval->parsed())
    {
      return frepkit::run_eval(eval_options);
    }
  }
  catch (const frepkit::UserError& e)
  {
    std::string message = e.what();
    if (!message.empty() && message.back() == '\n')
    {
      message.pop_back();
    }
    std::cerr << "frepkit: " << message << '\n';
    return 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "frepkit: internal error: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
