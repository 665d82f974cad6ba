// produce: what the rendering phases share (workers, progress, file writing).
#include "Production/detail/phases.h"

#include "Durable/atomic_output.h"
#include "Imaging/png_writer.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <sstream>
#include <thread>

namespace frep::mapping::production
{

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void write_png_file(const fs::path& path, const imaging::Image& image)
{
  durable::AtomicOutput out(path.string());
  imaging::write_png(out.stream(), image);
  out.commit();
}

void write_text_file(const fs::path& path, const std::string& text)
{
  durable::AtomicOutput out(path.string());
  out.stream() << text;
  out.commit();
}

nlohmann::json sample_json(const Sample& s, const std::vector<std::string>& names)
{
  nlohmann::json values = nlohmann::json::object();
  for (std::size_t i = 0; i < s.values.size() && i < names.size(); ++i)
  {
    if (!std::isnan(s.values[i]))
    {
      values[names[i]] = s.values[i];
    }
  }
  return { { "label", s.label }, { "values", values } };
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

Workers::Workers(const Job& job, const Products& products, int workers)
  : job_(job)
{
  {
    // libpng's first use loads zlib's tables; do it before the workers race for them.
    std::ostringstream warm;
    imaging::write_png(warm, 1, 1, { 255, 255, 255 });
  }
  // One picture kit per worker: fonts are not shared between threads.
  for (int w = 0; w < workers; ++w)
  {
    kits_.push_back(std::make_unique<PictureKit>());
  }
  // Meshing: each worker meshes its sample on one thread, so the workers use all cores on
  // independent samples (no synchronisation inside a mesh).
  for (int w = 0; w < workers; ++w)
  {
    pools_.push_back(std::make_shared<ThreadPool>(1));
  }
  const Plan& plan = job.plan;
  total_units_ = (products.spreadsheet ? plan.cells.size() : 0) +
                 (products.frames ? plan.frames.size() : 0) +
                 (products.movie ? plan.frames.size() / 4.0 : 0) + (products.ghost ? 1.0 : 0.0) +
                 // The topology map: a unit per cell and frame meshed (not its bisections).
                 (products.topology ? double(plan.cells.size() + plan.frames.size()) : 0.0) +
                 1.0;
}

Workers::Picture Workers::picture(RenderSettings::Method method,
  const Sample& sample,
  const imaging::Camera& camera,
  int width,
  int height,
  int worker,
  int threads,
  const raycast::Floor* floor)
{
  DrawOptions options;
  if (threads == 1)
  {
    options.pool = pools_[static_cast<std::size_t>(worker)];
  }
  else
  {
    options.threads = threads;
  }
  options.cancel = [this] { return job_.stopped(); };
  options.floor = floor;
  Picture p = draw_sample(job_.section_source(),
    job_.inputs.parameters,
    job_.plan,
    sample,
    camera,
    width,
    height,
    job_.spec().render,
    method,
    options,
    job_.framing);
  if (p.cancelled)
  {
    throw Stopped();
  }
  job_.throw_if_stopped();
  if (!p.error.empty())
  {
    throw ProductionError(sample.label + ": " + p.error);
  }
  failed_samples_ += p.failed_samples;
  triangles_ += p.triangles;
  return p;
}

void Workers::parallel(std::size_t count, const std::function<void(std::size_t, int)>& body)
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
      if (i >= count || failed || job_.stopped())
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
  job_.throw_if_stopped();
}

void Workers::advance()
{
  show_units(static_cast<double>(++units_done_));
}

void Workers::show_units(double units)
{
  if (!job_.options.progress)
  {
    return;
  }
  // One call at a time, so a caller's progress bar needs no lock of its own.
  std::lock_guard<std::mutex> lock(progress_mutex_);
  if (!job_.options.progress(std::min(1.0, units / total_units_)))
  {
    job_.stop_requested = true;
  }
}

} // namespace frep::mapping::production
