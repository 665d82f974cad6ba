// vtkFRepImplicitFunction inside VTK's own filters: vtkCutter cuts a plane along the model's
// surface, vtkClipPolyData keeps the model's inside (VTK's sign: negative inside).
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepImplicitFunction.h"
#include "vtkHyperFunSource.h"

#include "vtkClipPolyData.h"
#include "vtkCutter.h"
#include "vtkMassProperties.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <cmath>

int TestFRepImplicitFunctionFilters(int, char*[])
{
  int failures = 0;
  constexpr double pi = 3.14159265358979323846;
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText("my_model(x[3], a[1]) { my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2; }");
  source->Update();
  vtkNew<vtkFRepImplicitFunction> sphere;
  sphere->SetFRepObject(source->GetOutput());

  // The plane z = 3 meets the sphere in a circle of radius 4.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-10, -10, 3);
  plane->SetPoint1(10, -10, 3);
  plane->SetPoint2(-10, 10, 3);
  plane->SetResolution(400, 400);
  vtkNew<vtkCutter> cutter;
  cutter->SetInputConnection(plane->GetOutputPort());
  cutter->SetCutFunction(sphere);
  cutter->SetValue(0, 0.0);
  cutter->Update();
  vtkPolyData* circle = cutter->GetOutput();
  double length = 0;
  for (vtkIdType c = 0; c < circle->GetNumberOfCells(); ++c)
  {
    double a[3], b[3];
    circle->GetPoint(circle->GetCell(c)->GetPointId(0), a);
    circle->GetPoint(circle->GetCell(c)->GetPointId(1), b);
    FREPKIT_CHECK(failures, std::abs(std::sqrt(a[0] * a[0] + a[1] * a[1]) - 4.0) < 0.01);
    length += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]));
  }
  FREPKIT_CHECK(failures, std::abs(length - 8 * pi) < 0.01 * 8 * pi);

  // Clipping keeps the disc of radius 4 (inside, where the function is negative).
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkClipPolyData> clip;
  clip->SetInputConnection(triangles->GetOutputPort());
  clip->SetClipFunction(sphere);
  clip->InsideOutOn();
  clip->Update();
  vtkNew<vtkMassProperties> area;
  area->SetInputConnection(clip->GetOutputPort());
  area->Update();
  FREPKIT_CHECK(failures, std::abs(area->GetSurfaceArea() - 16 * pi) < 0.01 * 16 * pi);
  return failures == 0 ? 0 : 1;
}
