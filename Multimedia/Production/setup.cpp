// produce, phases 1-4: the plan, the products, the output directory, the framing.
#include "Production/detail/phases.h"

#include "Scene/section_model.h"

#include <algorithm>
#include <thread>

namespace frep::mapping::production
{

void Job::throw_if_stopped() const
{
  if (stopped())
  {
    throw Stopped();
  }
}

bool plan_job(Job& job, std::vector<std::string>& diagnostics)
{
  const Model& model = job.model();
  job.coordinates = hyperfun_coordinates(model.x_dim());
  PlanResult planned = make_plan(job.spec(), job.coordinates);
  if (!planned.ok())
  {
    for (const auto& e : planned.errors)
    {
      diagnostics.push_back((e.place.empty() ? "" : e.place + ": ") + e.message);
    }
    return false;
  }
  job.plan = std::move(planned.plan);
  SectionModel sectioned = section_model(job.inputs.model, job.plan, job.inputs.parameters);
  if (!sectioned.ok())
  {
    diagnostics.push_back(sectioned.error);
    return false;
  }
  job.sectioned = std::move(sectioned.model);
  return true;
}

Products choose_products(const Job& job)
{
  const std::vector<std::string>& only = job.options.only;
  for (const std::string& name : only)
  {
    const auto& known = product_names();
    if (std::find(known.begin(), known.end(), name) == known.end())
    {
      std::string names;
      for (const std::string& k : known)
        names += (names.empty() ? "" : ", ") + k;
      throw ProductionError("no product is called '" + name + "' (" + names + ")");
    }
  }
  auto wanted = [&](const char* what)
  { return only.empty() || std::find(only.begin(), only.end(), what) != only.end(); };
  const Plan& plan = job.plan;
  Products p;
  p.spreadsheet = wanted("spreadsheet") && !plan.cells.empty();
  p.path = wanted("path") && plan.dynamic_coordinates.size() == 2;
  p.frames = (wanted("frames") || wanted("movie")) && !plan.frames.empty();
  p.audio = (wanted("audio") || wanted("movie")) && !plan.frames.empty() && plan.voice_count > 0;
  p.movie = wanted("movie") && !plan.frames.empty();
  p.shape = wanted("shape") && plan.cells.empty() && plan.frames.empty();
  p.ghost = wanted("ghost") && job.spec().animation.ghost && !plan.frames.empty() &&
            !plan.dynamic_coordinates.empty();
  p.topology = wanted("topology") && job.spec().topology &&
               (!plan.cells.empty() || !plan.frames.empty());
  if (!p.spreadsheet && !p.path && !p.frames && !p.audio && !p.shape && !p.ghost && !p.topology)
  {
    throw ProductionError("the mapping has nothing of --only to produce (spreadsheet needs a "
                          "spreadsheet coordinate; path, frames, audio and movie a dynamic one; "
                          "shape neither; ghost animation.ghost and topology the key topology)");
  }
  return p;
}

void prepare_directory(const fs::path& directory)
{
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec)
  {
    throw ProductionError("cannot create " + directory.string() + ": " + ec.message());
  }
}

int worker_count(const ProductionOptions& options)
{
  return options.threads > 0 ? options.threads
                             : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void frame_solids(Job& job, const Products& products, int workers, Record& record)
{
  if (!(products.spreadsheet || products.shape || products.frames) || job.spec().render.view_box)
  {
    return;
  }
  const auto t0 = Clock::now();
  RunControl run;
  run.pool = job.options.pool ? job.options.pool : std::make_shared<ThreadPool>(workers);
  run.cancel = [&job] { return job.stopped(); };
  job.framing =
    mapping::frame_solids(job.spec().render, job.section_source(), job.inputs.parameters, job.plan, run);
  job.throw_if_stopped();
  const std::size_t samples = 1 + job.plan.cells.size() + job.plan.frames.size();
  record.stages.push_back({ "framing",
    seconds_since(t0),
    std::to_string(samples) + " solids seen from the view" +
      (job.framing.empty() ? std::string(": none in the model box") : std::string()) });
}

} // namespace frep::mapping::production
