// vtkFRepPolygonizer: closed, outward-oriented surfaces with the right volume and area, normals,
// s[] attributes, 2-D contours, pieces that add up to the whole, and clear errors.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepPolygonizer.h"
#include "vtkHyperFunSource.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFeatureEdges.h"
#include "vtkMassProperties.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <chrono>
#include <cmath>
#include <map>
#include <utility>

namespace
{
constexpr double pi = 3.14159265358979323846;

// Signed volume (> 0 when oriented outward) and the number of edges not shared by exactly two
// triangles in opposite directions.
std::pair<double, int> SignedVolumeAndBadEdges(vtkPolyData* mesh)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
  double volume = 0;
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType n;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k]);
      ++directed[{ ids[k], ids[(k + 1) % 3] }];
    }
    volume += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) / 6.0;
  }
  int bad = 0;
  for (const auto& [edge, count] : directed)
  {
    const auto back = directed.find({ edge.second, edge.first });
    bad += (count != 1 || back == directed.end() || back->second != 1) ? 1 : 0;
  }
  return { volume, bad };
}

vtkIdType BoundaryAndNonManifoldEdges(vtkPolyData* mesh)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(mesh);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfCells();
}
} // namespace

int TestFRepPolygonizer(int, char*[])
{
  int failures = 0;
  vtkNew<frepkit_test::EventCounter> events;

  // A sphere of radius 5; the box comes from the coordinate intervals.
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText("my_model(x[3], a[1], s[1]) { s[1] = x[3]; "
                       "my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2; }");
  for (int i = 0; i < 3; ++i)
  {
    source->SetCoordinateRange(i, -6, 6);
  }
  vtkNew<vtkFRepPolygonizer> mesher;
  mesher->SetInputConnection(source->GetOutputPort());
  mesher->SetSampleDimensions(128, 128, 128);
  mesher->Update();
  vtkPolyData* sphere = mesher->GetOutput();
  FREPKIT_CHECK(failures, sphere->GetNumberOfPolys() > 10000);
  FREPKIT_CHECK(failures, BoundaryAndNonManifoldEdges(sphere) == 0);
  const auto [volume, bad_edges] = SignedVolumeAndBadEdges(sphere);
  FREPKIT_CHECK(failures, bad_edges == 0);
  const double exact_volume = 4.0 / 3.0 * pi * 125.0;
  FREPKIT_CHECK(failures, std::abs(volume - exact_volume) < 0.01 * exact_volume);
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(sphere);
  mass->Update();
  FREPKIT_CHECK(failures, std::abs(mass->GetSurfaceArea() - 100 * pi) < pi);
  FREPKIT_CHECK(failures, mesher->GetNumberOfEvaluatedSamples() < 128u * 128u * 128u / 3);
  FREPKIT_CHECK(failures, mesher->GetNumberOfCulledBoxes() > 0);

  // Normals are outward and unit; "s" is s[1] = z.
  vtkDataArray* normals = sphere->GetPointData()->GetNormals();
  vtkDataArray* s = sphere->GetPointData()->GetArray("s");
  FREPKIT_CHECK(failures, normals && normals->GetNumberOfComponents() == 3);
  FREPKIT_CHECK(failures, s && s->GetNumberOfComponents() == 1);
  if (normals && s)
  {
    for (vtkIdType p = 0; p < sphere->GetNumberOfPoints(); p += 101)
    {
      double x[3], n[3];
      sphere->GetPoint(p, x);
      normals->GetTuple(p, n);
      const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      FREPKIT_CHECK(failures, (x[0] * n[0] + x[1] * n[1] + x[2] * n[2]) / r > 0.999);
      FREPKIT_CHECK(failures, std::abs(s->GetComponent(p, 0) - x[2]) < 1e-5);
    }
  }

  // Culling off: the same mesh (same triangle count), only slower.
  vtkNew<vtkFRepPolygonizer> dense;
  dense->SetInputConnection(source->GetOutputPort());
  dense->SetSampleDimensions(48, 48, 48);
  dense->CullingOff();
  dense->Update();
  mesher->SetSampleDimensions(48, 48, 48);
  mesher->Update();
  FREPKIT_CHECK(failures, dense->GetOutput()->GetNumberOfPolys() == mesher->GetOutput()->GetNumberOfPolys());
  FREPKIT_CHECK(failures, dense->GetNumberOfEvaluatedSamples() >= 48u * 48u * 48u);

  // Pieces: three slabs give the whole triangle count and each is only part of it.
  mesher->SetModelBounds(-6, 6, -6, 6, -2, 6); // cut by the box: caps on the bottom
  mesher->SetSampleDimensions(40, 40, 40);
  mesher->UpdatePiece(0, 1, 0);
  const vtkIdType whole = mesher->GetOutput()->GetNumberOfPolys();
  vtkIdType sum = 0;
  for (int piece = 0; piece < 3; ++piece)
  {
    mesher->UpdatePiece(piece, 3, 0);
    const vtkIdType part = mesher->GetOutput()->GetNumberOfPolys();
    FREPKIT_CHECK(failures, part > 0 && part < whole);
    sum += part;
  }
  FREPKIT_CHECK(failures, sum == whole);
  mesher->UpdatePiece(0, 1, 0);
  FREPKIT_CHECK(failures, BoundaryAndNonManifoldEdges(mesher->GetOutput()) == 0);

  // A 2-D object gives contour lines in z = 0: a circle of radius 3.
  vtkNew<vtkHyperFunSource> disc;
  disc->SetModelText("my_model(x[2], a[1]) { my_model = 9 - x[1]^2 - x[2]^2; }");
  disc->SetCoordinateRange(0, -4, 4);
  disc->SetCoordinateRange(1, -4, 4);
  vtkNew<vtkFRepPolygonizer> contour;
  contour->SetInputConnection(disc->GetOutputPort());
  contour->SetSampleDimensions(200, 200, 1);
  contour->Update();
  vtkPolyData* circle = contour->GetOutput();
  FREPKIT_CHECK(failures, circle->GetNumberOfLines() > 100 && circle->GetNumberOfPolys() == 0);
  double length = 0;
  vtkIdType n;
  const vtkIdType* ids;
  for (circle->GetLines()->InitTraversal(); circle->GetLines()->GetNextCell(n, ids);)
  {
    double a[3], b[3];
    circle->GetPoint(ids[0], a);
    circle->GetPoint(ids[1], b);
    FREPKIT_CHECK(failures, a[2] == 0.0);
    length += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]));
  }
  FREPKIT_CHECK(failures, std::abs(length - 6 * pi) < 0.01 * 6 * pi);

  // Progress is reported; an abort requested from a progress observer empties the output.
  {
    vtkNew<vtkFRepPolygonizer> watched;
    watched->SetInputConnection(source->GetOutputPort());
    watched->SetSampleDimensions(160, 160, 160);
    int progress_events = 0;
    bool abort = false;
    vtkNew<vtkCallbackCommand> on_progress;
    struct State
    {
      int* events;
      bool* abort;
    } state{ &progress_events, &abort };
    on_progress->SetClientData(&state);
    on_progress->SetCallback(
      [](vtkObject* caller, unsigned long, void* data, void*)
      {
        auto* st = static_cast<State*>(data);
        ++*st->events;
        if (*st->abort)
        {
          static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
        }
      });
    watched->AddObserver(vtkCommand::ProgressEvent, on_progress);
    watched->Update();
    FREPKIT_CHECK(failures, progress_events > 2);
    FREPKIT_CHECK(failures, watched->GetOutput()->GetNumberOfPolys() > 0);
    abort = true;
    watched->Modified();
    watched->Update();
    FREPKIT_CHECK(failures, watched->GetOutput()->GetNumberOfPolys() == 0);
  }

  // Bad requests: clear errors, empty outputs, no crash, nothing slow.
  events->Observe(mesher);
  mesher->SetSampleDimensions(1, 40, 40);
  mesher->Update();
  FREPKIT_CHECK(failures, events->Errors == 1 && mesher->GetOutput()->GetNumberOfPoints() == 0);
  FREPKIT_CHECK(failures, events->ErrorText.find("at least 2 samples") != std::string::npos);
  events->Clear();
  const auto start = std::chrono::steady_clock::now();
  mesher->SetSampleDimensions(100000, 100000, 100000);
  mesher->Update();
  FREPKIT_CHECK(failures, events->Errors == 1 && mesher->GetOutput()->GetNumberOfPoints() == 0);
  FREPKIT_CHECK(failures,
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 1.0);
  events->Clear();
  mesher->SetSampleDimensions(16, 16, 16);
  mesher->SetModelBounds(1, 1, -6, 6, -6, 6); // zero size
  mesher->Update();
  FREPKIT_CHECK(failures, events->Errors == 1 && events->ErrorText.find("box") != std::string::npos);
  events->Clear();

  // Nothing in the box: empty output, no error.
  mesher->SetModelBounds(7, 9, 7, 9, 7, 9);
  mesher->Update();
  FREPKIT_CHECK(failures, events->Errors == 0 && mesher->GetOutput()->GetNumberOfPolys() == 0);

  // A 4-D object cannot be meshed without a slice; a broken model gives an empty output.
  vtkNew<vtkHyperFunSource> four;
  four->SetModelText("my_model(x[4], a[1]) { my_model = 1 - x[1]^2 - x[4]^2; }");
  vtkNew<vtkFRepPolygonizer> four_mesher;
  four_mesher->SetInputConnection(four->GetOutputPort());
  events->Observe(four_mesher);
  four_mesher->Update();
  FREPKIT_CHECK(failures, events->Errors == 1 &&
      events->ErrorText.find("4 free coordinates") != std::string::npos);
  events->Clear();
  vtkNew<vtkHyperFunSource> broken;
  broken->SetModelText("my_model(x[3], a[1]) { my_model = ; }");
  events->Observe(broken);
  vtkNew<vtkFRepPolygonizer> broken_mesher;
  broken_mesher->SetInputConnection(broken->GetOutputPort());
  events->Observe(broken_mesher);
  broken_mesher->Update();
  FREPKIT_CHECK(failures, events->Errors >= 1 && broken_mesher->GetOutput()->GetNumberOfPoints() == 0);
  FREPKIT_CHECK(failures, events->ErrorText.find("<string>:1:") != std::string::npos);

  return failures == 0 ? 0 : 1;
}
