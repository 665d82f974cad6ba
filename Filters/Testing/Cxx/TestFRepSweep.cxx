// vtkFRepSweep: a ball of radius 0.5 swept along a segment is the capsule (point values within
// the tolerance at 500 points, a closed polygonised surface of the capsule's volume); the
// output's keys in RequestInformation match the data (dimension, names, the ranges swept along
// the path); a slice of a 4-D model is a profile; the tangent orientation turns a long profile;
// every bad request is one error and an empty output; an empty input is quiet; Set/Get, MTime,
// PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkFRepPolygonizer.h"
#include "vtkFRepSlice.h"
#include "vtkFRepSweep.h"
#include "vtkHyperFunSource.h"
#include "vtkInformation.h"
#include "vtkMassProperties.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include "Eval/point_evaluator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

namespace
{
// A ball of radius 0.5 whose x4 stretches it along x3 (x4 = 0: the ball; 1: a cigar).
const char* Ball4D = R"(ball(x[4], a[1])
{
  ball = 0.25 - (x[1]^2 + x[2]^2 + (x[3] / (1 + 4 * x[4]))^2);
}
)";

double Value(vtkFRepObject* object, std::vector<double> x)
{
  frep::PointEvaluator e(object->GetTape());
  return e.value(x);
}
}

int TestFRepSweep(int, char*[])
{
  int failures = 0;
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(Ball4D);
  vtkNew<vtkFRepSlice> slice; // the ball: x4 fixed at 0 upstream
  slice->SetInputConnection(source->GetOutputPort());
  slice->SetFixedValue(3, 0.0);
  vtkNew<vtkFRepSweep> sweep;
  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(sweep);
  sweep->SetInputConnection(slice->GetOutputPort());

  // --- defaults
  FREPKIT_CHECK(failures, sweep->GetNumberOfPathPoints() == 0);
  FREPKIT_CHECK(failures, sweep->GetCurve() == vtkFRepSweep::POLYLINE);
  FREPKIT_CHECK(failures, !sweep->GetClosed());
  FREPKIT_CHECK(failures, sweep->GetOrientation() == vtkFRepSweep::FIXED);
  FREPKIT_CHECK(failures, sweep->GetTolerance() == 1e-4);
  FREPKIT_CHECK(failures, sweep->GetBand() == 0.1);

  // --- along (-1, 0, 0) -> (1, 0, 0): the capsule; keys before data
  for (int axis = 0; axis < 3; ++axis)
  {
    source->SetCoordinateRange(axis, -0.5, 0.5);
  }
  sweep->AddPathPoint(-1, 0, 0);
  sweep->AddPathPoint(1, 0, 0);
  double p[3];
  sweep->GetPathPoint(1, p);
  FREPKIT_CHECK(failures, p[0] == 1 && p[1] == 0 && p[2] == 0);
  sweep->UpdateInformation();
  vtkInformation* info = sweep->GetOutputInformation(0);
  FREPKIT_CHECK(failures, vtkFRepInformation::Has(info));
  FREPKIT_CHECK(failures, info->Get(vtkFRepInformation::DIMENSION()) == 3);
  FREPKIT_CHECK(failures, info->Get(vtkFRepInformation::MODEL_DIMENSION()) == 3);
  sweep->Update();
  vtkFRepObject* out = sweep->GetOutput();
  FREPKIT_CHECK(failures, out->HasModel() && events->Errors == 0);
  FREPKIT_CHECK(failures, out->GetDimension() == 3);
  FREPKIT_CHECK(failures, out->GetCoordinateName(2) == "x3");
  FREPKIT_CHECK(failures, out->GetObjectName() == std::string(info->Get(vtkFRepInformation::OBJECT_NAME())));
  double range[2];
  out->GetCoordinateRange(0, range);
  FREPKIT_CHECK(failures, range[0] == -1.5 && range[1] == 1.5);
  out->GetCoordinateRange(1, range);
  FREPKIT_CHECK(failures, range[0] == -0.5 && range[1] == 0.5);
  vtkFRepInformation::Metadata keys;
  FREPKIT_CHECK(failures, vtkFRepInformation::Get(info, keys) && keys.Ranges[0][1] == 1.5);
  std::mt19937 random(29);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  int inside = 0;
  for (int i = 0; i < 500; ++i)
  {
    const double x = u(random), y = u(random) * 0.4, z = u(random) * 0.4;
    const double along = std::clamp(x, -1.0, 1.0);
    const double exact = 0.25 - ((x - along) * (x - along) + y * y + z * z);
    const double v = Value(out, { x, y, z });
    if (std::abs(exact) < 0.1) // within the band: the value to the tolerance
    {
      FREPKIT_CHECK(failures, v <= exact + 1e-9 && v >= exact - 1e-4 - 1e-9);
    }
    FREPKIT_CHECK(failures, (v >= 0) == (exact >= 0) || std::abs(exact) < 1e-4);
    inside += v >= 0;
  }
  FREPKIT_CHECK(failures, inside > 50);

  // --- polygonised over the output's ranges: closed, the capsule's volume
  vtkNew<vtkFRepPolygonizer> mesher;
  mesher->SetInputConnection(sweep->GetOutputPort());
  mesher->SetSampleDimensions(48, 24, 24);
  mesher->SetModelBounds(-1.6, 1.6, -0.6, 0.6, -0.6, 0.6);
  mesher->Update();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(mesher->GetOutputPort());
  vtkNew<vtkMassProperties> mass;
  mass->SetInputConnection(triangles->GetOutputPort());
  mass->Update();
  const double capsule = M_PI * 0.25 * 2 + 4.0 / 3.0 * M_PI * 0.125;
  FREPKIT_CHECK(failures, std::abs(mass->GetVolume() - capsule) < 0.03 * capsule);

  // --- a long profile (x4 = 1: semi-axis 2.5 along z) turned by the tangent lies along x
  slice->SetFixedValue(3, 1.0);
  sweep->RemoveAllPathPoints();
  sweep->AddPathPoint(0, 0, 0);
  sweep->AddPathPoint(0.001, 0, 0);
  sweep->SetOrientationToTangent();
  sweep->Update();
  FREPKIT_CHECK(failures, Value(sweep->GetOutput(), { 2.0, 0, 0 }) > 0);
  FREPKIT_CHECK(failures, Value(sweep->GetOutput(), { 0, 0, 2.0 }) < 0);
  sweep->SetOrientationToFixed();
  sweep->Update();
  FREPKIT_CHECK(failures, Value(sweep->GetOutput(), { 2.0, 0, 0 }) < 0);
  FREPKIT_CHECK(failures, Value(sweep->GetOutput(), { 0, 0, 2.0 }) > 0);
  sweep->SetCurveToCatmullRom();
  sweep->AddPathPoint(0.001, 1, 0);
  sweep->ClosedOn();
  events->Clear();
  sweep->Update();
  FREPKIT_CHECK(failures, sweep->GetOutput()->HasModel() && events->Errors == 0);
  sweep->ClosedOff();
  sweep->SetCurveToPolyline();

  // --- bad requests: one error each, an empty output
  const auto refused = [&](const char* expected)
  { return frepkit_test::RefusedWithOneError(sweep.GetPointer(), events.GetPointer(), expected); };
  slice->ReleaseCoordinate(3);
  FREPKIT_CHECK(failures, refused("the profile must have 3 free coordinates (it has 4)"));
  slice->SetFixedValue(3, 0.0);
  sweep->RemoveAllPathPoints();
  sweep->AddPathPoint(0, 0, 0);
  FREPKIT_CHECK(failures, refused("at least 2 points"));
  sweep->AddPathPoint(0, 0, 0);
  FREPKIT_CHECK(failures, refused("are the same"));
  sweep->RemoveAllPathPoints();
  sweep->AddPathPoint(0, 0, 0);
  sweep->AddPathPoint(NAN, 0, 0);
  FREPKIT_CHECK(failures, refused("not finite"));
  sweep->RemoveAllPathPoints();
  sweep->AddPathPoint(0, 0, 0);
  sweep->AddPathPoint(1, 0, 0);
  sweep->SetTolerance(0.0);
  FREPKIT_CHECK(failures, refused("Tolerance must be > 0"));
  sweep->SetTolerance(1e-4);
  sweep->SetBand(1e-5);
  FREPKIT_CHECK(failures, refused("Band must be greater"));
  sweep->SetBand(0.1);
  events->Clear();
  sweep->Update();
  FREPKIT_CHECK(failures, sweep->GetOutput()->HasModel() && events->Errors == 0);

  // --- an empty input is quiet
  vtkNew<vtkHyperFunSource> broken;
  broken->SetModelText("this is not HyperFun");
  vtkNew<frepkit_test::EventCounter> brokenEvents;
  brokenEvents->Observe(broken);
  sweep->SetInputConnection(broken->GetOutputPort());
  events->Clear();
  sweep->Update();
  FREPKIT_CHECK(failures, !sweep->GetOutput()->HasModel() && events->Errors == 0);

  // --- MTime and PrintSelf
  const vtkMTimeType before = sweep->GetMTime();
  sweep->SetTolerance(1e-4); // unchanged
  FREPKIT_CHECK(failures, sweep->GetMTime() == before);
  sweep->RemoveAllPathPoints();
  FREPKIT_CHECK(failures, sweep->GetMTime() > before);
  std::ostringstream printed;
  sweep->SetOrientationToTangent();
  sweep->AddPathPoint(1, 2, 3);
  sweep->Print(printed);
  FREPKIT_CHECK(failures, printed.str().find("PathPoints: (1, 2, 3)") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("Orientation: Tangent") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("Band: 0.1") != std::string::npos);
  return failures == 0 ? 0 : 1;
}
