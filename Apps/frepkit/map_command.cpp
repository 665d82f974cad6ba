#include "map_command.h"

#include "atomic_output.h"
#include "interrupt_guard.h"
#include "model_loading.h"
#include "progress_bar.h"
#include "section_writers/png_writer.h"
#include "user_error.h"

#include "Plan/mapping_json.h"
#include "Plan/mapping_plan.h"
#include "Media/movie_encoder.h"
#include "Scene/pictures.h"
#include "Scene/section_mesh.h"
#include "Media/tone_synthesis.h"
#include "Media/wav_writer.h"

#include "Eval/thread_pool.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace frepkit
{
namespace
{

using Clock = std::chrono::steady_clock;
namespace mapping = frep::mapping;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

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

void write_png_file(const fs::path& path, const frep::render::Image& image)
{
  AtomicOutput out(path.string());
  write_png(out.stream(), image.width, image.height, frep::render::to_rgb8(image));
  out.commit();
}

void write_text_file(const fs::path& path, const std::string& text)
{
  AtomicOutput out(path.string());
  out.stream() << text;
  out.commit();
}

// What the frames depend on: a frame on disk is reused only when the model, the mapping and
// the overrides are the ones it was rendered with.
std::string fingerprint(const std::string& model_text,
  const std::string& mapping_text,
  const MapOptions& options)
{
  std::ostringstream key;
  key << model_text << '\0' << mapping_text << '\0' << options.object.value_or("") << '\0'
      << options.resolution.value_or(0) << '\0' << options.frames.value_or(0) << '\0';
  for (double a : options.parameters)
  {
    key << a << ',';
  }
  char hex[32];
  std::snprintf(hex, sizeof hex, "%016zx", std::hash<std::string>{}(key.str()));
  return hex;
}

// Runs body(i, worker) for i in [0, count) on `workers` threads; the first exception (or an
// interrupt) stops the others and is rethrown.
void parallel_samples(std::size_t count,
  int workers,
  const std::function<void(std::size_t, int)>& body)
{
  std::atomic<std::size_t> next{ 0 };
  std::atomic<bool> failed{ false };
  std::exception_ptr error;
  std::mutex error_mutex;
  auto run = [&](int worker)
  {
    for (;;)
    {
      const std::size_t i = next.fetch_add(1);
      if (i >= count || failed || InterruptGuard::interrupted())
      {
        return;
      }
      try
      {
        body(i, worker);
      }
      catch (...)
      {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error)
        {
          error = std::current_exception();
        }
        failed = true;
      }
    }
  };
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w)
  {
    threads.emplace_back(run, w);
  }
  run(0);
  for (auto& t : threads)
  {
    t.join();
  }
  if (error)
  {
    std::rethrow_exception(error);
  }
  if (InterruptGuard::interrupted())
  {
    throw UserError("interrupted; the files written so far are kept (run again to resume)");
  }
}

nlohmann::json sample_json(const mapping::Sample& s, const std::vector<std::string>& names)
{
  nlohmann::json values = nlohmann::json::object();
  for (std::size_t i = 0; i < s.values.size() && i < names.size(); ++i)
  {
    if (!std::isnan(s.values[i]))
    {
      values[names[i]] = s.values[i];
    }
  }
  nlohmann::json j{ { "label", s.label }, { "values", values } };
  return j;
}

struct Stage
{
  std::string name;
  double seconds = 0;
  std::string detail;
};

// Where a stage's time goes, summed over the workers (thread seconds, not wall time).
struct Ledger
{
  std::mutex mutex;
  double meshing = 0, rendering = 0, writing = 0;
  void add(double mesh, double render, double write)
  {
    std::lock_guard<std::mutex> lock(mutex);
    meshing += mesh;
    rendering += render;
    writing += write;
  }
  std::string text()
  {
    char line[160];
    std::snprintf(line,
      sizeof line,
      "; worker time: meshing %.1f s, drawing %.1f s, PNG %.1f s",
      meshing,
      rendering,
      writing);
    return line;
  }
};

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
      "grid samples along the longest world axis (default: the mapping's world.resolution)")
    ->check(CLI::Range(2, 4096));
  cmd->add_option("--frames", o.frames, "number of frames (default: duration x fps)")
    ->check(CLI::Range(1, 1000000));
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
  return cmd;
}

