// frepkit: FRepKit's command-line tool. Exit codes: 0 ok, 1 user error, 2 internal error,
// 128 + the signal (130 SIGINT, 143 SIGTERM) when a signal stopped the run.
#include "check_command.h"
#include "eval_command.h"
#include "hfp_command.h"
#include "demo_command.h"
#include "Durable/interrupt_guard.h"
#include "Imaging/png_writer.h"
#include "map_command.h"
#include "mesh_command.h"
#include "morph_command.h"
#include "query_command.h"
#include "sweep_command.h"
#include "slice_command.h"
#include "render_command.h"
#include "user_error.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <functional>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace
{

/// " (address-space limit N MB)" when ulimit -v set one, else nothing.
std::string address_space_limit()
{
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
  {
    return {};
  }
  return " (address-space limit " + std::to_string(limit.rlim_cur >> 20) + " MB)";
}

/// A user error or an output that could not be put in place: one message, exit code 1; or, when
/// a signal caused it (ffmpeg stopped by the same Ctrl-C, a read cut short by EINTR, a commit
/// refused after the signal), the interruption it is: 128 + the signal.
int report_failure(std::string message)
{
  if (!message.empty() && message.back() == '\n')
  {
    message.pop_back();
  }
  std::cerr << "frepkit: " << message << '\n';
  if (frep::durable::InterruptGuard::interrupted())
  {
    return 128 + frep::durable::InterruptGuard::signal_number();
  }
  return 1;
}

/// Runs a command under one InterruptGuard (Support/Durable), so that a signal at any moment of
/// any subcommand, its writes included, ends in a clean exit; a UserError, OutputError or
/// PngError (a picture that cannot be encoded, or no libpng in this build) is one
/// message and exit code 1, an interruption exit code 128 + the signal, anything else exit
/// code 2. A command that finished before it noticed a signal has written everything: its exit
/// code stands.
int guarded(const std::function<int()>& command)
{
  frep::durable::InterruptGuard interrupt;
  try
  {
    return command();
  }
  catch (const frepkit::UserError& e)
  {
    return report_failure(e.what());
  }
  catch (const frep::durable::OutputError& e)
  {
    return report_failure(e.what());
  }
  catch (const frep::imaging::PngError& e)
  {
    return report_failure(e.what());
  }
  catch (const std::bad_alloc&)
  {
    // A request larger than the memory this process may use (ulimit -v, the machine's): a
    // refusal like a refused size, not a bug. The unwinding removed the temporaries.
    std::cerr << "frepkit: out of memory: the request needs more memory than this process may "
                 "use"
              << address_space_limit() << "; nothing written (try a smaller grid or size)\n";
    return 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "frepkit: internal error: " << e.what() << '\n';
    return 2;
  }
}

} // namespace

int main(int argc, char** argv)
{
  // hfp's grammar is not CLI11's (see hfp_arguments.h): everything after "hfp" goes to its own
  // parser.
  if (argc >= 2 && std::string(argv[1]) == "hfp")
  {
    const std::vector<std::string> args(argv + 2, argv + argc);
    return guarded([&args] { return frepkit::run_hfp(args); });
  }

  CLI::App app{ "frepkit: function-representation (FRep) modelling in any number of dimensions. "
                "Models are HyperFun programs (value-compatible with the original interpreter)." };
  app.set_version_flag("--version", std::string("frepkit ") + FREPKIT_VERSION);
  app.require_subcommand(1);

  frepkit::CheckOptions check_options;
  frepkit::EvalOptions eval_options;
  frepkit::MeshOptions mesh_options;
  frepkit::SliceOptions slice_options;
  CLI::App* check = frepkit::add_check_command(app, check_options);
  CLI::App* eval = frepkit::add_eval_command(app, eval_options);
  CLI::App* mesh = frepkit::add_mesh_command(app, mesh_options);
  CLI::App* slice = frepkit::add_slice_command(app, slice_options);
  frepkit::RenderOptions render_options;
  CLI::App* render = frepkit::add_render_command(app, render_options);
  frepkit::MapOptions map_options;
  CLI::App* map = frepkit::add_map_command(app, map_options);
  frepkit::DemoOptions demo_options;
  CLI::App* demo = frepkit::add_demo_command(app, demo_options);
  frepkit::MorphOptions morph_options;
  CLI::App* morph = frepkit::add_morph_command(app, morph_options);
  frepkit::QueryOptions query_options;
  CLI::App* query = frepkit::add_query_command(app, query_options);
  frepkit::SweepOptions sweep_options;
  CLI::App* sweep = frepkit::add_sweep_command(app, sweep_options);
  // Listed for --help only: main() hands "hfp" to its own parser before CLI11 runs.
  app
    .add_subcommand("hfp",
      "Drop-in replacement of the HyperFun polygonizer's command line: frepkit hfp FILE.hf "
      "[-b ..] [-g ..] [-wrl|-stl|-stlb|-pov|-cli [FILE]] ... ('frepkit hfp -h' lists the options)")
    ->allow_extras();

  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    const int code = app.exit(e);
    return code == 0 ? 0 : 1;
  }

  return guarded(
    [&]
    {
      if (check->parsed())
      {
        return frepkit::run_check(check_options);
      }
      if (eval->parsed())
      {
        return frepkit::run_eval(eval_options);
      }
      if (mesh->parsed())
      {
        return frepkit::run_mesh(mesh_options);
      }
      if (slice->parsed())
      {
        return frepkit::run_slice(slice_options);
      }
      if (render->parsed())
      {
        return frepkit::run_render(render_options);
      }
      if (map->parsed())
      {
        return frepkit::run_map(map_options);
      }
      if (demo->parsed())
      {
        return frepkit::run_demo(demo_options);
      }
      if (morph->parsed())
      {
        return frepkit::run_morph(morph_options);
      }
      if (query->parsed())
      {
        return frepkit::run_query(query_options);
      }
      if (sweep->parsed())
      {
        return frepkit::run_sweep(sweep_options);
      }
      return 0;
    });
}
