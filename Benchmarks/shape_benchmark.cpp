// The mesh distance of --shape / vtkPolyDataToFRep (FRep/Shapes/mesh_distance.h, a BVH with
// enclosures) against VTK's way on the same mesh:
//   1. cost per point: MeshDistance::value vs vtkImplicitPolyDataDistance::EvaluateFunction,
//      one thread, the same random points in the mesh's box grown by 20%;
//   2. meshing at N^3 (default 256) over that box: the engine's culled extractor on the model
//      `pebble(x)` (and the example's metamorphosis at x4 = 0.5) vs vtkImplicitPolyDataDistance +
//      vtkSampleFunction + vtkFlyingEdges3D (iso 0).
//   frep_shape_benchmark [MESH.stl] [N] [frep|vtk|all]
//     (default Examples/metamorphosis/pebble.stl, 256, all; "frep" or "vtk" meshes one way only)
#include "Compiler/model.h"
#include "Language/parser.h"
#include "Mesh/surface.h"
#include "Shapes/mesh_readers.h"
#include "Shapes/shape_functions.h"

#include <vtkCellArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkImplicitPolyDataDistance.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSampleFunction.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <random>
#include <string>

namespace
{

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::shared_ptr<const frep::Model> compile(const std::string& text,
  std::shared_ptr<const frep::UserFunctionRegistry> users)
{
  frep::ParseOptions o;
  o.user_functions = std::move(users);
  frep::ParseResult p = frep::parse_program(text, "<benchmark>", o);
  if (!p.ok())
  {
    std::cerr << p.diagnostics.front().format() << "\n";
    return nullptr;
  }
  return frep::Model::compile(p.program, 0).model;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string path =
    argc > 1 ? argv[1] : std::string(FREPKIT_SOURCE_DIR) + "/Examples/metamorphosis/pebble.stl";
  const int n = argc > 2 ? std::stoi(argv[2]) : 256;
  const std::string part = argc > 3 ? argv[3] : "all";
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  frep::shapes::MeshReadResult read = frep::shapes::read_mesh_file(path);
  if (!read.ok())
  {
    std::cerr << read.error << "\n";
    return 1;
  }
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  for (std::size_t i = 0; i < read.mesh.point_count(); ++i)
  {
    points->InsertNextPoint(&read.mesh.points[3 * i]);
  }
  vtkNew<vtkCellArray> cells;
  for (std::size_t t = 0; t < read.mesh.triangle_count(); ++t)
  {
    const vtkIdType ids[3] = { read.mesh.triangles[3 * t], read.mesh.triangles[3 * t + 1],
      read.mesh.triangles[3 * t + 2] };
    cells->InsertNextCell(3, ids);
  }
  poly->SetPoints(points);
  poly->SetPolys(cells);

  auto t0 = std::chrono::steady_clock::now();
  auto built = frep::shapes::MeshDistance::build(read.mesh, true);
  const double build_s = seconds_since(t0);
  if (!built.distance)
  {
    std::cerr << built.error << "\n";
    return 1;
  }
  t0 = std::chrono::steady_clock::now();
  vtkNew<vtkImplicitPolyDataDistance> vtk_distance;
  vtk_distance->SetInput(poly);
  const double vtk_build_s = seconds_since(t0);

  const std::array<double, 6> b = built.distance->bounds();
  double box[6];
  for (int k = 0; k < 3; ++k)
  {
    const double pad = 0.2 * (b[k + 3] - b[k]);
    box[2 * k] = b[k] - pad;
    box[2 * k + 1] = b[k + 3] + pad;
  }
  std::printf("mesh %s: %zu triangles; BVH build %.1f ms (%zu nodes), VTK locator build %.1f ms\n",
    path.c_str(), built.distance->triangle_count(), 1e3 * build_s, built.distance->node_count(),
    1e3 * vtk_build_s);

  // 1. Cost per point, one thread.
  const int count = 200000;
  std::mt19937 rng(1);
  std::vector<std::array<double, 3>> samples(count);
  for (auto& p : samples)
  {
    for (int k = 0; k < 3; ++k)
    {
      p[k] = std::uniform_real_distribution<double>(box[2 * k], box[2 * k + 1])(rng);
    }
  }
  double sum = 0;
  t0 = std::chrono::steady_clock::now();
  for (const auto& p : samples)
  {
    sum += built.distance->value(p);
  }
  const double ours = seconds_since(t0) / count;
  double vtk_sum = 0;
  double max_difference = 0;
  t0 = std::chrono::steady_clock::now();
  for (const auto& p : samples)
  {
    double x[3] = { p[0], p[1], p[2] };
    vtk_sum += -vtk_distance->EvaluateFunction(x);
  }
  const double theirs = seconds_since(t0) / count;
  for (int i = 0; i < 2000; ++i)
  {
    double x[3] = { samples[i][0], samples[i][1], samples[i][2] };
    max_difference = std::max(max_difference,
      std::fabs(built.distance->value(samples[i]) + vtk_distance->EvaluateFunction(x)));
  }
  std::printf("per point (1 thread, %d points): MeshDistance %.3f us, vtkImplicitPolyDataDistance "
              "%.3f us (%.1fx); largest |difference| over 2000 points %.2e (sums %.6g %.6g)\n",
    count, 1e6 * ours, 1e6 * theirs, theirs / ours, max_difference, sum, vtk_sum);

  // 2. Meshing at n^3.
  auto users = std::make_shared<frep::UserFunctionRegistry>();
  users->add(frep::shapes::mesh_function("pebble", built.distance));
  const auto shape = compile("shape(x[3], a[1]) { shape = pebble(x); }", users);
  const auto meta = compile("meta(x[3], a[1]) { mesh = pebble(x); "
                            "ring = 0.55 - sqrt((sqrt(x[1]^2 + x[2]^2) - 1.5)^2 + x[3]^2); "
                            "meta = mesh * 0.5 + ring * 0.5; }",
    users);
  if (!shape || !meta)
  {
    return 1;
  }
  frep::GridSpec grid;
  for (int k = 0; k < 3; ++k)
  {
    grid.axes.push_back({ box[2 * k], box[2 * k + 1], n });
  }
  frep::mesh::ExtractOptions options;
  options.normals = false; // as flying edges computes none below
  for (const auto& [name, model] : { std::pair{ "pebble(x)", shape }, std::pair{ "metamorphosis x4=0.5", meta } })
  {
    if (part == "vtk")
    {
      break;
    }
    t0 = std::chrono::steady_clock::now();
    const frep::mesh::ExtractResult r = frep::mesh::extract_surface(model->tape(), grid, options);
    const double s = seconds_since(t0);
    std::printf("FRepKit extract_surface %s at %d^3: %.2f s, %zu triangles, %zu of %zu samples "
                "evaluated, %zu of %zu boxes culled\n",
      name, n, s, r.surface.cell_count(), r.statistics.samples, r.statistics.dense_samples,
      r.statistics.boxes_culled, r.statistics.boxes_tested);
  }
  if (part == "frep")
  {
    return 0;
  }
  t0 = std::chrono::steady_clock::now();
  vtkNew<vtkSampleFunction> sampler;
  sampler->SetImplicitFunction(vtk_distance);
  sampler->SetModelBounds(box);
  sampler->SetSampleDimensions(n, n, n);
  sampler->ComputeNormalsOff();
  sampler->SetOutputScalarTypeToFloat();
  sampler->Update();
  const double sample_s = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  vtkNew<vtkFlyingEdges3D> edges;
  edges->SetInputConnection(sampler->GetOutputPort());
  edges->SetValue(0, 0.0);
  edges->ComputeNormalsOff();
  edges->Update();
  const double edges_s = seconds_since(t0);
  std::printf("VTK vtkImplicitPolyDataDistance + vtkSampleFunction + vtkFlyingEdges3D at %d^3: "
              "%.2f s (sampling %.2f s, flying edges %.2f s), %lld triangles; SMP backend %s, %d "
              "threads\n",
    n, sample_s + edges_s, sample_s, edges_s,
    static_cast<long long>(edges->GetOutput()->GetNumberOfCells()), vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads());
  return 0;
}