int run_map(const MapOptions& options)
{
  const auto start = Clock::now();
  std::vector<Stage> stages;

  // 1. The mapping and the model; every problem reported before anything is written.
  const std::string mapping_text = read_file(options.mapping, "mapping file");
  mapping::LoadResult loaded = mapping::load_mapping(mapping_text);
  if (!loaded.errors.empty())
  {
    for (const auto& e : loaded.errors)
    {
      std::cerr << options.mapping << ": " << (e.place.empty() ? "" : e.place + ": ") << e.message
                << '\n';
    }
    throw UserError("the mapping file is not valid; nothing written");
  }
  mapping::Spec spec = loaded.spec;
  if (options.resolution)
  {
    spec.world.resolution = *options.resolution;
  }
  if (options.frames)
  {
    spec.animation.duration = *options.frames / spec.animation.fps;
  }

  const LoadedProgram program = load_program(options.model);
  require_parsed(program);
  std::optional<std::string> object_name = options.object;
  if (!object_name && !spec.object.empty())
  {
    object_name = spec.object;
  }
  const int object_index = choose_object(program, object_name);
  const std::shared_ptr<const frep::Model> model = compile_object(program, object_index);
  const std::vector<double> parameters =
    options.parameters.empty() ? spec.parameters : options.parameters;
  warn_extra_parameters(program.program->objects[object_index], parameters.size());

  mapping::ModelCoordinates coordinates;
  for (int i = 0; i < model->x_dim(); ++i)
  {
    coordinates.names.push_back("x" + std::to_string(i + 1));
    coordinates.intervals.push_back({ -10.0, 10.0 }); // hfp's default box
  }
  const mapping::PlanResult planned = mapping::make_plan(spec, coordinates);
  if (!planned.ok())
  {
    for (const auto& e : planned.errors)
    {
      std::cerr << options.mapping << ": " << (e.place.empty() ? "" : e.place + ": ") << e.message
                << '\n';
    }
    throw UserError("the mapping does not fit " + model->name() + " (" +
                    std::to_string(model->x_dim()) + "-D); nothing written");
  }
  const mapping::Plan& plan = planned.plan;

  auto wanted = [&](const char* what)
  {
    return options.only.empty() ||
           std::find(options.only.begin(), options.only.end(), what) != options.only.end();
  };
  const bool do_spreadsheet = wanted("spreadsheet") && !plan.cells.empty();
  const bool do_path = wanted("path") && plan.dynamic_coordinates.size() == 2;
  const bool do_frames = (wanted("frames") || wanted("movie")) && !plan.frames.empty();
  const bool do_audio =
    (wanted("audio") || wanted("movie")) && !plan.frames.empty() && plan.voice_count > 0;
  const bool do_movie = wanted("movie") && !plan.frames.empty();
  // Nothing varies (world and fixed coordinates only): one picture of the shape.
  const bool do_shape = wanted("shape") && plan.cells.empty() && plan.frames.empty();
  if (!do_spreadsheet && !do_path && !do_frames && !do_audio && !do_shape)
  {
    throw UserError("the mapping has nothing of --only to produce (spreadsheet needs a "
                    "spreadsheet coordinate; path, frames, audio and movie a dynamic one; shape "
                    "neither)");
  }

  const fs::path out_dir(options.output_directory);
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec)
  {
    throw UserError("cannot create " + out_dir.string() + ": " + ec.message());
  }
  const std::string stem =
    !options.name.empty() ? options.name : fs::path(options.mapping).stem().string();
  const int workers = options.threads > 0
                        ? options.threads
                        : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  InterruptGuard interrupt;
  {
    // The PNG encoder is loaded on first use; load it before the workers race for it.
    std::ostringstream warm;
    write_png(warm, 1, 1, { 255, 255, 255 });
  }

  // One picture kit per worker: fonts are not shared between threads.
  std::vector<std::unique_ptr<mapping::PictureKit>> kits;
  for (int w = 0; w < workers; ++w)
  {
    kits.push_back(std::make_unique<mapping::PictureKit>());
  }
  if (!kits.front()->font_error.empty() && !options.quiet)
  {
    std::cerr << "frepkit: warning: " << kits.front()->font_error << "; pictures without labels\n";
  }
  // Meshing: each worker meshes its sample on one thread, so the workers use all cores on
  // independent samples (no synchronisation inside a mesh).
  std::vector<std::shared_ptr<frep::ThreadPool>> pools;
  for (int w = 0; w < workers; ++w)
  {
    pools.push_back(std::make_shared<frep::ThreadPool>(1));
  }

  ProgressBar bar("map", !options.quiet);
  const double total_units = (do_spreadsheet ? plan.cells.size() : 0) +
                             (do_frames ? plan.frames.size() : 0) +
                             (do_movie ? plan.frames.size() / 4.0 : 0) + 1.0;
  std::atomic<std::size_t> units_done{ 0 };
  std::mutex bar_mutex;
  auto advance = [&]
  {
    const std::size_t done = ++units_done;
    std::lock_guard<std::mutex> lock(bar_mutex);
    bar.update(done / total_units);
  };
  std::atomic<std::size_t> failed_samples{ 0 };
  std::atomic<std::size_t> triangles{ 0 };
  auto section_of = [&](const mapping::Sample& sample, int worker)
  {
    mapping::SectionOptions so;
    so.pool = pools[worker];
    so.progress = [](double) { return !InterruptGuard::interrupted(); };
    mapping::Section section = mapping::make_section(*model, parameters, plan, sample, so);
    if (section.cancelled || InterruptGuard::interrupted())
    {
      throw UserError("interrupted; the files written so far are kept (run again to resume)");
    }
    if (!section.error.empty())
    {
      throw UserError(sample.label + ": " + section.error);
    }
    failed_samples += section.statistics.failed_samples;
    triangles += section.surface.cell_count();
    return section;
  };

  nlohmann::json manifest{ { "model", options.model },
    { "mapping", options.mapping },
    { "object", model->name() },
    { "dimension", model->x_dim() } };
  nlohmann::json files = nlohmann::json::array();
  const std::vector<std::string>& names = coordinates.names;

  // 2. The spreadsheet: every cell with one camera, composed with labels.
  if (do_spreadsheet)
  {
    const auto t0 = Clock::now();
    const int cell_px = spec.spreadsheet.cell_size;
    const frep::render::Camera camera = mapping::plan_camera(plan, spec.render, 1.0);
    std::vector<frep::render::Image> pictures(plan.cells.size());
    Ledger cell_ledger;
    parallel_samples(plan.cells.size(),
      workers,
      [&](std::size_t i, int worker)
      {
        const auto m0 = Clock::now();
        const mapping::Section section = section_of(plan.cells[i], worker);
        const auto r0 = Clock::now();
        pictures[i] = mapping::render_sample(
          plan, section, plan.cells[i], camera, cell_px, cell_px, spec.render);
        cell_ledger.add(std::chrono::duration<double>(r0 - m0).count(), seconds_since(r0), 0.0);
        advance();
      });
    std::vector<std::array<int, 4>> rects;
    const frep::render::Image sheet =
      mapping::compose_spreadsheet(plan, pictures, spec, kits.front().get(), &rects);
    write_png_file(out_dir / "spreadsheet.png", sheet);
    nlohmann::json cells = nlohmann::json::array();
    for (std::size_t i = 0; i < plan.cells.size(); ++i)
    {
      const auto& c = plan.cells[i];
      nlohmann::json j = sample_json(c, names);
      j["cell"] = { c.cell[0], c.cell[1], c.cell[2] };
      if (i < rects.size())
      {
        j["rect"] = rects[i]; // x, y, width, height of the cell's picture in spreadsheet.png
      }
      cells.push_back(j);
    }
    files.push_back({ { "file", "spreadsheet.png" },
      { "kind", "spreadsheet" },
      { "width", sheet.width },
      { "height", sheet.height },
      { "grid", { plan.grid_shape[0], plan.grid_shape[1], plan.grid_shape[2] } },
      { "cells", cells } });
    stages.push_back({ "spreadsheet",
      seconds_since(t0),
      std::to_string(plan.cells.size()) + " cells, " + std::to_string(sheet.width) + "x" +
        std::to_string(sheet.height) + cell_ledger.text() });
  }

  // 2b. The shape alone, when nothing varies.
  if (do_shape)
  {
    const auto t0 = Clock::now();
    const frep::render::Camera camera = mapping::plan_camera(
      plan, spec.render, static_cast<double>(spec.render.width) / spec.render.height);
    const mapping::Section section = section_of(plan.still, 0);
    const frep::render::Image picture = mapping::render_sample(plan,
      section,
      plan.still,
      camera,
      spec.render.width,
      spec.render.height,
      spec.render,
      workers);
    write_png_file(out_dir / "shape.png", picture);
    files.push_back({ { "file", "shape.png" },
      { "kind", "shape" },
      { "width", picture.width },
      { "height", picture.height },
      { "triangles", section.surface.cell_count() } });
    stages.push_back(
      { "shape", seconds_since(t0), std::to_string(section.surface.cell_count()) + " triangles" });
  }

  // 3. The path of the dynamic coordinates.
  if (do_path)
  {
    const auto t0 = Clock::now();
    const frep::render::Image picture = mapping::path_picture(plan, 900, kits.front().get());
    write_png_file(out_dir / "path.png", picture);
    files.push_back(
      { { "file", "path.png" }, { "kind", "path" }, { "coordinates", plan.dynamic_coordinates } });
    stages.push_back({ "path", seconds_since(t0), std::to_string(plan.frames.size()) + " points" });
  }

  // 4. The frames, resumable.
  const std::string pattern = "frame_%05d.png";
  const fs::path frames_dir = out_dir / "frames";
  std::size_t reused = 0;
  if (do_frames)
  {
    const auto t0 = Clock::now();
    fs::create_directories(frames_dir, ec);
    if (ec)
    {
      throw UserError("cannot create " + frames_dir.string() + ": " + ec.message());
    }
    const std::string key = fingerprint(read_file(options.model, "model"), mapping_text, options);
    const fs::path key_file = frames_dir / ".fingerprint";
    bool resume = false;
    if (!options.force && fs::exists(key_file))
    {
      std::ifstream in(key_file);
      std::string old;
      std::getline(in, old);
      resume = old == key;
    }
    write_text_file(key_file, key + "\n");
    const frep::render::Camera camera = mapping::plan_camera(
      plan, spec.render, static_cast<double>(spec.render.width) / spec.render.height);
    std::atomic<std::size_t> reused_count{ 0 };
    Ledger frame_ledger;
    parallel_samples(plan.frames.size(),
      workers,
      [&](std::size_t k, int worker)
      {
        char file[64];
        std::snprintf(file, sizeof file, pattern.c_str(), static_cast<int>(k));
        const fs::path path = frames_dir / file;
        if (resume && fs::exists(path))
        {
          ++reused_count;
          advance();
          return;
        }
        const mapping::Sample& frame = plan.frames[k];
        const auto m0 = Clock::now();
        const mapping::Section section = section_of(frame, worker);
        const auto r0 = Clock::now();
        frep::render::Image picture = mapping::render_sample(
          plan, section, frame, camera, spec.render.width, spec.render.height, spec.render);
        mapping::decorate_frame(picture, plan, frame, spec.render, kits[worker].get());
        const auto w0 = Clock::now();
        write_png_file(path, picture);
        frame_ledger.add(std::chrono::duration<double>(r0 - m0).count(),
          std::chrono::duration<double>(w0 - r0).count(),
          seconds_since(w0));
        advance();
      });
    reused = reused_count;
    nlohmann::json frames = nlohmann::json::array();
    for (std::size_t k = 0; k < plan.frames.size(); ++k)
    {
      char file[64];
      std::snprintf(file, sizeof file, pattern.c_str(), static_cast<int>(k));
      nlohmann::json j = sample_json(plan.frames[k], names);
      j["file"] = std::string("frames/") + file;
      j["time"] = plan.frames[k].time;
      j["path_parameter"] = plan.frames[k].path_parameter;
      frames.push_back(j);
    }
    files.push_back({ { "file", "frames/" + pattern },
      { "kind", "frames" },
      { "count", plan.frames.size() },
      { "fps", spec.animation.fps },
      { "width", spec.render.width },
      { "height", spec.render.height },
      { "frames", frames } });
    stages.push_back({ "frames",
      seconds_since(t0),
      std::to_string(plan.frames.size()) + " frames" +
        (reused ? " (" + std::to_string(reused) + " kept from an earlier run)" : "") +
        frame_ledger.text() });
  }

  // 5. The sound track.
  const fs::path wav = out_dir / (stem + ".wav");
  if (do_audio)
  {
    const auto t0 = Clock::now();
    frep::media::VoiceFrames voices;
    for (const auto& f : plan.frames)
    {
      std::vector<frep::media::VoiceParams> v;
      for (const auto& voice : f.voices)
      {
        v.push_back({ voice.pitch, voice.loudness, voice.timbre });
      }
      voices.push_back(v);
    }
    const frep::media::SynthesisResult sound =
      frep::media::synthesise(voices, spec.animation.fps, spec.audio.sample_rate);
    if (!sound.ok())
    {
      throw UserError("sound: " + sound.error);
    }
    const frep::media::WavWriteResult written =
      frep::media::write_wav(wav, sound.samples, spec.audio.sample_rate);
    if (!written.ok())
    {
      throw UserError(written.error);
    }
    const double duration = static_cast<double>(sound.samples.size()) / spec.audio.sample_rate;
    files.push_back({ { "file", wav.filename().string() },
      { "kind", "audio" },
      { "sample_rate", spec.audio.sample_rate },
      { "voices", plan.voice_count },
      { "duration", duration } });
    char detail[64];
    std::snprintf(detail, sizeof detail, "%.2f s, %d voice(s)", duration, plan.voice_count);
    stages.push_back({ "audio", seconds_since(t0), detail });
  }

  // 6. The movie, from the frames and the sound track.
  if (do_movie)
  {
    const auto t0 = Clock::now();
    frep::media::MovieInput input;
    input.frame_pattern = (frames_dir / pattern).string();
    input.frame_count = static_cast<int>(plan.frames.size());
    input.fps = spec.animation.fps;
    if (do_audio)
    {
      input.audio = wav;
    }
    frep::media::MovieOptions mo;
    const std::size_t before = units_done;
    mo.progress = [&](const frep::media::MovieProgress& p)
    {
      std::lock_guard<std::mutex> lock(bar_mutex);
      bar.update((before + p.frames_done / 4.0) / total_units);
    };
    const fs::path movie = out_dir / (stem + ".mp4");
    const frep::media::MovieResult encoded = frep::media::encode_movie(input, movie, mo);
    if (!encoded.ok())
    {
      throw UserError("movie: " + encoded.error);
    }
    files.push_back({ { "file", movie.filename().string() },
      { "kind", "movie" },
      { "frames", plan.frames.size() },
      { "fps", spec.animation.fps },
      { "duration", plan.frames.size() / spec.animation.fps },
      { "audio", do_audio } });
    stages.push_back({ "movie", seconds_since(t0), movie.filename().string() });
  }
  bar.finish();

  manifest["files"] = files;
  nlohmann::json timing = nlohmann::json::object();
  for (const auto& s : stages)
  {
    timing[s.name] = s.seconds;
  }
  manifest["seconds"] = timing;
  write_text_file(out_dir / "manifest.json", manifest.dump(2) + "\n");

  if (!options.quiet)
  {
    std::cerr << "frepkit map: " << model->name() << " (" << model->x_dim() << "-D) -> "
              << out_dir.string() << "\n";
    for (const auto& s : stages)
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
      seconds_since(start),
      triangles.load());
    std::cerr << line;
  }
  if (failed_samples > 0)
  {
    std::cerr << "frepkit: warning: " << failed_samples
              << " samples raised a run-time error (taken as outside)\n";
  }
  return 0;
}

} // namespace frepkit
