// vtkFRepProjection: a 4-D ball projected along x4 is the 3-D ball (point values within the
// tolerance, a closed polygonised surface of the right volume); the output's keys in
// RequestInformation match the data; a slice of the input stays fixed; two coordinates at once;
// every bad request is one error and an empty output; an empty input is quiet; Set/Get, MTime,
// PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkFRepPolygonizer.h"
#include "vtkFRepProjection.h"
#include "vtkFRepSlice.h"
#include "vtkHyperFunSource.h"
#include "vtkInformation.h"
#include "vtkMassProperties.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include "Eval/point_evaluator.h"

#include <cmath>
#include <random>
#include <sstream>

namespace
{
// A ball of radius 1 in (x1, x2, x3, x4), shifted along x1 by x5 (a 5-D family of 4-D balls).
const char* Ball5D = R"(ball(x[5], a[1])
{
  ball = 1 - ((x[1] - x[5])^2 + x[2]^2 + x[3]^2 + x[4]^2);
}
)";

double Value(vtkFRepObject* object, std::vector<double> x)
{
  frep::PointEvaluator e(object->GetTape());
  return e.value(x);
}
}

int TestFRepProjection(int, char*[])
{
  int failures = 0;
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(Ball5D);
  vtkNew<vtkFRepSlice> slice; // x5 fixed at 0.5 upstream
  slice->SetInputConnection(source->GetOutputPort());
  slice->SetFixedValue(4, 0.5);
  vtkNew<vtkFRepProjection> projection;
  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(projection);
  projection->SetInputConnection(slice->GetOutputPort());

  // --- defaults
  FREPKIT_CHECK(failures, projection->GetProjectedCoordinate() == 3);
  FREPKIT_CHECK(failures, projection->GetProjectedRange()[0] == 0.0);
  FREPKIT_CHECK(failures, projection->GetProjectedRange()[1] == 1.0);
  FREPKIT_CHECK(failures, projection->GetTolerance() == 1e-4);
  FREPKIT_CHECK(failures, projection->GetBand() == 0.1);
  FREPKIT_CHECK(failures, projection->GetNumberOfAddedProjections() == 0);

  // --- x4 over [-1, 2]: the 3-D ball centred at x1 = 0.5; keys before data
  projection->SetProjectedRange(-1.0, 2.0);
  projection->UpdateInformation();
  vtkInformation* info = projection->GetOutputInformation(0);
  FREPKIT_CHECK(failures, vtkFRepInformation::Has(info));
  FREPKIT_CHECK(failures, info->Get(vtkFRepInformation::DIMENSION()) == 3);
  FREPKIT_CHECK(failures, info->Get(vtkFRepInformation::MODEL_DIMENSION()) == 5);
  projection->Update();
  vtkFRepObject* out = projection->GetOutput();
  FREPKIT_CHECK(failures, out->HasModel());
  FREPKIT_CHECK(failures, out->GetDimension() == 3);
  FREPKIT_CHECK(failures, out->GetModelDimension() == 5);
  FREPKIT_CHECK(failures, out->IsCoordinateFixed(3) && out->IsCoordinateFixed(4));
  FREPKIT_CHECK(failures, out->GetFixedValue(4) == 0.5);
  FREPKIT_CHECK(failures, out->GetCoordinateName(3) == "x4");
  FREPKIT_CHECK(failures, (out->GetFreeCoordinates() == std::vector<int>{ 0, 1, 2 }));
  FREPKIT_CHECK(failures, out->GetObjectName() == std::string(info->Get(vtkFRepInformation::OBJECT_NAME())));
  std::mt19937 random(28);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int wrong = 0;
  for (int i = 0; i < 500; ++i)
  {
    const double x = u(random), y = u(random), z = u(random);
    const double exact = 1 - ((x - 0.5) * (x - 0.5) + y * y + z * z);
    const double v = Value(out, { x, y, z });
    const bool ok = v <= exact + 1e-12 &&
      (v >= 0.1 || (v < -0.1 ? exact < -0.1 + 1e-4 : v >= exact - 1e-4));
    wrong += ok ? 0 : 1;
  }
  FREPKIT_CHECK(failures, wrong == 0);
  FREPKIT_CHECK(failures, events->Errors == 0);

  // --- polygonised: closed, the ball's volume
  vtkNew<vtkFRepPolygonizer> mesher;
  mesher->SetInputConnection(projection->GetOutputPort());
  mesher->SetSampleDimensions(40, 40, 40);
  mesher->SetModelBounds(-1.0, 2.0, -1.5, 1.5, -1.5, 1.5);
  mesher->Update();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(mesher->GetOutputPort());
  vtkNew<vtkMassProperties> mass;
  mass->SetInputConnection(triangles->GetOutputPort());
  mass->Update();
  FREPKIT_CHECK(failures, std::abs(mass->GetVolume() - 4.0 / 3.0 * M_PI) < 0.05);

  // --- two coordinates: x4 and x5 (released upstream) over [0, 1] each
  slice->ReleaseCoordinate(4);
  projection->SetProjectedRange(0.0, 1.0);
  projection->AddProjection(4, 0.0, 1.0);
  projection->SetBand(VTK_DOUBLE_MAX); // values within the tolerance everywhere
  FREPKIT_CHECK(failures, projection->GetNumberOfAddedProjections() == 1);
  projection->Update();
  out = projection->GetOutput();
  FREPKIT_CHECK(failures, out->GetDimension() == 3);
  // max over x4, x5 in [0, 1]: x4 = 0 and x5 = clamp(x1, 0, 1)
  FREPKIT_CHECK(failures, std::abs(Value(out, { 0.7, 0.2, 0.1 }) - (1 - 0.05)) < 1e-4);
  FREPKIT_CHECK(failures, std::abs(Value(out, { -0.5, 0.0, 0.0 }) - (1 - 0.25)) < 1e-4);
  projection->RemoveAllProjections();
  projection->SetBand(0.1);

  // --- bad requests: one error each, an empty output
  const auto refused = [&](const char* expected)
  { return frepkit_test::RefusedWithOneError(projection.GetPointer(), events.GetPointer(), expected); };
  projection->SetProjectedCoordinate(7);
  FREPKIT_CHECK(failures, refused("cannot project along coordinate 7: the model has 5"));
  projection->SetProjectedCoordinate(-1);
  FREPKIT_CHECK(failures, refused("no coordinate to project"));
  slice->SetFixedValue(3, 0.0);
  projection->SetProjectedCoordinate(3);
  FREPKIT_CHECK(failures, refused("is fixed by the input"));
  slice->ReleaseCoordinate(3);
  projection->SetProjectedRange(1.0, 0.0);
  FREPKIT_CHECK(failures, refused("lo <= hi"));
  projection->SetProjectedRange(0.0, 1.0);
  projection->SetTolerance(0.0);
  FREPKIT_CHECK(failures, refused("Tolerance must be > 0"));
  projection->SetTolerance(1e-4);
  projection->SetBand(1e-5);
  FREPKIT_CHECK(failures, refused("Band must be greater"));
  projection->SetBand(0.1);
  projection->AddProjection(0, -1, 1);
  projection->AddProjection(1, -1, 1);
  projection->AddProjection(2, -1, 1);
  projection->AddProjection(4, -1, 1);
  FREPKIT_CHECK(failures, refused("nothing would be left"));
  projection->RemoveAllProjections();
  events->Clear();
  projection->Update();
  FREPKIT_CHECK(failures, projection->GetOutput()->HasModel() && events->Errors == 0);

  // --- an empty input is quiet
  vtkNew<vtkHyperFunSource> broken;
  broken->SetModelText("this is not HyperFun");
  vtkNew<frepkit_test::EventCounter> brokenEvents;
  brokenEvents->Observe(broken);
  projection->SetInputConnection(broken->GetOutputPort());
  events->Clear();
  projection->Update();
  FREPKIT_CHECK(failures, !projection->GetOutput()->HasModel() && events->Errors == 0);

  // --- MTime and PrintSelf
  const vtkMTimeType before = projection->GetMTime();
  projection->SetTolerance(1e-4); // unchanged
  FREPKIT_CHECK(failures, projection->GetMTime() == before);
  projection->SetTolerance(2e-4);
  FREPKIT_CHECK(failures, projection->GetMTime() > before);
  std::ostringstream printed;
  projection->Print(printed);
  FREPKIT_CHECK(failures, printed.str().find("ProjectedCoordinate: 3") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("Band: 0.1") != std::string::npos);
  return failures == 0 ? 0 : 1;
}
