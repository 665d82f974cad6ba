// frepkit map, phases 1-4: the inputs (mapping, model, plan), the products, the output place,
// the framing.
#include "map_phases.h"

#include "Durable/interrupt_guard.h"
#include "model_loading.h"
#include "user_error.h"

#include "Plan/mapping_json.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace frepkit::map_run
{
namespace
{

template<typename Errors>
void print_errors(const MapOptions& options, const Errors& errors)
{
  for (const auto& e : errors)
  {
    std::cerr << options.mapping << ": " << (e.place.empty() ? "" : e.place + ": ") << e.message
              << '\n';
  }
}

// The mapping file, checked, with --resolution, --frames and --method applied.
mapping::Spec load_spec(const MapOptions& options, const std::string& mapping_text)
{
  mapping::LoadResult loaded = mapping::load_mapping(mapping_text);
  if (!loaded.errors.empty())
  {
    print_errors(options, loaded.errors);
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
  if (options.method)
  {
    using Method = mapping::RenderSettings::Method;
    const Method method = *options.method == "raycast" ? Method::Raycast : Method::Mesh;
    spec.render.method = method;
    spec.render.frames_method = method;
  }
  return spec;
}

// The object (--object, else the mapping's, else the default), compiled, and its a[] values.
void load_mapped_model(const MapOptions& options, MapInputs& in)
{
  std::optional<std::string> object_name = options.object;
  if (!object_name && !in.spec.object.empty())
  {
    object_name = in.spec.object;
  }
  in.parameters = options.parameters.empty() ? in.spec.parameters : options.parameters;
  in.model =
    frepkit::load_model(options.model, options.user, object_name, in.parameters.size()).model;
}

// The model's coordinates x1..xn over hfp's default box, and the plan of the mapping for them.
void plan_mapping(const MapOptions& options, MapInputs& in)
{
  const frep::Model& model = *in.model;
  for (int i = 0; i < model.x_dim(); ++i)
  {
    in.coordinates.names.push_back("x" + std::to_string(i + 1));
    in.coordinates.intervals.push_back({ -10.0, 10.0 }); // hfp's default box
  }
  mapping::PlanResult planned = mapping::make_plan(in.spec, in.coordinates);
  if (!planned.ok())
  {
    print_errors(options, planned.errors);
    throw UserError("the mapping does not fit " + model.name() + " (" +
                    std::to_string(model.x_dim()) + "-D); nothing written");
  }
  in.plan = std::move(planned.plan);
}

} // namespace

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

MapInputs load_inputs(const MapOptions& options)
{
  MapInputs in;
  in.mapping_text = read_file(options.mapping, "mapping file");
  in.spec = load_spec(options, in.mapping_text);
  load_mapped_model(options, in);
  plan_mapping(options, in);
  return in;
}

MapProducts choose_products(const MapOptions& options, const mapping::Plan& plan)
{
  auto wanted = [&](const char* what)
  {
    return options.only.empty() ||
           std::find(options.only.begin(), options.only.end(), what) != options.only.end();
  };
  MapProducts p;
  p.spreadsheet = wanted("spreadsheet") && !plan.cells.empty();
  p.path = wanted("path") && plan.dynamic_coordinates.size() == 2;
  p.frames = (wanted("frames") || wanted("movie")) && !plan.frames.empty();
  p.audio = (wanted("audio") || wanted("movie")) && !plan.frames.empty() && plan.voice_count > 0;
  p.movie = wanted("movie") && !plan.frames.empty();
  p.shape = wanted("shape") && plan.cells.empty() && plan.frames.empty();
  if (!p.spreadsheet && !p.path && !p.frames && !p.audio && !p.shape)
  {
    throw UserError("the mapping has nothing of --only to produce (spreadsheet needs a "
                    "spreadsheet coordinate; path, frames, audio and movie a dynamic one; shape "
                    "neither)");
  }
  return p;
}

void frame_solids(MapInputs& in, const MapProducts& products, int workers, MapRecord& record)
{
  if (!(products.spreadsheet || products.shape || products.frames) || in.spec.render.view_box)
  {
    return;
  }
  const auto t0 = Clock::now();
  frep::ThreadPool pool(workers);
  in.framing = mapping::frame_solids(in.spec.render, *in.model, in.parameters, in.plan, &pool);
  frep::durable::InterruptGuard::throw_if_interrupted();
  const std::size_t samples = 1 + in.plan.cells.size() + in.plan.frames.size();
  record.stages.push_back({ "framing",
    seconds_since(t0),
    std::to_string(samples) + " solids seen from the view" +
      (in.framing.empty() ? std::string(": none in the model box") : std::string()) });
}

MapOutput prepare_output(const MapOptions& options)
{
  MapOutput out;
  out.directory = fs::path(options.output_directory);
  std::error_code ec;
  fs::create_directories(out.directory, ec);
  if (ec)
  {
    throw UserError("cannot create " + out.directory.string() + ": " + ec.message());
  }
  out.stem = !options.name.empty() ? options.name : fs::path(options.mapping).stem().string();
  out.workers = options.threads > 0
                  ? options.threads
                  : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return out;
}

} // namespace frepkit::map_run
