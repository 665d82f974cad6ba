// VTK data as FRep: vtkPolyDataToFRep (signed distance of vtkSphereSource's closed mesh: the
// sign, the value against the exact sphere, meshing culls; an open plane refused naming its
// open edges; the unsigned mode), vtkImageDataToFRep (values at samples, an image without
// scalars refused), vtkImplicitFunctionToFRep (F = -f of a vtkSphere, no function refused),
// vtkHyperFunSource::AddShape (the mesh named inside a HyperFun program and blended), the
// keys published in RequestInformation, PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkDoubleArray.h"
#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkHyperFunSource.h"
#include "vtkImageData.h"
#include "vtkImageDataToFRep.h"
#include "vtkImplicitFunctionToFRep.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataToFRep.h"
#include "vtkSampleFunction.h"
#include "vtkSphere.h"
#include "vtkSphereSource.h"

#include "Eval/point_evaluator.h"
#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"

#include <cmath>
#include <sstream>

namespace
{

double value_at(vtkFRepObject* object, double x, double y, double z)
{
  frep::PointEvaluator e(object->GetTape());
  const double p[3] = { x, y, z };
  return e.value(p);
}

} // namespace

int TestShapeSources(int, char*[])
{
  int failures = 0;

  // A closed sphere mesh of radius 2.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(2.0);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataToFRep> mesh;
  mesh->SetInputConnection(sphere->GetOutputPort());
  mesh->SetFunctionName("ball");
  mesh->Update();
  vtkFRepObject* ball = mesh->GetOutput();
  FREPKIT_CHECK(failures, ball->HasModel());
  FREPKIT_CHECK(failures, ball->GetDimension() == 3);
  FREPKIT_CHECK(failures, ball->GetObjectName() == "ball_model");
  if (ball->HasModel())
  {
    FREPKIT_CHECK(failures, std::fabs(value_at(ball, 0, 0, 0) - 2.0) < 0.01);
    FREPKIT_CHECK(failures, std::fabs(value_at(ball, 3, 0, 0) + 1.0) < 0.01);
    FREPKIT_CHECK(failures, value_at(ball, 0, 1.9, 0) > 0);
    FREPKIT_CHECK(failures, value_at(ball, 0, 0, -2.1) < 0);
    double range[2];
    ball->GetCoordinateRange(0, range);
    FREPKIT_CHECK(failures, range[0] < -2.0 && range[0] > -3.5 && range[1] > 2.0);
    // Meshing culls (the distance's enclosures) and gives a closed surface.
    const frep::GridSpec grid{ { { -3, 3, 64 }, { -3, 3, 64 }, { -3, 3, 64 } } };
    const frep::mesh::ExtractResult r = frep::mesh::extract_surface(ball->GetTape(), grid);
    FREPKIT_CHECK(failures, r.ok());
    const frep::mesh::MeshTopology t = frep::mesh::analyse_topology(r.surface);
    FREPKIT_CHECK(failures, t.boundary_edges == 0 && t.euler_characteristic == 2);
    FREPKIT_CHECK(failures, r.statistics.boxes_culled > 0);
    FREPKIT_CHECK(failures, r.statistics.samples < r.statistics.dense_samples / 2);
  }
  // The keys are published before RequestData.
  {
    vtkNew<vtkPolyDataToFRep> planned;
    planned->SetInputData(sphere->GetOutput());
    planned->SetBounds(-5, 5, -4, 4, -3, 3);
    planned->UpdateInformation();
    vtkFRepInformation::Metadata m;
    FREPKIT_CHECK(failures, vtkFRepInformation::Get(planned->GetOutputInformation(0), m));
    FREPKIT_CHECK(failures, m.GetDimension() == 3 && m.ObjectName == "shape_model");
    FREPKIT_CHECK(failures, m.Ranges.size() == 3 && m.Ranges[1][0] == -4 && m.Ranges[2][1] == 3);
  }

  // An open mesh is refused, naming its open edges; unsigned distance accepts it.
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(2, 2);
  vtkNew<vtkPolyDataToFRep> open;
  open->SetInputConnection(plane->GetOutputPort());
  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(open);
  open->Update();
  FREPKIT_CHECK(failures, !open->GetOutput()->HasModel());
  FREPKIT_CHECK(failures, events->ErrorText.find("8 open edges") != std::string::npos);
  if (events->ErrorText.find("8 open edges") == std::string::npos)
  {
    std::cerr << "error was: " << events->ErrorText << "\n";
  }
  open->UnsignedDistanceOn();
  events->Clear();
  open->Update();
  FREPKIT_CHECK(failures, events->Errors == 0 && open->GetOutput()->HasModel());
  if (open->GetOutput()->HasModel())
  {
    FREPKIT_CHECK(failures, std::fabs(value_at(open->GetOutput(), 0, 0, 0.25) + 0.25) < 1e-12);
  }

  // A volume: F at a sample is the sample minus the iso value.
  vtkNew<vtkSphere> field;
  field->SetRadius(1.0);
  vtkNew<vtkSampleFunction> sampled;
  sampled->SetImplicitFunction(field);
  sampled->SetModelBounds(-2, 2, -2, 2, -2, 2);
  sampled->SetSampleDimensions(21, 21, 21);
  sampled->ComputeNormalsOff();
  vtkNew<vtkImageDataToFRep> volume;
  volume->SetInputConnection(sampled->GetOutputPort());
  volume->SetFunctionName("ct");
  volume->SetIsoValue(0.5);
  volume->Update();
  FREPKIT_CHECK(failures, volume->GetOutput()->HasModel());
  if (volume->GetOutput()->HasModel())
  {
    vtkImageData* image = sampled->GetOutput();
    const vtkIdType id = image->FindPoint(0.4, -0.6, 1.0);
    double p[3];
    image->GetPoint(id, p);
    const double sample = image->GetPointData()->GetScalars()->GetComponent(id, 0);
    FREPKIT_CHECK(failures, std::fabs(value_at(volume->GetOutput(), p[0], p[1], p[2]) - (sample - 0.5)) < 1e-9);
  }
  vtkNew<vtkImageData> empty;
  empty->SetDimensions(4, 4, 4);
  vtkNew<vtkImageDataToFRep> noScalars;
  noScalars->SetInputData(empty);
  vtkNew<frepkit_test::EventCounter> volumeEvents;
  volumeEvents->Observe(noScalars);
  noScalars->Update();
  FREPKIT_CHECK(failures, !noScalars->GetOutput()->HasModel());
  FREPKIT_CHECK(failures, volumeEvents->ErrorText.find("no point scalars") != std::string::npos);

  // Any vtkImplicitFunction: F = -f.
  vtkNew<vtkImplicitFunctionToFRep> implicit;
  implicit->SetImplicitFunction(field);
  implicit->SetFunctionName("vtksphere");
  implicit->Update();
  FREPKIT_CHECK(failures, implicit->GetOutput()->HasModel());
  if (implicit->GetOutput()->HasModel())
  {
    FREPKIT_CHECK(failures, value_at(implicit->GetOutput(), 0.5, 0, 0) == -(0.25 - 1.0));
  }
  const vtkMTimeType before = implicit->GetMTime();
  field->SetRadius(1.5);
  FREPKIT_CHECK(failures, implicit->GetMTime() > before);
  vtkNew<vtkImplicitFunctionToFRep> none;
  vtkNew<frepkit_test::EventCounter> noneEvents;
  noneEvents->Observe(none);
  none->Update();
  FREPKIT_CHECK(failures, noneEvents->ErrorText.find("no ImplicitFunction") != std::string::npos);
  vtkNew<vtkImplicitFunctionToFRep> badName;
  badName->SetImplicitFunction(field);
  badName->SetFunctionName("hfSphere");
  vtkNew<frepkit_test::EventCounter> nameEvents;
  nameEvents->Observe(badName);
  badName->Update();
  FREPKIT_CHECK(failures, nameEvents->ErrorText.find("library function") != std::string::npos);

  // The mesh named inside a HyperFun program and united with a library sphere.
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText("my_model(x[3], a[1]) { array c[3]; c = [3, 0, 0]; "
                       "my_model = ball(x) | hfSphere(x, c, 0.5); }");
  source->AddShape("ball", ball);
  source->Update();
  vtkFRepObject* united = source->GetOutput();
  FREPKIT_CHECK(failures, united->HasModel());
  if (united->HasModel())
  {
    FREPKIT_CHECK(failures, value_at(united, 0, 0, 0) > 1.9);
    FREPKIT_CHECK(failures, value_at(united, 3, 0, 0) > 0.2);
    FREPKIT_CHECK(failures, value_at(united, 0, 5, 0) < 0);
  }
  source->RemoveAllShapes();
  vtkNew<frepkit_test::EventCounter> sourceEvents;
  sourceEvents->Observe(source);
  source->Update();
  FREPKIT_CHECK(failures, sourceEvents->Errors > 0 && !source->GetOutput()->HasModel());
  source->AddUserLibrary("/nonexistent/libshapes.so");
  sourceEvents->Clear();
  source->Update();
  FREPKIT_CHECK(failures, sourceEvents->ErrorText.find("user library /nonexistent/libshapes.so: no such file") != std::string::npos);

  std::ostringstream print;
  mesh->Print(print);
  volume->Print(print);
  implicit->Print(print);
  source->Print(print);
  FREPKIT_CHECK(failures, print.str().find("FunctionName: ball") != std::string::npos);
  FREPKIT_CHECK(failures, print.str().find("IsoValue: 0.5") != std::string::npos);
  FREPKIT_CHECK(failures, print.str().find("UserLibraries (1)") != std::string::npos);

  return failures == 0 ? 0 : 1;
}
