// What framing a mapping's pictures costs (Scene/framing.h, frame_solids): the one camera that
// fits every cell's and frame's solid. FRepStudio's spreadsheet waits for it before its first
// cell. Prints the whole call's wall time on a pool, then the same work per step on one thread
// (the section's tape, the solid's bounds, the silhouette), so a change shows where time went.
//
// Usage: frep_framing_benchmark MODEL MAPPING.json [--threads 0] [--repeat 3] [--cells-only]
//                               [--pixels 48]
//   e.g. Examples/homotopic/meta5d.hf Benchmarks/framing_sheet.json (Meta5D's 5 x 5 sheet).
//   The mapping's view_box is dropped (a view_box skips framing). --cells-only drops the frames.
//   --pixels: the silhouette's rays per side in the per-step timing (frame_solids uses 48).
#include "benchmark_cli.h"

#include "Mapping/mapping_json.h"
#include "Mapping/mapping_plan.h"
#include "Scene/framing.h"
#include "Scene/section_mesh.h"
#include "Scene/section_raycast.h"

#include "Eval/thread_pool.h"
#include "Raycast/raycast.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

namespace
{

namespace fm = frep::mapping;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct Steps
{
  double specialise = 0.0, bounds = 0.0, silhouette = 0.0;
};

// frame_solids' work per sample, one step at a time, on the calling thread.
Steps time_steps(const frep::Model& model, const fm::Plan& plan, const fm::RenderSettings& render,
  int pixels)
{
  Steps t;
  const frep::imaging::CameraFrame view =
    frep::imaging::view_frame(render.azimuth, render.elevation);
  std::vector<frep::Interval> box;
  for (int k = 0; k < 3; ++k)
  {
    box.push_back(frep::Interval{ plan.model_box[k].lo, plan.model_box[k].hi });
  }
  std::vector<const fm::Sample*> samples{ &plan.still };
  for (const fm::Sample& s : plan.cells)
    samples.push_back(&s);
  for (const fm::Sample& s : plan.frames)
    samples.push_back(&s);
  for (const fm::Sample* s : samples)
  {
    Clock::time_point t0 = Clock::now();
    frep::raycast::Shape shape;
    shape.tape = model.specialise(fm::section_specialisation(plan, *s, {}));
    t.specialise += seconds_since(t0);
    t0 = Clock::now();
    shape.bounds = frep::raycast::solid_bounds(shape.tape, box);
    t.bounds += seconds_since(t0);
    if (!shape.bounds->bounded())
      continue;
    for (int k = 0; k < 3; ++k)
      shape.box[k] = box[static_cast<std::size_t>(k)];
    shape.to_world = fm::raycast_world_map(plan, *s);
    t0 = Clock::now();
    (void)frep::raycast::silhouette(shape, view, pixels);
    t.silhouette += seconds_since(t0);
  }
  return t;
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 3)
  {
    std::cerr << "usage: frep_framing_benchmark MODEL MAPPING.json [--threads T] [--repeat R] "
                 "[--cells-only] [--pixels N]\n";
    return 1;
  }
  int threads = 0, repeat = 3, pixels = 48;
  bool cells_only = false;
  for (int i = 3; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--cells-only")
      cells_only = true;
    else if (i + 1 < argc && a == "--threads")
      threads = std::stoi(argv[++i]);
    else if (i + 1 < argc && a == "--pixels")
      pixels = std::stoi(argv[++i]);
    else if (i + 1 < argc && a == "--repeat")
      repeat = std::max(1, std::stoi(argv[++i]));
    else
    {
      std::cerr << "unknown option " << a << "\n";
      return 1;
    }
  }
  const std::shared_ptr<const frep::Model> model = frep::bench::compile_model_file(argv[1]);
  std::ifstream in(argv[2]);
  const std::string text{ std::istreambuf_iterator<char>(in), {} };
  fm::LoadResult loaded = fm::load_mapping(text);
  if (!model || !in || !loaded.ok())
  {
    std::cerr << "cannot read the model or the mapping " << argv[2] << "\n";
    return 1;
  }
  loaded.spec.render.view_box.reset();
  fm::PlanResult planned = fm::make_plan(loaded.spec, fm::hyperfun_coordinates(model->x_dim()));
  if (!planned.ok() || !fm::raycast_supported(planned.plan))
  {
    std::cerr << (planned.ok() ? "the plan cannot be ray-cast\n" : fm::format_errors(planned.errors));
    return 1;
  }
  fm::Plan& plan = planned.plan;
  if (cells_only)
    plan.frames.clear();
  frep::RunControl run;
  run.pool = std::make_shared<frep::ThreadPool>(threads);
  const std::size_t samples = 1 + plan.cells.size() + plan.frames.size();
  double best = 1e300;
  for (int r = 0; r < repeat; ++r)
  {
    const Clock::time_point t0 = Clock::now();
    const fm::Framing framing = fm::frame_solids(loaded.spec.render, *model, {}, plan, run);
    best = std::min(best, seconds_since(t0));
    if (framing.empty())
    {
      std::cerr << "no sample has a solid\n";
      return 1;
    }
  }
  const Steps steps = time_steps(*model, plan, loaded.spec.render, pixels);
  std::printf("| samples | threads | frame_solids s (best of %d) | 1 thread: specialise s | "
              "solid_bounds s | silhouette s |\n|---|---|---|---|---|---|\n",
    repeat);
  std::printf("| %zu | %d | %.3f | %.3f | %.3f | %.3f |\n", samples, run.pool->size(), best,
    steps.specialise, steps.bounds, steps.silhouette);
  return 0;
}
