// Meshing time, side by side on the same box and grid:
//   frepkit  — frep::mesh::extract_surface (interval culling, batch sampling of the surviving
//              leaves, marching cubes, caps, gradient normals), all cores; with and without
//              the per-box tape simplification (identical surfaces; the column "instructions
//              per sample" is the mean length of the tapes the samples ran);
//   vtk      — how it is done in VTK today: vtkSampleFunction over a vtkImplicitFunction that
//              calls the engine point by point (vtkFRepImplicitFunction), then vtkFlyingEdges3D,
//              STDThread SMP backend.
// Usage: frep_mesh_benchmark [--sizes 128,256,512] [--models sphere,csg,HF_sample,union200_chain]
//                            [--repeat 3] [--vtk-max-samples 3e7] [--jit 1]
// The VTK baseline is skipped (printed as "-") above --vtk-max-samples grid points: at 512^3 it
// takes minutes per model.
#include "benchmark_models.h"

#include "Compiler/model.h"
#include "Language/parser.h"
#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"

#include "vtkFRepImplicitFunction.h"
#include "vtkHyperFunSource.h"
#include "vtkFRepObject.h"

#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSampleFunction.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using Clock = std::chrono::steady_clock;

std::vector<std::string> split(const std::string& text)
{
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    out.push_back(item);
  }
  return out;
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Run
{
  double seconds = 0;
  std::size_t triangles = 0;
  std::size_t samples = 0;
  std::size_t sample_instructions = 0;
  double extract = 0, merge = 0, normals = 0; // seconds of the phases (ExtractStatistics)
  double cpu = 0; // processor seconds of all threads (robust to other load on the machine)
};

Run run_frepkit(const std::shared_ptr<const frep::Tape>& tape, const frep::bench::BenchModel& m,
  int n, bool simplify, bool jit, bool& closed)
{
  const std::array<std::int64_t, 3> samples{ n, n, n };
  const frep::GridSpec grid = frep::box_grid(m.lo, m.hi, samples);
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  frep::mesh::ExtractOptions options;
  options.simplify = simplify;
  options.jit = jit;
  const frep::mesh::ExtractResult r = frep::mesh::extract_surface(tape, grid, options);
  Run run;
  run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  run.cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  if (!r.ok())
  {
    std::cerr << m.name << ": " << r.error << "\n";
    std::exit(1);
  }
  run.triangles = r.surface.cell_count();
  run.samples = r.statistics.samples;
  run.sample_instructions = r.statistics.sample_instructions;
  run.extract = r.statistics.seconds_extract;
  run.merge = r.statistics.seconds_merge;
  run.normals = r.statistics.seconds_normals;
  closed = frep::mesh::analyse_topology(r.surface).watertight_and_oriented();
  return run;
}

