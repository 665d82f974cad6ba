// frepkit map, phase 5: the animation frames, resumable.
#include "map_phases.h"

#include "user_error.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

namespace frepkit::map_run
{
namespace
{

/// The bytes of a file, or "" when it cannot be read.
std::string bytes_of(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return in ? std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>())
            : std::string();
}

/// The file of a --shape name=FILE[:ISO] (the ISO suffix is part of the spec, hashed anyway).
std::string shape_file_bytes(const std::string& spec)
{
  const std::size_t eq = spec.find('=');
  const std::string file = eq == std::string::npos ? spec : spec.substr(eq + 1);
  std::string bytes = bytes_of(file);
  if (const std::size_t colon = file.rfind(':'); bytes.empty() && colon != std::string::npos)
  {
    bytes = bytes_of(file.substr(0, colon));
  }
  return bytes;
}

// What the frames depend on: a frame on disk is reused only when the model, the mapping, the
// overrides, the user's libraries and shapes (their files' contents) and the framing rule are
// the ones it was rendered with.
std::string fingerprint(const std::string& model_text,
  const std::string& mapping_text,
  const MapOptions& options)
{
  std::ostringstream key;
  key << model_text << '\0' << mapping_text << '\0' << options.object.value_or("") << '\0'
      << options.resolution.value_or(0) << '\0' << options.frames.value_or(0) << '\0'
      << options.method.value_or("") << '\0';
  for (double a : options.parameters)
  {
    key << a << ',';
  }
  for (const std::string& library : options.user.libraries)
  {
    key << '\0' << library << '\0' << bytes_of(library);
  }
  for (const std::string& shape : options.user.shapes)
  {
    key << '\0' << shape << '\0' << shape_file_bytes(shape);
  }
  key << '\0' << options.user.unsigned_distance;
  // The framing rule: frames of an older rule (the model box's) must not be kept beside new ones.
  key << '\0' << "framing: the solids' box";
  char hex[32];
  std::snprintf(hex, sizeof hex, "%016zx", std::hash<std::string>{}(key.str()));
  return hex;
}

// Frames rendered with another fingerprint must not survive an interrupted run: they would be
// trusted under the new one when the run is resumed. The old fingerprint goes first, so that a
// run stopped during the removal leaves no key at all (the next run renders every frame).
void remove_stale_frames(const fs::path& directory, const fs::path& key_file)
{
  std::error_code ec;
  fs::remove(key_file, ec);
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, ec))
  {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("frame_") && name.ends_with(".png"))
    {
      fs::remove(entry.path(), ec);
    }
  }
}

// Creates the frames' directory and writes this run's fingerprint there; true when the frames
// on disk were rendered with the same one (and --force is not given), so they can be kept.
bool prepare_resume(const MapOptions& options, const MapInputs& in, const FrameFiles& frames)
{
  std::error_code ec;
  fs::create_directories(frames.directory, ec);
  if (ec)
  {
    throw UserError("cannot create " + frames.directory.string() + ": " + ec.message());
  }
  const std::string key = fingerprint(read_file(options.model, "model"), in.mapping_text, options);
  const fs::path key_file = frames.directory / ".fingerprint";
  std::string old;
  if (std::ifstream old_file(key_file); old_file)
  {
    std::getline(old_file, old);
  }
  // --force renders every frame again; frames of the same fingerprint may stay meanwhile.
  const bool resume = !options.force && old == key;
  if (old != key)
  {
    remove_stale_frames(frames.directory, key_file);
  }
  write_text_file(key_file, key + "\n");
  return resume;
}

// The manifest's entry of the frames, with every frame's file, time and values.
nlohmann::json frames_json(const MapInputs& in, const FrameFiles& files)
{
  const mapping::Plan& plan = in.plan;
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t k = 0; k < plan.frames.size(); ++k)
  {
    nlohmann::json j = sample_json(plan.frames[k], in.coordinates.names);
    j["file"] = std::string("frames/") + files.name(k);
    j["time"] = plan.frames[k].time;
    j["path_parameter"] = plan.frames[k].path_parameter;
    frames.push_back(j);
  }
  return { { "file", "frames/" + files.pattern },
    { "kind", "frames" },
    { "count", plan.frames.size() },
    { "fps", in.spec.animation.fps },
    { "width", in.spec.render.width },
    { "height", in.spec.render.height },
    { "frames", frames } };
}

} // namespace

std::string FrameFiles::name(std::size_t k) const
{
  char file[64];
  std::snprintf(file, sizeof file, pattern.c_str(), static_cast<int>(k));
  return file;
}

fs::path FrameFiles::file(std::size_t k) const
{
  return directory / name(k);
}

void render_frames(const MapOptions& options,
  const MapInputs& in,
  MapWorkers& workers,
  const FrameFiles& frames,
  MapRecord& record)
{
  const auto t0 = Clock::now();
  const bool resume = prepare_resume(options, in, frames);
  const mapping::Plan& plan = in.plan;
  const mapping::RenderSettings& render = in.spec.render;
  const double aspect = static_cast<double>(render.width) / render.height;
  // The paper's Fig. 8 (render.scene "floor"): the shape travels over the dynamic plane.
  const bool on_floor = render.scene == mapping::RenderSettings::Scene::Floor;
  const mapping::FloorScene scene =
    on_floor ? mapping::make_floor_scene(plan, in.spec, aspect, in.framing) : mapping::FloorScene{};
  const frep::imaging::Camera camera =
    on_floor ? scene.camera
             : mapping::frame_camera(plan, render, render.width, render.height, in.framing);
  std::atomic<std::size_t> reused_count{ 0 };
  Ledger frame_ledger;
  workers.parallel(plan.frames.size(),
    [&](std::size_t k, int worker)
    {
      const fs::path path = frames.file(k);
      if (resume && fs::exists(path))
      {
        ++reused_count;
        workers.advance();
        return;
      }
      const mapping::Sample frame = on_floor ? mapping::on_floor(scene, plan.frames[k]) : plan.frames[k];
      MapWorkers::Picture p = workers.picture(render.frames_method,
        frame, camera, render.width, render.height, worker, 1, on_floor ? &scene.floor : nullptr);
      mapping::decorate_frame(p.image, plan, frame, render, workers.kit(worker));
      const auto w0 = Clock::now();
      write_png_file(path, p.image);
      frame_ledger.add(p.mesh_seconds, p.render_seconds, seconds_since(w0));
      workers.advance();
    });
  const std::size_t reused = reused_count;
  record.files.push_back(frames_json(in, frames));
  record.stages.push_back({ "frames",
    seconds_since(t0),
    std::to_string(plan.frames.size()) + " frames" +
      (reused ? " (" + std::to_string(reused) + " kept from an earlier run)" : "") +
      frame_ledger.text() });
}

} // namespace frepkit::map_run
