#include "map_command.h"

#include "Durable/interrupt_guard.h"
#include "map_phases.h"

#include <CLI/CLI.hpp>

namespace frepkit
{

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
      "grid samples along the longest world axis (default: the mapping's world.resolution)")
    ->check(CLI::Range(2, 4096));
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
      "produce only these: spreadsheet, path, frames, audio, movie, shape (default: all the "
      "mapping defines)")
    ->delimiter(',')
    ->check(CLI::IsMember({ "spreadsheet", "path", "frames", "audio", "movie", "shape" }));
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
  using namespace map_run;
  const auto start = Clock::now();
  MapInputs in = load_inputs(options);
  const MapProducts products = choose_products(options, in.plan);
  const MapOutput out = prepare_output(options);
  MapRecord record;
  frame_solids(in, products, out.workers, record);
  // Ctrl-C / SIGTERM (main()'s guard) cancels: finished files are kept, temporaries removed.
  MapWorkers workers(in, products, out.workers, options.quiet);
  if (products.spreadsheet)
  {
    render_spreadsheet(in, workers, out.directory, record);
  }
  if (products.shape)
  {
    render_shape(in, workers, out.directory, record);
  }
  if (products.path)
  {
    draw_path(in, workers, out.directory, record);
  }
  FrameFiles frames;
  frames.directory = out.directory / "frames";
  if (products.frames)
  {
    render_frames(options, in, workers, frames, record);
  }
  const fs::path wav = out.directory / (out.stem + ".wav");
  // The sound and the movie are renamed into place by the Media library, which knows nothing of
  // signals: none is started after one.
  if (products.audio)
  {
    frep::durable::InterruptGuard::throw_if_interrupted();
    write_sound(in, wav, record);
  }
  if (products.movie)
  {
    frep::durable::InterruptGuard::throw_if_interrupted();
    const fs::path movie = out.directory / (out.stem + ".mp4");
    encode_movie(in, workers, frames, products.audio ? &wav : nullptr, movie, record);
  }
  workers.finish_bar();
  write_manifest(options, in, out.directory, record);
  print_summary(options, in, out.directory, record, workers, start);
  return 0;
}

} // namespace frepkit
