// One cross-section drawn both ways, on the same camera and lights: ray-cast from the function
// (Raycast/raycast.h) and meshed at a grid then rasterised (Mesh + Render, what frepkit map's
// "mesh" method does). Prints one Markdown row: wall seconds of each and the ray caster's
// counters, so a run shows pixels per second and where the time goes.
//
// Usage: frep_raycast_benchmark MODEL [--fix 0.5,0.5] [--size 1280,720] [--grid 128]
//                               [--threads 0] [--floor]
//   --fix gives x4, x5, ... (the coordinates after the first three), as many as the model has.
#include "benchmark_cli.h"

#include "Raycast/raycast.h"
#include "Imaging/camera.h"
#include "Render/mesh_renderer.h"

#include "Compiler/model.h"
#include "Compiler/load_model.h"
#include "Mesh/surface.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << "usage: frep_raycast_benchmark MODEL [--fix v4,v5,..] [--size W,H] [--grid N] "
                 "[--threads T] [--floor]\n";
    return 1;
  }
  std::vector<double> fix, size{ 1280, 720 };
  int grid = 128, threads = 0;
  bool with_floor = false;
  for (int i = 2; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--floor")
    {
      with_floor = true;
    }
    else if (i + 1 < argc && a == "--fix")
    {
      fix = frep::bench::comma_numbers(argv[++i]);
    }
    else if (i + 1 < argc && a == "--size")
    {
      size = frep::bench::comma_numbers(argv[++i]);
    }
    else if (i + 1 < argc && a == "--grid")
    {
      grid = std::stoi(argv[++i]);
    }
    else if (i + 1 < argc && a == "--threads")
    {
      threads = std::stoi(argv[++i]);
    }
    else
    {
      std::cerr << "unknown option " << a << "\n";
      return 1;
    }
  }
  const frep::LoadedModel loaded = frep::load_model(frep::ModelSource::file(argv[1]));
  if (!loaded.ok())
  {
    std::cerr << loaded.message();
    return 1;
  }
  const auto model = loaded.model;
  frep::Specialisation spec;
  spec.fixed.assign(static_cast<std::size_t>(model->x_dim()), std::nullopt);
  for (std::size_t k = 0; k < fix.size() && k + 3 < spec.fixed.size(); ++k)
  {
    spec.fixed[k + 3] = fix[k];
  }
  for (std::size_t k = 3; k < spec.fixed.size(); ++k)
  {
    spec.fixed[k] = spec.fixed[k].value_or(0.0);
  }
  spec.input_order = { 0, 1, 2 };
  const auto tape = model->specialise(spec);
  const int width = static_cast<int>(size.at(0)), height = static_cast<int>(size.at(1));
  const std::array<double, 3> lo{ -10, -10, -10 }, hi{ 10, 10, 10 };
  const frep::imaging::Camera camera =
    frep::imaging::fit_box(lo, hi, static_cast<double>(width) / height, 25.0, 15.0);
  frep::raycast::Floor floor;
  floor.height = -10;
  floor.origin = { -16, -16 };
  floor.square = 4;

  // Ray-cast.
  frep::raycast::Shape shape;
  shape.tape = tape;
  shape.box = { frep::Interval{ -10, 10 }, frep::Interval{ -10, 10 }, frep::Interval{ -10, 10 } };
  frep::raycast::Style style;
  style.render.threads = threads; // the mesh renderer's, below
  frep::RunControl run;
  run.threads = threads;
  frep::imaging::Image ray_picture(width, height, { 1, 1, 1, 1 });
  const frep::raycast::Result r = frep::raycast::render(
    ray_picture, camera, shape, with_floor ? &floor : nullptr, style, nullptr, run);
  if (!r.ok())
  {
    std::cerr << r.error << "\n";
    return 1;
  }

  // Meshed and rasterised.
  auto t0 = Clock::now();
  const frep::GridSpec g{ { { -10, 10, grid }, { -10, 10, grid }, { -10, 10, grid } } };
  frep::mesh::ExtractOptions eo;
  eo.threads = threads;
  const frep::mesh::ExtractResult m = frep::mesh::extract_surface(tape, g, eo);
  const double mesh_s = seconds_since(t0);
  t0 = Clock::now();
  frep::imaging::Image mesh_picture(width, height, { 1, 1, 1, 1 });
  frep::render::MeshInput mi;
  mi.points = m.surface.points;
  mi.triangles = m.surface.cells;
  mi.normals = m.surface.normals;
  frep::imaging::RenderStyle rs;
  rs.threads = threads;
  frep::render::render_mesh(mesh_picture, camera, mi, rs);
  const double raster_s = seconds_since(t0);

  const frep::raycast::Statistics& s = r.statistics;
  std::printf("| model | picture | ray-cast s | rays | hits | edge px | intervals | points | "
              "shadow s | mesh %d^3 s | raster s | triangles |\n",
    grid);
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::printf("| %s | %dx%d | %.3f | %zu | %zu | %zu | %zu | %zu | %.3f | %.3f | %.3f | %zu |\n",
    argv[1],
    width,
    height,
    s.seconds,
    s.rays,
    s.hits,
    s.edge_pixels,
    s.interval_evaluations,
    s.point_evaluations,
    s.shadow_seconds,
    mesh_s,
    raster_s,
    m.surface.cell_count());
  return 0;
}
