// produce, phase 6: the animation frames, resumable.
#include "Production/detail/phases.h"

#include "Mapping/mapping_json.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace frep::mapping::production
{
namespace
{

// What the frames depend on: a frame on disk is reused only when the model (its key: text,
// libraries, shapes), the object, the mapping as planned (overrides included: it is written out
// again), the parameters and the framing rule are the ones it was rendered with.
std::string fingerprint(const Job& job)
{
  std::ostringstream key;
  key << job.inputs.model_key << '\0' << job.model().name() << '\0'
      << save_mapping(job.spec()) << '\0';
  for (double a : job.inputs.parameters)
  {
    key << a << ',';
  }
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
// on disk were rendered with the same one (and `force` is not set), so they can be kept.
bool prepare_resume(const Job& job, const FrameFiles& frames)
{
  std::error_code ec;
  fs::create_directories(frames.directory, ec);
  if (ec)
  {
    throw ProductionError("cannot create " + frames.directory.string() + ": " + ec.message());
  }
  const std::string key = fingerprint(job);
  const fs::path key_file = frames.directory / ".fingerprint";
  std::string old;
  if (std::ifstream old_file(key_file); old_file)
  {
    std::getline(old_file, old);
  }
  // `force` renders every frame again; frames of the same fingerprint may stay meanwhile.
  const bool resume = !job.options.force && old == key;
  if (old != key)
  {
    remove_stale_frames(frames.directory, key_file);
  }
  write_text_file(key_file, key + "\n");
  return resume;
}

// The manifest's entry of the frames, with every frame's file, time and values.
nlohmann::json frames_json(const Job& job, const FrameFiles& files)
{
  const Plan& plan = job.plan;
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t k = 0; k < plan.frames.size(); ++k)
  {
    nlohmann::json j = sample_json(plan.frames[k], job.coordinates.names);
    j["file"] = std::string("frames/") + files.name(k);
    j["time"] = plan.frames[k].time;
    j["path_parameter"] = plan.frames[k].path_parameter;
    frames.push_back(j);
  }
  return { { "file", "frames/" + files.pattern },
    { "kind", "frames" },
    { "count", plan.frames.size() },
    { "fps", job.spec().animation.fps },
    { "width", job.spec().render.width },
    { "height", job.spec().render.height },
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

void render_frames(const Job& job, Workers& workers, const FrameFiles& frames, Record& record)
{
  const auto t0 = Clock::now();
  const bool resume = prepare_resume(job, frames);
  const Plan& plan = job.plan;
  const RenderSettings& render = job.spec().render;
  const double aspect = static_cast<double>(render.width) / render.height;
  // The paper's Fig. 8 (render.scene "floor"): the shape travels over the dynamic plane.
  const bool on_floor = render.scene == RenderSettings::Scene::Floor;
  const FloorScene scene =
    on_floor ? make_floor_scene(plan, job.spec(), aspect, job.framing) : FloorScene{};
  const imaging::Camera camera =
    on_floor ? scene.camera : frame_camera(plan, render, render.width, render.height, job.framing);
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
      const Sample frame = on_floor ? mapping::on_floor(scene, plan.frames[k]) : plan.frames[k];
      Workers::Picture p = workers.picture(render.frames_method,
        frame,
        camera,
        render.width,
        render.height,
        worker,
        1,
        on_floor ? &scene.floor : nullptr);
      decorate_frame(p.image, plan, frame, render, workers.kit(worker));
      const auto w0 = Clock::now();
      write_png_file(path, p.image);
      frame_ledger.add(p.mesh_seconds, p.render_seconds, seconds_since(w0));
      workers.advance();
    });
  const std::size_t reused = reused_count;
  record.files.push_back(frames_json(job, frames));
  record.stages.push_back({ "frames",
    seconds_since(t0),
    std::to_string(plan.frames.size()) + " frames" +
      (reused ? " (" + std::to_string(reused) + " kept from an earlier run)" : "") +
      frame_ledger.text() });
}

} // namespace frep::mapping::production
