// frepkit map: what the rendering phases share (workers, progress, file writing).
#include "map_phases.h"

#include "Durable/atomic_output.h"
#include "Durable/interrupt_guard.h"
#include "section_writers/png_writer.h"
#include "user_error.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <sstream>
#include <thread>

namespace frepkit::map_run
{

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void write_png_file(const fs::path& path, const frep::imaging::Image& image)
{
  frep::durable::AtomicOutput out(path.string());
  write_png(out.stream(), image.width, image.height, frep::imaging::to_rgb8(image));
  out.commit();
}

void write_text_file(const fs::path& path, const std::string& text)
{
  frep::durable::AtomicOutput out(path.string());
  out.stream() << text;
  out.commit();
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

void Ledger::add(double mesh, double render, double write)
{
  std::lock_guard<std::mutex> lock(mutex);
  meshing += mesh;
  rendering += render;
  writing += write;
}

std::string Ledger::text()
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

MapWorkers::MapWorkers(const MapInputs& inputs,
  const MapProducts& products,
  int workers,
  bool quiet)
  : inputs_(inputs)
  , bar_("map", !quiet)
{
  {
    // The PNG encoder is loaded on first use; load it before the workers race for it.
    std::ostringstream warm;
    write_png(warm, 1, 1, { 255, 255, 255 });
  }
  // One picture kit per worker: fonts are not shared between threads.
  for (int w = 0; w < workers; ++w)
  {
    kits_.push_back(std::make_unique<mapping::PictureKit>());
  }
  if (!kits_.front()->font_error.empty() && !quiet)
  {
    std::cerr << "frepkit: warning: " << kits_.front()->font_error << "; pictures without labels\n";
  }
  // Meshing: each worker meshes its sample on one thread, so the workers use all cores on
  // independent samples (no synchronisation inside a mesh).
  for (int w = 0; w < workers; ++w)
  {
    pools_.push_back(std::make_shared<frep::ThreadPool>(1));
  }
  const mapping::Plan& plan = inputs.plan;
  total_units_ = (products.spreadsheet ? plan.cells.size() : 0) +
                 (products.frames ? plan.frames.size() : 0) +
                 (products.movie ? plan.frames.size() / 4.0 : 0) + 1.0;
}

mapping::Section MapWorkers::section(const mapping::Sample& sample, int worker)
{
  mapping::SectionOptions so;
  so.pool = pools_[static_cast<std::size_t>(worker)];
  so.cancel = [] { return frep::durable::InterruptGuard::interrupted(); };
  mapping::Section section =
    mapping::make_section(*inputs_.model, inputs_.parameters, inputs_.plan, sample, so);
  if (section.cancelled || frep::durable::InterruptGuard::interrupted())
  {
    throw frep::durable::Interrupted(
      "interrupted; the files written so far are kept (run again to resume)");
  }
  if (!section.error.empty())
  {
    throw UserError(sample.label + ": " + section.error);
  }
  failed_samples_ += section.statistics.failed_samples;
  triangles_ += section.surface.cell_count();
  return section;
}

MapWorkers::Picture MapWorkers::picture(mapping::RenderSettings::Method method,
  const mapping::Sample& sample,
  const frep::imaging::Camera& camera,
  int width,
  int height,
  int worker,
  int threads,
  const frep::raycast::Floor* floor)
{
  Picture p;
  const mapping::RenderSettings& settings = inputs_.spec.render;
  const auto t0 = std::chrono::steady_clock::now();
  if (method == mapping::RenderSettings::Method::Raycast)
  {
    mapping::RaycastOptions ro;
    ro.threads = threads;
    ro.cancel = [] { return frep::durable::InterruptGuard::interrupted(); };
    ro.floor = floor;
    // On the floor scene's board the solid stands on its lowest point.
    const mapping::Sample placed = floor
      ? mapping::stand_on_floor(
          *inputs_.model, inputs_.parameters, inputs_.plan, sample, *floor, threads)
      : sample;
    mapping::RaycastPicture r = mapping::raycast_sample(
      *inputs_.model, inputs_.parameters, inputs_.plan, placed, camera, width, height, ro);
    if (frep::durable::InterruptGuard::interrupted() || r.error == "cancelled")
    {
      throw frep::durable::Interrupted(
      "interrupted; the files written so far are kept (run again to resume)");
    }
    if (!r.ok())
    {
      throw UserError(sample.label + ": " + r.error);
    }
    p.image = std::move(r.image);
    p.render_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return p;
  }
  mapping::Section s = section(sample, worker);
  if (floor)
  {
    mapping::stand_on_floor(s, *floor); // the mesh's lowest vertex on the board
  }
  const auto t1 = std::chrono::steady_clock::now();
  p.image = mapping::render_sample(
    inputs_.plan, s, sample, camera, width, height, settings, threads, floor, inputs_.framing);
  p.mesh_seconds = std::chrono::duration<double>(t1 - t0).count();
  p.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  p.triangles = s.surface.cell_count();
  return p;
}

void MapWorkers::parallel(std::size_t count, const std::function<void(std::size_t, int)>& body)
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
      if (i >= count || failed || frep::durable::InterruptGuard::interrupted())
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
  for (int w = 1; w < this->count(); ++w)
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
  if (frep::durable::InterruptGuard::interrupted())
  {
    throw frep::durable::Interrupted(
      "interrupted; the files written so far are kept (run again to resume)");
  }
}

void MapWorkers::advance()
{
  const std::size_t done = ++units_done_;
  std::lock_guard<std::mutex> lock(bar_mutex_);
  bar_.update(done / total_units_);
}

void MapWorkers::show_units(double units)
{
  std::lock_guard<std::mutex> lock(bar_mutex_);
  bar_.update(units / total_units_);
}

} // namespace frepkit::map_run
