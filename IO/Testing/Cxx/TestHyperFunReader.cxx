// vtkHyperFunReader: port 0 is vtkHyperFunSource's object, port 1 the default mesh (x1..x3
// free, further coordinates at their midpoints), object names default-first, pieces of port 1
// that add up to the whole, GenerateGeometry, and errors reported once with file:line:col.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepObject.h"
#include "vtkFRepPolygonizer.h"
#include "vtkHyperFunReader.h"
#include "vtkHyperFunSource.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTrivialConsumer.h"

#include <cmath>
#include <string>

namespace
{
// A 4-D ball whose radius grows with x4: r = 2 + x4; x4 in [0, 2] has midpoint 1 (radius 3).
const char* const Program = "helper(x[3], a[1]) { helper = 1 - x[1]^2; }\n"
                            "my_model(x[4], a[1]) {\n"
                            "  my_model = (2 + x[4])^2 - x[1]^2 - x[2]^2 - x[3]^2;\n"
                            "}\n";
}

int TestHyperFunReader(int, char*[])
{
  int failures = 0;
  vtkNew<frepkit_test::EventCounter> events;

  vtkNew<vtkHyperFunReader> reader;
  events->Observe(reader);
  FREPKIT_CHECK(failures, reader->GetNumberOfOutputPorts() == 2);
  FREPKIT_CHECK(failures, reader->GetGenerateGeometry() == 1);
  FREPKIT_CHECK(failures, reader->GetGeometryResolution() == 64);
  reader->SetGeometryResolution(1);
  FREPKIT_CHECK(failures, reader->GetGeometryResolution() == 2); // clamped
  reader->SetGeometryResolution(41);
  reader->SetModelText(Program);
  reader->SetCoordinateRange(3, 0.0, 2.0);
  reader->SetDefaultCoordinateRange(-4.0, 4.0);

  // Names: the default object (my_model) first, after RequestInformation only.
  reader->UpdateInformation();
  vtkStringArray* names = reader->GetObjectNames();
  FREPKIT_CHECK(failures, names->GetNumberOfValues() == 2);
  if (names->GetNumberOfValues() == 2)
  {
    FREPKIT_CHECK(failures, names->GetValue(0) == "my_model");
    FREPKIT_CHECK(failures, names->GetValue(1) == "helper");
  }

  reader->Update();
  vtkFRepObject* object = reader->GetOutput();
  vtkPolyData* mesh = reader->GetGeometryOutput();
  FREPKIT_CHECK(failures, object && object->HasModel() && object->GetDimension() == 4);
  FREPKIT_CHECK(failures, mesh != nullptr);
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  if (!object || !mesh)
  {
    return 1;
  }
  // The same object as vtkHyperFunSource's.
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(Program);
  source->SetCoordinateRange(3, 0.0, 2.0);
  source->SetDefaultCoordinateRange(-4.0, 4.0);
  source->Update();
  FREPKIT_CHECK(failures, source->GetOutput()->GetModelDimension() == 4);
  for (int i = 0; i < 4; ++i)
  {
    double a[2], b[2];
    object->GetCoordinateRange(i, a);
    source->GetOutput()->GetCoordinateRange(i, b);
    FREPKIT_CHECK(failures, a[0] == b[0] && a[1] == b[1]);
    FREPKIT_CHECK(failures, !object->IsCoordinateFixed(i));
  }

  // The mesh is the ball of radius 3 (x4 = 1, its interval's midpoint) sampled on 41^3.
  FREPKIT_CHECK(failures, mesh->GetNumberOfPolys() > 1000);
  double bounds[6];
  mesh->GetBounds(bounds);
  for (int a = 0; a < 3; ++a)
  {
    FREPKIT_CHECK(failures, std::fabs(bounds[2 * a] + 3.0) < 0.05);
    FREPKIT_CHECK(failures, std::fabs(bounds[2 * a + 1] - 3.0) < 0.05);
  }
  // Field data name the cross-section.
  auto* fixed = vtkDoubleArray::SafeDownCast(mesh->GetFieldData()->GetArray("FRepFixedValues"));
  auto* dimension = vtkIntArray::SafeDownCast(mesh->GetFieldData()->GetArray("FRepDimension"));
  FREPKIT_CHECK(failures, fixed && fixed->GetNumberOfTuples() == 4);
  FREPKIT_CHECK(failures, dimension && dimension->GetValue(0) == 3);
  if (fixed && fixed->GetNumberOfTuples() == 4)
  {
    FREPKIT_CHECK(failures, std::isnan(fixed->GetValue(0)) && fixed->GetValue(3) == 1.0);
  }
  // Exactly the polygoniser's mesh of that slice.
  vtkNew<vtkFRepObject> slice;
  slice->ShallowCopy(source->GetOutput());
  slice->FixCoordinate(3, 1.0);
  vtkNew<vtkFRepPolygonizer> polygonizer;
  polygonizer->SetInputData(slice);
  polygonizer->SetSampleDimensions(41, 41, 41);
  polygonizer->Update();
  FREPKIT_CHECK(failures,
    polygonizer->GetOutput()->GetNumberOfPolys() == mesh->GetNumberOfPolys() &&
      polygonizer->GetOutput()->GetNumberOfPoints() == mesh->GetNumberOfPoints());
  const vtkIdType whole = mesh->GetNumberOfPolys();

  // Pieces of port 1 add up to the whole mesh; port 0 stays the whole object.
  vtkIdType sum = 0;
  for (int piece = 0; piece < 3; ++piece)
  {
    // A request on port 1 (as a consumer of the mesh makes it), after one on port 0.
    reader->UpdatePiece(0, 1, 0);
    vtkInformation* info = reader->GetOutputInformation(1);
    info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), piece);
    info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 3);
    info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    reader->Update(1);
    vtkPolyData* part = reader->GetGeometryOutput();
    FREPKIT_CHECK(failures, part->GetNumberOfPolys() > 0 && part->GetNumberOfPolys() < whole);
    sum += part->GetNumberOfPolys();
    FREPKIT_CHECK(failures, reader->GetOutput()->HasModel());
  }
  FREPKIT_CHECK(failures, sum == whole);
  reader->UpdatePiece(0, 1, 0);
  reader->GetOutputInformation(1)->Set(
    vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  reader->GetOutputInformation(1)->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);

  // One process (DISTRIBUTED RUNS): with a consumer on port 1, an update of port 0 still meshes
  // port 1 (and the request of port 1's own consumer, piece 1 of 2, then meshes that piece
  // only). The parallel case, where a port-0 update leaves port 1 alone, is
  // checked by the plug-in's MPI test (ctest -R ParaViewPlugin-MPI).
  {
    vtkNew<vtkHyperFunReader> lazy;
    lazy->SetGeometryResolution(41);
    lazy->SetModelText(Program);
    lazy->SetCoordinateRange(3, 0.0, 2.0);
    lazy->SetDefaultCoordinateRange(-4.0, 4.0);
    vtkNew<vtkTrivialConsumer> consumer;
    consumer->SetInputConnection(lazy->GetOutputPort(1));
    lazy->Update(0);
    FREPKIT_CHECK(failures, lazy->GetOutput()->HasModel());
    FREPKIT_CHECK(failures, lazy->GetGeometryOutput()->GetNumberOfPolys() == whole);
    auto requestPiece = [&](int piece)
    {
      vtkInformation* info = lazy->GetOutputInformation(1);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), piece);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 2);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
      lazy->Update(1);
    };
    requestPiece(1);
    const vtkIdType half = lazy->GetGeometryOutput()->GetNumberOfPolys();
    FREPKIT_CHECK(failures, half > 0 && half < whole);
    requestPiece(0);
    const vtkIdType other = lazy->GetGeometryOutput()->GetNumberOfPolys();
    FREPKIT_CHECK(failures, other > 0 && other + half == whole);
  }

  // A 2-D object: a contour (lines); GenerateGeometry off: an empty port 1.
  reader->SetModelText("disc(x[2], a[1]) { disc = 4 - x[1]^2 - x[2]^2; }");
  reader->Update();
  FREPKIT_CHECK(failures, reader->GetOutput()->GetDimension() == 2);
  FREPKIT_CHECK(failures, reader->GetGeometryOutput()->GetNumberOfLines() > 50);
  FREPKIT_CHECK(failures, reader->GetGeometryOutput()->GetNumberOfPolys() == 0);
  reader->GenerateGeometryOff();
  reader->Update();
  FREPKIT_CHECK(failures, reader->GetOutput()->HasModel());
  FREPKIT_CHECK(failures, reader->GetGeometryOutput()->GetNumberOfCells() == 0);
  reader->GenerateGeometryOn();

  // A syntax error: one error naming <string>:line:col, empty outputs, no names; fixed again,
  // everything is back.
  events->Clear();
  reader->SetModelText("my_model(x[3], a[1])\n{\n  my_model = 1 - * x[1];\n}\n");
  reader->Update();
  FREPKIT_CHECK(failures, events->Errors >= 1);
  FREPKIT_CHECK(failures, events->ErrorText.find("<string>:3:") != std::string::npos);
  FREPKIT_CHECK(failures, !reader->GetOutput()->HasModel());
  FREPKIT_CHECK(failures, reader->GetGeometryOutput()->GetNumberOfCells() == 0);
  FREPKIT_CHECK(failures, reader->GetObjectNames()->GetNumberOfValues() == 0);
  events->Clear();
  reader->SetModelText(Program);
  reader->Update();
  FREPKIT_CHECK(failures, events->Errors == 0);
  FREPKIT_CHECK(failures, reader->GetGeometryOutput()->GetNumberOfPolys() == whole);
  FREPKIT_CHECK(failures, reader->GetObjectNames()->GetNumberOfValues() == 2);

  // The default mesh reports progress through the reader, and an abort stops it.
  {
    vtkNew<vtkHyperFunReader> meshing;
    meshing->SetModelText(Program);
    meshing->SetGeometryResolution(128);
    double last = -1;
    int progressEvents = 0;
    struct Watch
    {
      double* last;
      int* count;
    } watch{ &last, &progressEvents };
    vtkNew<vtkCallbackCommand> onProgress;
    onProgress->SetClientData(&watch);
    onProgress->SetCallback(
      [](vtkObject*, unsigned long, void* w, void* data)
      {
        auto* watch = static_cast<Watch*>(w);
        *watch->last = *static_cast<double*>(data);
        ++*watch->count;
      });
    meshing->AddObserver(vtkCommand::ProgressEvent, onProgress);
    meshing->Update();
    FREPKIT_CHECK(failures, progressEvents > 2);
    FREPKIT_CHECK(failures, meshing->GetGeometryOutput()->GetNumberOfPolys() > 0);

    vtkNew<vtkHyperFunReader> aborted;
    aborted->SetModelText(Program);
    // 128^3 samples are 64 blocks of the mesher: the thread that may call observers reports
    // between 0 and 1 many times. At 48^3 (8 blocks) the other worker could finish all but the
    // last block while this one was descheduled, and no report came before 1 (seen under load).
    aborted->SetGeometryResolution(128);
    vtkNew<vtkCallbackCommand> abort;
    abort->SetCallback(
      [](vtkObject* caller, unsigned long, void*, void* data)
      {
        if (*static_cast<double*>(data) > 0.0 && *static_cast<double*>(data) < 1.0)
        {
          static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
        }
      });
    aborted->AddObserver(vtkCommand::ProgressEvent, abort);
    aborted->Update();
    FREPKIT_CHECK(failures, aborted->GetGeometryOutput()->GetNumberOfPolys() == 0);
  }

  // A missing file: one error naming it.
  events->Clear();
  reader->SetFileName("/nonexistent/model.hf");
  reader->Update();
  FREPKIT_CHECK(failures, events->Errors == 1);
  FREPKIT_CHECK(failures, events->ErrorText.find("/nonexistent/model.hf") != std::string::npos);
  FREPKIT_CHECK(failures, reader->GetGeometryOutput()->GetNumberOfCells() == 0);

  reader->Print(std::cout);
  return failures == 0 ? 0 : 1;
}
