// Swept volumes: the projection along time (FRep/Project) against the naive union of N sampled
// frames, meshed at the same grid (issue 28's speed goal: the projection faster than the 64-frame
// union, and exact). Two moving solids: a sphere going along a segment (the sweep is a capsule of
// known volume) and a thin blade turning half a turn (the union of few frames misses the slivers
// between them near the tips). For each: wall time, enclosed volume, components, and the points
// of a 64^3 probe grid inside the sweep (P >= 1e-3) that the union leaves out.
//
//   frep_sweep_benchmark [--grids 128,256] [--frames 64,240] [--threads 0]
#include "Compiler/load_model.h"
#include "Eval/point_evaluator.h"
#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"
#include "Project/projection.h"
#include "benchmark_cli.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace
{

struct Case
{
  const char* name;
  const char* object;
  const char* text;
  double lo[3], hi[3];
  double exact_volume; // 0: not known
};

const Case kCases[] = {
  { "moving sphere (capsule)", "moving",
    "moving(x[4], a[1]) { moving = 0.25 - ((x[1] + 1 - 2*x[4])^2 + x[2]^2 + x[3]^2); }",
    { -1.6, -0.6, -0.6 }, { 1.6, 0.6, 0.6 }, M_PI * 0.25 * 2.0 + 4.0 / 3.0 * M_PI * 0.125 },
  { "turning blade (half a turn)", "blade",
    "blade(x[4], a[1]) { an = 3.141592653589793*x[4]; cs = cos(an); sn = sin(an);"
    " u = cs*x[1] + sn*x[2]; v = -sn*x[1] + cs*x[2];"
    " blade = min(min(1 - abs(u), 0.01 - abs(v)), 0.1 - abs(x[3])); }",
    { -1.1, -1.1, -0.15 }, { 1.1, 1.1, 0.15 }, M_PI * 1.0 * 0.2 }, // a disc of radius 1, 0.2 thick
};

std::shared_ptr<const frep::Model> load(const char* text)
{
  const frep::LoadedModel loaded = frep::load_model(frep::ModelSource::from_text(text));
  if (!loaded.ok())
    std::fprintf(stderr, "%s\n", loaded.message().c_str());
  return loaded.model;
}

// The union of `frames` frames t = i / (frames - 1): max over them (the set union exactly; the
// language's | is an R-function, whose zero set is not quite the union), one HyperFun object.
std::shared_ptr<const frep::Model> frame_union(const Case& c, int frames)
{
  std::string text = std::string(c.text) + "\nframes(x[3], a[1])\n{\n  array p[4];\n";
  text += "  p[1] = x[1];\n  p[2] = x[2];\n  p[3] = x[3];\n  p[4] = 0;\n";
  text += "  u = " + std::string(c.object) + "(p, a);\n";
  for (int i = 1; i < frames; ++i)
    text += "  p[4] = " + std::to_string(i) + "/" + std::to_string(frames - 1) + ";\n  u = max(u, " +
            c.object + "(p, a));\n";
  text += "  frames = u;\n}\n";
  frep::LoadOptions options;
  options.object = "frames";
  const frep::LoadedModel loaded = frep::load_model(frep::ModelSource::from_text(text), options);
  if (!loaded.ok())
    std::fprintf(stderr, "%s\n", loaded.message().c_str());
  return loaded.model;
}

struct Meshed
{
  double seconds = 0, volume = 0;
  std::size_t components = 0, triangles = 0;
};

Meshed mesh(const std::shared_ptr<const frep::Tape>& tape, const Case& c, int grid, int threads)
{
  const std::int64_t samples[3] = { grid, grid, grid };
  frep::mesh::ExtractOptions options;
  options.normals = false;
  options.attributes = false;
  options.threads = threads;
  const auto start = std::chrono::steady_clock::now();
  const frep::mesh::ExtractResult r =
    frep::mesh::extract_surface(tape, frep::box_grid(c.lo, c.hi, samples), options);
  Meshed m;
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const frep::mesh::MeshTopology t = frep::mesh::analyse_topology(r.surface);
  m.volume = t.signed_volume;
  m.components = t.components;
  m.triangles = t.triangles;
  return m;
}

// Probe points inside the sweep (P >= 1e-3) that the union leaves out (< 0).
int missed(const frep::Model& sweep, const frep::Model& u, const Case& c)
{
  frep::PointEvaluator p(sweep.tape()), q(u.tape());
  int count = 0;
  const int n = 64;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
      {
        const std::vector<double> x{ c.lo[0] + (c.hi[0] - c.lo[0]) * (i + 0.5) / n,
          c.lo[1] + (c.hi[1] - c.lo[1]) * (j + 0.5) / n, c.lo[2] + (c.hi[2] - c.lo[2]) * (k + 0.5) / n };
        if (p.value(x) >= 1e-3 && q.value(x) < 0)
          ++count;
      }
  return count;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<double> grids{ 128, 256 }, frames{ 64, 240 };
  int threads = 0;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    if (!std::strcmp(argv[i], "--grids"))
      grids = frep::bench::comma_numbers(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--frames"))
      frames = frep::bench::comma_numbers(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--threads"))
      threads = std::stoi(argv[i + 1]);
  }
  for (const Case& c : kCases)
  {
    const auto model = load(c.text);
    frep::project::ProjectionOptions options;
    options.tolerance = 1e-4;
    const frep::LoadedModel sweep = frep::project::project(model, { { 4, 0.0, 1.0 } }, options);
    if (!model || !sweep.ok())
      return 1;
    std::printf("%s (exact volume %.5f)\n", c.name, c.exact_volume);
    std::printf("  %-22s %5s %9s %9s %6s %10s %8s\n", "method", "grid", "seconds", "volume",
      "parts", "triangles", "missed");
    for (const double g : grids)
    {
      const Meshed p = mesh(sweep.model->tape(), c, int(g), threads);
      std::printf("  %-22s %5d %9.3f %9.5f %6zu %10zu %8s\n", "projection", int(g), p.seconds,
        p.volume, p.components, p.triangles, "-");
      for (const double n : frames)
      {
        const auto u = frame_union(c, int(n));
        const Meshed m = mesh(u->tape(), c, int(g), threads);
        const std::string label = "union of " + std::to_string(int(n)) + " frames";
        std::printf("  %-22s %5d %9.3f %9.5f %6zu %10zu %8d\n", label.c_str(), int(g), m.seconds,
          m.volume, m.components, m.triangles, missed(*sweep.model, *u, c));
      }
    }
  }
  return 0;
}