Run run_vtk(const frep::bench::BenchModel& m, int n)
{
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(m.text.c_str());
  if (m.object != "my_model")
  {
    source->SetObjectName(m.object.c_str()); // else my_model, or the first object
  }
  source->Update();
  vtkNew<vtkFRepImplicitFunction> function;
  function->SetFRepObject(source->GetOutput());
  const auto start = Clock::now();
  vtkNew<vtkSampleFunction> sample;
  sample->SetImplicitFunction(function);
  sample->SetModelBounds(m.lo[0], m.hi[0], m.lo[1], m.hi[1], m.lo[2], m.hi[2]);
  sample->SetSampleDimensions(n, n, n);
  sample->ComputeNormalsOff();
  sample->SetOutputScalarTypeToDouble();
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputConnection(sample->GetOutputPort());
  contour->SetValue(0, 0.0); // the adaptor returns -F: the surface is still 0
  contour->ComputeNormalsOn();
  contour->Update();
  Run run;
  run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  run.triangles = static_cast<std::size_t>(contour->GetOutput()->GetNumberOfCells());
  run.samples = static_cast<std::size_t>(n) * n * n;
  return run;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<int> sizes{ 128, 256, 512 };
  std::vector<std::string> names{ "sphere", "csg", "HF_sample", "union200_chain",
    "union200_balanced" };
  int repeat = 3;
  double vtk_max_samples = 3e7;
  bool jit = true; // --jit 0: the interpreter only (ExtractOptions::jit)
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    const std::string value = argv[i + 1];
    if (option == "--sizes")
    {
      sizes.clear();
      for (const auto& s : split(value))
      {
        sizes.push_back(std::stoi(s));
      }
    }
    else if (option == "--models")
    {
      names = split(value);
    }
    else if (option == "--repeat")
    {
      repeat = std::max(1, std::stoi(value));
    }
    else if (option == "--vtk-max-samples")
    {
      vtk_max_samples = std::stod(value);
    }
    else if (option == "--jit")
    {
      jit = std::stoi(value) != 0;
    }
    else
    {
      std::cerr << "unknown option " << option << "\n";
      return 1;
    }
  }
  vtkSMPTools::SetBackend("STDThread");
  const auto models = frep::bench::benchmark_models(FREPKIT_SHARED_DIR);
  std::printf("| model | grid | frepkit (s) | cpu (s) | extract / merge / normals (s) | unsimplified (s) | cpu (s) | instructions per sample "
              "(unsimplified) | triangles | samples evaluated | closed | vtk baseline (s) "
              "| triangles | speed-up |\n|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---|---:|---:|---:|\n");
  for (const std::string& name : names)
  {
    const auto it = std::find_if(models.begin(), models.end(),
      [&](const frep::bench::BenchModel& m) { return m.name == name; });
    if (it == models.end())
    {
      std::cerr << "no model " << name << "\n";
      return 1;
    }
    const auto parsed = frep::parse_program(it->text, it->name);
    const int object = frep::ast::select_object(*parsed.program, it->object);
    const auto compiled = frep::Model::compile(parsed.program, object);
    const auto tape = compiled.model->tape();
    for (int n : sizes)
    {
      std::vector<double> times;
      Run ours, unsimplified;
      bool closed = false, closed_unsimplified = false;
      for (int r = 0; r < repeat; ++r)
      {
        ours = run_frepkit(tape, *it, n, true, jit, closed);
        times.push_back(ours.seconds);
      }
      const double frepkit_seconds = median(times);
      times.clear();
      for (int r = 0; r < repeat; ++r)
      {
        unsimplified = run_frepkit(tape, *it, n, false, jit, closed_unsimplified);
        times.push_back(unsimplified.seconds);
      }
      const double unsimplified_seconds = median(times);
      if (unsimplified.triangles != ours.triangles)
      {
        std::cerr << name << ": simplified and full tapes gave different surfaces\n";
        return 1;
      }
      std::string vtk_cell = "-", vtk_triangles = "-", speedup = "-";
      if (double(n) * n * n <= vtk_max_samples)
      {
        times.clear();
        Run theirs;
        for (int r = 0; r < repeat; ++r)
        {
          theirs = run_vtk(*it, n);
          times.push_back(theirs.seconds);
        }
        const double vtk_seconds = median(times);
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.3f", vtk_seconds);
        vtk_cell = buffer;
        vtk_triangles = std::to_string(theirs.triangles);
        std::snprintf(buffer, sizeof buffer, "%.1fx", vtk_seconds / frepkit_seconds);
        speedup = buffer;
      }
      const auto per_sample = [](const Run& run)
      { return run.samples ? double(run.sample_instructions) / double(run.samples) : 0.0; };
      std::printf("| %s | %d^3 | %.3f | %.3f | %.3f / %.3f / %.3f | %.3f | %.3f | %.1f (%.0f) | %zu | %.1f%% | %s | %s | %s | %s |\n",
        name.c_str(), n, frepkit_seconds, ours.cpu, ours.extract, ours.merge, ours.normals,
        unsimplified_seconds, unsimplified.cpu, per_sample(ours),
        per_sample(unsimplified), ours.triangles, 100.0 * double(ours.samples) / (double(n) * n * n),
        closed ? "yes" : "NO", vtk_cell.c_str(), vtk_triangles.c_str(), speedup.c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}
