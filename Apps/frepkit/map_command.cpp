#include "map_command.h"

#include "Durable/interrupt_guard.h"
#include "model_loading.h"
#include "progress_bar.h"
#include "shape_files.h"
#include "user_error.h"

#include "Mapping/mapping_json.h"
#include "Production/production.h"

#include <algorithm>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace frepkit
{
namespace
{

namespace mapping = frep::mapping;

std::string read_file(const std::string& path, const char* what)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw UserError(std::string("cannot read the ") + what + " " + path);
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The mapping file, checked, with --resolution, --ghost, --topology, --frames and --method
// applied.
mapping::Spec load_spec(const MapOptions& options)
{
  const mapping::LoadResult loaded =
    mapping::load_mapping(read_file(options.mapping, "mapping file"));
  if (!loaded.errors.empty())
  {
    for (const auto& e : loaded.errors)
    {
      std::cerr << options.mapping << ": " << (e.place.empty() ? "" : e.place + ": ")
                << e.message << '\n';
    }
    throw UserError("the mapping file is not valid; nothing written");
  }
  mapping::Spec spec = loaded.spec;
  if (options.resolution)
  {
    spec.world.resolution = *options.resolution;
    if (spec.animation.ghost) // a quick run is quick for the ghost too
    {
      spec.animation.ghost->resolution = std::min(spec.animation.ghost->resolution, *options.resolution);
    }
    if (spec.topology) // and for the topology map
    {
      spec.topology->resolution = std::min(spec.topology->resolution, *options.resolution);
    }
  }
  if (options.topology)
  {
    if (*options.topology == 0)
      spec.topology.reset();
    else
    {
      if (!spec.topology)
        spec.topology = mapping::TopologySettings{};
      spec.topology->resolution = *options.topology;
    }
  }
  if (options.ghost)
  {
    if (*options.ghost == 0)
      spec.animation.ghost.reset();
    else
    {
      if (!spec.animation.ghost)
        spec.animation.ghost = mapping::GhostSettings{};
      spec.animation.ghost->resolution = *options.ghost;
    }
  }
  if (options.frames)
  {
    spec.animation.duration = *options.frames / spec.animation.fps;
  }
  if (options.method)
  {
    using Method = mapping::RenderSettings::Method;
    const Method method = *options.method == "raycast" ? Method::Raycast : Method::Mesh;
    spec.render.method = method;
    spec.render.frames_method = method;
  }
  return spec;
}

// The mapping, the model it names (--object, else the mapping's, else the default) and what
// identifies them.
mapping::ProductionInputs load_inputs(const MapOptions& options)
{
  mapping::ProductionInputs in;
  in.spec = load_spec(options);
  in.parameters = options.parameters.empty() ? in.spec.parameters : options.parameters;
  const std::string object = mapping::mapped_object(in.spec, options.object.value_or(""));
  in.model = frepkit::load_model(options.model,
    options.user,
    object.empty() ? std::nullopt : std::optional<std::string>(object),
    in.parameters.size())
               .model;
  in.model_key = read_file(options.model, "model") +
                 user_inputs_key(options.user.libraries, options.user.shapes,
                   options.user.unsigned_distance);
  in.model_label = options.model;
  in.mapping_label = options.mapping;
  return in;
}

void print_summary(const MapOptions& options,
  const mapping::ProductionInputs& in,
  const mapping::ProductionReport& report)
{
  if (options.quiet)
  {
    return;
  }
  std::cerr << "frepkit map: " << in.model->name() << " (" << in.model->x_dim() << "-D) -> "
            << options.output_directory << "\n";
  for (const auto& s : report.stages)
  {
    char line[256];
    std::snprintf(
      line, sizeof line, "  %-12s %7.2f s  %s\n", s.name.c_str(), s.seconds, s.detail.c_str());
    std::cerr << line;
  }
  char line[128];
  std::snprintf(line,
    sizeof line,
    "  %-12s %7.2f s  %zu triangles meshed, manifest.json\n",
    "total",
    report.seconds,
    report.triangles);
  std::cerr << line;
}

// The report as frepkit reports: the mapping's problems on standard error and a UserError, an
// interruption as one (exit code 128 + the signal), warnings unless --quiet.
void check_report(const MapOptions& options, const mapping::ProductionReport& report)
{
  using Status = mapping::ProductionReport::Status;
  if (report.status == Status::Cancelled)
  {
    throw frep::durable::Interrupted(
      "interrupted; the files written so far are kept (run again to resume)");
  }
  for (const std::string& d : report.diagnostics)
  {
    std::cerr << options.mapping << ": " << d << '\n';
  }
  if (!report.ok())
  {
    throw UserError(report.error);
  }
  for (const std::string& w : report.warnings)
  {
    if (!options.quiet)
    {
      std::cerr << "frepkit: warning: " << w << '\n';
    }
  }
  if (report.failed_samples > 0)
  {
    std::cerr << "frepkit: warning: " << report.failed_samples
              << " samples raised a run-time error (taken as outside)\n";
  }
}

} // namespace

CLI::App* add_map_command(CLI::App& app, MapOptions& o)
{
  CLI::App* cmd = app.add_subcommand("map",
    "Map an n-D model onto multimedia coordinates as a mapping file says: spreadsheet of "
    "cross-sections, path picture, animation frames, sound, movie, manifest "
    "(Documentation/mapping.md)");
  cmd->add_option("model", o.model, "HyperFun model (.hf)")->required();
  cmd->add_option("mapping", o.mapping, "mapping file (.json, Documentation/mapping-file.md)")
    ->required();
  cmd->add_option("-O,--output-directory", o.output_directory, "directory for the outputs")
    ->required();
  cmd->add_option("--object",
    o.object,
    "object to map (default: the mapping's, else my_model, "
    "else the first)");
  cmd->add_option("-a,--parameters", o.parameters, "a[1], a[2], ... (default: the mapping's)")
    ->delimiter(',');
  cmd
    ->add_option("--resolution",
      o.resolution,
      "grid samples along the longest world axis (default: the mapping's world.resolution; the "
      "ghost's animation.ghost.resolution and topology.resolution are lowered to it)")
    ->check(CLI::Range(2, 4096));
  cmd
    ->add_option("--ghost",
      o.ghost,
      "draw the animation's ghost (ghost.png: the union of every shape the path passes) at this "
      "resolution, 0 for none (default: the mapping's animation.ghost)")
    ->check(CLI::Range(0, 8192) & !CLI::Range(1, 1));
  cmd
    ->add_option("--topology",
      o.topology,
      "map the topology (pieces and genus of every cell and frame, where they change: "
      "spreadsheet-topology.png, topology.png, the manifest's topology) with sections meshed at "
      "this resolution, 0 for none (default: the mapping's topology)")
    ->check(CLI::Range(0, 8192) & !CLI::Range(1, 1));
  cmd->add_option("--frames", o.frames, "number of frames (default: duration x fps)")
    ->check(CLI::Range(1, 1000000));
  cmd
    ->add_option("--method",
      o.method,
      "draw cells and frames by 'mesh' or 'raycast' (default: the mapping's render.method)")
    ->check(CLI::IsMember({ "mesh", "raycast" }));
  cmd
    ->add_option("--only",
      o.only,
      "produce only these: spreadsheet, path, frames, audio, movie, shape, ghost, topology "
      "(default: all the mapping defines)")
    ->delimiter(',')
    ->check(CLI::IsMember(mapping::product_names()));
  cmd->add_option("--name",
    o.name,
    "stem of the movie and sound files (default: the mapping "
    "file's stem)");
  cmd->add_flag("--force", o.force, "render every frame again, even those already written");
  cmd->add_option("-j,--threads", o.threads, "worker threads (default: all cores)")
    ->check(CLI::Range(0, 1024));
  cmd->add_flag("-q,--quiet", o.quiet, "no progress bar and no summary");
  add_user_input_options(cmd, o.user);
  return cmd;
}

int run_map(const MapOptions& options)
{
  const mapping::ProductionInputs in = load_inputs(options);
  mapping::ProductionOptions run;
  run.directory = options.output_directory;
  run.stem = !options.name.empty() ? options.name
                                   : std::filesystem::path(options.mapping).stem().string();
  run.only = options.only;
  run.force = options.force;
  run.threads = options.threads;
  run.write_manifest = options.manifest_out == nullptr;
  // Ctrl-C / SIGTERM (main()'s guard) cancels: finished files are kept, temporaries removed.
  run.cancel = [] { return frep::durable::InterruptGuard::interrupted(); };
  ProgressBar bar("map", !options.quiet);
  run.progress = [&bar](double fraction)
  {
    bar.update(fraction); // produce() calls one at a time
    return true;
  };
  const mapping::ProductionReport report = mapping::produce(in, run);
  bar.finish();
  check_report(options, report);
  if (options.manifest_out != nullptr)
  {
    *options.manifest_out = report.manifest;
  }
  print_summary(options, in, report);
  return 0;
}

} // namespace frepkit
