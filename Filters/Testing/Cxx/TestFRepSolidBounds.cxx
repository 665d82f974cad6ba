// vtkHyperFunSource's default intervals are the solid's own bounds (UseSolidBounds, issue 32):
// a unit ball gets about [-1.05, 1.05] on every axis, a 4-D ball on all four, a half-space warns
// once and keeps DefaultCoordinateRange, a range set wins, x1..x3 of a blend cover the sections
// at the corners of x4's range, and a slice of a unit 4-D ball meshes at the full resolution
// without a range anywhere.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepObject.h"
#include "vtkFRepPolygonizer.h"
#include "vtkFRepSlice.h"
#include "vtkHyperFunSource.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <string>

namespace
{
const char* Ball3 = "my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }";
const char* Ball4 = "my_model(x[4], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2; }";
const char* HalfSpace = "my_model(x[3], a[1]) { my_model = a[1] - x[1]; }";
// Two unit balls at x1 = -3 and x1 = 3, blended linearly by x4: A at x4 = 0, B at x4 = 1, and
// nothing at x4 = 0.5 (the mean of the two is below 0 everywhere).
const char* Blend = R"(my_model(x[4], a[1])
{
  ba = 1 - (x[1] + 3)^2 - x[2]^2 - x[3]^2;
  bb = 1 - (x[1] - 3)^2 - x[2]^2 - x[3]^2;
  my_model = (1 - x[4]) * ba + x[4] * bb;
})";

// The interval is about [lo, hi] with the search's 5% margin: within `slack` outside it, never
// inside it.
bool About(const double range[2], double lo, double hi, double slack)
{
  const bool ok =
    range[0] <= lo && range[0] >= lo - slack && range[1] >= hi && range[1] <= hi + slack;
  if (!ok)
  {
    std::cerr << "range [" << range[0] << ", " << range[1] << "], expected about [" << lo << ", "
              << hi << "]\n";
  }
  return ok;
}
}

int TestFRepSolidBounds(int, char*[])
{
  int failures = 0;
  vtkNew<frepkit_test::EventCounter> events;
  double range[2];

  // --- a unit ball: every axis about [-1, 1] plus the margin, in the source and its output
  vtkNew<vtkHyperFunSource> ball;
  events->Observe(ball);
  ball->SetModelText(Ball3);
  ball->UpdateInformation();
  for (int i = 0; i < 3; ++i)
  {
    ball->GetCoordinateRange(i, range);
    FREPKIT_CHECK(failures, About(range, -1.0, 1.0, 0.2));
  }
  ball->Update();
  for (int i = 0; i < 3; ++i)
  {
    ball->GetOutput()->GetCoordinateRange(i, range);
    FREPKIT_CHECK(failures, About(range, -1.0, 1.0, 0.2));
  }
  // a range set wins, the others are still the ball's
  ball->SetCoordinateRange(0, -3, 3);
  ball->Update();
  ball->GetOutput()->GetCoordinateRange(0, range);
  FREPKIT_CHECK(failures, range[0] == -3 && range[1] == 3);
  ball->GetOutput()->GetCoordinateRange(1, range);
  FREPKIT_CHECK(failures, About(range, -1.0, 1.0, 0.2));
  // off: hfp's box
  ball->UseSolidBoundsOff();
  ball->Update();
  ball->GetOutput()->GetCoordinateRange(1, range);
  FREPKIT_CHECK(failures, range[0] == -10 && range[1] == 10);
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);

  // --- a 4-D ball: bounded as a whole, so x4 gets its bounds too
  vtkNew<vtkHyperFunSource> ball4;
  events->Observe(ball4);
  ball4->SetModelText(Ball4);
  ball4->Update();
  for (int i = 0; i < 4; ++i)
  {
    ball4->GetOutput()->GetCoordinateRange(i, range);
    FREPKIT_CHECK(failures, About(range, -1.0, 1.0, 0.2));
  }

  // --- a half-space reports itself once and keeps DefaultCoordinateRange
  vtkNew<vtkHyperFunSource> half;
  events->Observe(half);
  half->SetModelText(HalfSpace);
  events->Clear();
  half->Update();
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 1);
  FREPKIT_CHECK(failures, events->WarningText.find("reaches the edge") != std::string::npos);
  half->GetOutput()->GetCoordinateRange(0, range);
  FREPKIT_CHECK(failures, range[0] == -10 && range[1] == 10);
  half->SetParameter(0, 2.0); // the same model: not said again
  half->Update();
  FREPKIT_CHECK(failures, events->Warnings == 1);

  // --- a blend by x4: the sections at the centre and corners of x4's range
  vtkNew<vtkHyperFunSource> blend;
  events->Observe(blend);
  blend->SetModelText(Blend);
  events->Clear();
  blend->Update(); // x4 without a range: the section at the centre of [-10, 10], ball A
  blend->GetOutput()->GetCoordinateRange(0, range);
  FREPKIT_CHECK(failures, About(range, -4.0, -2.0, 0.2));
  blend->GetOutput()->GetCoordinateRange(3, range);
  FREPKIT_CHECK(failures, range[0] == -10 && range[1] == 10);
  blend->SetCoordinateRange(3, 0, 1); // x4 in [0, 1]: A at 0, B at 1, nothing at 0.5
  blend->Update();
  blend->GetOutput()->GetCoordinateRange(0, range);
  FREPKIT_CHECK(failures, About(range, -4.0, 4.0, 0.5));
  blend->GetOutput()->GetCoordinateRange(1, range);
  FREPKIT_CHECK(failures, About(range, -1.0, 1.0, 0.2));
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);

  // --- a newcomer's pipeline, no range anywhere: the slice x4 = 0.5 of the unit 4-D ball
  // meshes at the full resolution (284 triangles over hfp's [-10, 10], about 12,000 here)
  vtkNew<vtkFRepSlice> slice;
  slice->SetInputConnection(ball4->GetOutputPort());
  slice->SetFixedValue(3, 0.5);
  vtkNew<vtkFRepPolygonizer> mesher;
  mesher->SetInputConnection(slice->GetOutputPort());
  mesher->Update();
  const vtkIdType triangles = mesher->GetOutput()->GetNumberOfCells();
  FREPKIT_CHECK(failures, triangles > 8000);
  ball4->UseSolidBoundsOff();
  mesher->Update();
  FREPKIT_CHECK(failures, mesher->GetOutput()->GetNumberOfCells() < triangles / 10);
  std::cout << "4-D ball, slice x4 = 0.5, default polygonizer: " << triangles
            << " triangles with the solid's bounds, " << mesher->GetOutput()->GetNumberOfCells()
            << " over [-10, 10]\n";

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
