// vtkFRepImplicitFunction: -F and -grad F of a sphere of radius 5 against the analytic values;
// vtkSampleFunction on the STDThread backend (several threads at once) equals per-point
// evaluation, and the batch array form equals it too; vtkCutter gives the circle of radius 5;
// vtkClipPolyData keeps the inside; run-time errors are outside, counted and reported once;
// a non-3-D object is an error; MTime includes the object's; Set/Get; PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkCellArray.h"
#include "vtkClipPolyData.h"
#include "vtkCutter.h"
#include "vtkDoubleArray.h"
#include "vtkFRepImplicitFunction.h"
#include "vtkFRepObject.h"
#include "vtkFloatArray.h"
#include "vtkHyperFunSource.h"
#include "vtkImageData.h"
#include "vtkMassProperties.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSampleFunction.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

namespace
{
const char* SphereText = R"(my_model(x[3], a[1])
{
  array c[3];
  c = [0, 0, 0];
  my_model = hfSphere(x, c, 5);
}
)";

// Records which threads call it, and forwards to the FRep function: shows that the sampler
// really calls the adaptor from several threads at once.
class ThreadRecorder : public vtkImplicitFunction
{
public:
  static ThreadRecorder* New();
  vtkTypeMacro(ThreadRecorder, vtkImplicitFunction);
  using vtkImplicitFunction::EvaluateFunction;
  double EvaluateFunction(double x[3]) override
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Threads.insert(std::this_thread::get_id());
    }
    return this->Target->EvaluateFunction(x);
  }
  void EvaluateGradient(double x[3], double g[3]) override { this->Target->EvaluateGradient(x, g); }
  vtkFRepImplicitFunction* Target = nullptr;
  std::mutex Mutex;
  std::set<std::thread::id> Threads;
};
vtkStandardNewMacro(ThreadRecorder);

vtkSmartPointer<vtkHyperFunSource> MakeSource(const char* text)
{
  auto source = vtkSmartPointer<vtkHyperFunSource>::New();
  source->SetModelText(text);
  source->Update();
  return source;
}
}

int TestFRepImplicitFunction(int, char*[])
{
  int failures = 0;
  // Parallel by default is the rule; ParaView's VTK defaults to Sequential.
  vtkSMPTools::SetBackend("STDThread");
  FREPKIT_CHECK(failures, std::string(vtkSMPTools::GetBackend()) == "STDThread");

  auto source = MakeSource(SphereText);
  vtkNew<vtkFRepImplicitFunction> function;
  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(function);

  // --- defaults, Set/Get
  FREPKIT_CHECK(failures, function->GetFRepObject() == nullptr);
  FREPKIT_CHECK(failures, function->GetErrorValue() == VTK_FLOAT_MAX);
  function->SetErrorValue(1e30);
  FREPKIT_CHECK(failures, function->GetErrorValue() == 1e30);
  function->SetErrorValue(VTK_FLOAT_MAX);

  // no object: an error once per round, every point outside
  double origin[3] = { 0, 0, 0 };
  FREPKIT_CHECK(failures, function->EvaluateFunction(origin) == VTK_FLOAT_MAX);
  FREPKIT_CHECK(failures, function->EvaluateFunction(origin) == VTK_FLOAT_MAX);
  FREPKIT_CHECK(failures, events->Errors == 1);

  function->SetFRepObject(source->GetOutput());
  FREPKIT_CHECK(failures, function->GetFRepObject() == source->GetOutput());
  events->Clear();

  // --- values and gradients: -F = r^2 - 25, -grad F = 2 x
  const double points[][3] = {
    { 0, 0, 0 }, { 5, 0, 0 }, { 1, 2, 3 }, { -3, 4, 0 }, { 6.5, -1.25, 2 }, { 0.1, 0.2, -7 }
  };
  for (const auto& p : points)
  {
    double x[3] = { p[0], p[1], p[2] };
    const double r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    const double f = function->EvaluateFunction(x);
    FREPKIT_CHECK(failures, std::abs(f - (r2 - 25)) <= 1e-12 * (1 + std::abs(r2)));
    FREPKIT_CHECK(failures, function->EvaluateFunction(x[0], x[1], x[2]) == f);
    FREPKIT_CHECK(failures, function->FunctionValue(x) == f);
    double g[3];
    function->EvaluateGradient(x, g);
    for (int k = 0; k < 3; ++k)
    {
      FREPKIT_CHECK(failures, std::abs(g[k] - 2 * x[k]) <= 1e-12 * (1 + std::abs(x[k])));
    }
  }
  FREPKIT_CHECK(failures, function->EvaluateFunction(origin) < 0); // inside is negative
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  FREPKIT_CHECK(failures, function->GetNumberOfEvaluationErrors() == 0);

  // --- vtkSampleFunction on several threads equals per-point evaluation
  vtkNew<ThreadRecorder> recorder;
  recorder->Target = function;
  vtkNew<vtkSampleFunction> sampler;
  sampler->SetImplicitFunction(recorder);
  sampler->SetModelBounds(-6, 6, -6, 6, -6, 6);
  sampler->SetSampleDimensions(48, 48, 48);
  sampler->SetOutputScalarTypeToDouble();
  sampler->ComputeNormalsOn();
  sampler->Update();
  vtkImageData* image = sampler->GetOutput();
  vtkDataArray* sampled = image->GetPointData()->GetScalars();
  FREPKIT_CHECK(failures, sampled && sampled->GetNumberOfTuples() == 48 * 48 * 48);
  vtkIdType mismatches = 0;
  vtkNew<vtkDoubleArray> sampledPoints;
  sampledPoints->SetNumberOfComponents(3);
  sampledPoints->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    sampledPoints->SetTuple(i, x);
    mismatches += function->EvaluateFunction(x) != sampled->GetTuple1(i) ? 1 : 0;
  }
  FREPKIT_CHECK(failures, mismatches == 0);
  const unsigned cores = std::thread::hardware_concurrency();
  std::cout << "vtkSampleFunction called the function from " << recorder->Threads.size()
            << " threads (" << cores << " cores, " << vtkSMPTools::GetEstimatedNumberOfThreads()
            << " SMP threads)" << std::endl;
  if (cores > 1 && vtkSMPTools::GetEstimatedNumberOfThreads() > 1)
  {
    FREPKIT_CHECK(failures, recorder->Threads.size() > 1);
  }
  // normals from the gradient point outwards (vtkSampleFunction negates the gradient)
  vtkDataArray* normals = image->GetPointData()->GetNormals();
  FREPKIT_CHECK(failures, normals != nullptr);

  // --- the batch (array) form equals per-point evaluation, bit for bit, double and float
  vtkNew<vtkDoubleArray> batchValues;
  function->EvaluateFunction(sampledPoints, batchValues);
  FREPKIT_CHECK(failures, batchValues->GetNumberOfTuples() == sampledPoints->GetNumberOfTuples());
  mismatches = 0;
  for (vtkIdType i = 0; i < sampledPoints->GetNumberOfTuples(); ++i)
  {
    mismatches += batchValues->GetValue(i) != sampled->GetTuple1(i) ? 1 : 0;
  }
  FREPKIT_CHECK(failures, mismatches == 0);
  vtkNew<vtkFloatArray> floatPoints;
  floatPoints->DeepCopy(sampledPoints);
  vtkNew<vtkFloatArray> floatValues;
  function->FunctionValue(floatPoints, floatValues);
  mismatches = 0;
  for (vtkIdType i = 0; i < floatPoints->GetNumberOfTuples(); ++i)
  {
    double x[3];
    floatPoints->GetTuple(i, x);
    mismatches += floatValues->GetValue(i) != static_cast<float>(function->EvaluateFunction(x));
  }
  FREPKIT_CHECK(failures, mismatches == 0);
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);

  // --- vtkCutter on a plane: the circle of radius 5
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-8, -8, 0);
  plane->SetPoint1(8, -8, 0);
  plane->SetPoint2(-8, 8, 0);
  plane->SetResolution(160, 160);
  vtkNew<vtkCutter> cutter;
  cutter->SetInputConnection(plane->GetOutputPort());
  cutter->SetCutFunction(function);
  cutter->Update();
  vtkPolyData* circle = cutter->GetOutput();
  FREPKIT_CHECK(failures, circle->GetNumberOfPoints() > 100);
  FREPKIT_CHECK(failures, circle->GetNumberOfLines() > 100);
  double worst = 0;
  for (vtkIdType i = 0; i < circle->GetNumberOfPoints(); ++i)
  {
    double x[3];
    circle->GetPoint(i, x);
    worst = std::max(worst, std::abs(std::hypot(x[0], x[1]) - 5.0));
  }
  FREPKIT_CHECK(failures, worst < 0.01);
  double length = 0;
  {
    vtkCellArray* lines = circle->GetLines();
    vtkIdType n;
    const vtkIdType* ids;
    for (lines->InitTraversal(); lines->GetNextCell(n, ids);)
    {
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        double a[3], b[3];
        circle->GetPoint(ids[k], a);
        circle->GetPoint(ids[k + 1], b);
        length += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      }
    }
  }
  std::cout << "cut: " << circle->GetNumberOfPoints() << " points, radius error " << worst
            << ", length " << length << " (2 pi 5 = " << 2 * vtkMath::Pi() * 5 << ")" << std::endl;
  FREPKIT_CHECK(failures, std::abs(length - 2 * vtkMath::Pi() * 5) < 0.01 * 2 * vtkMath::Pi() * 5);

  // --- vtkClipPolyData keeps the inside (negative values) with InsideOut
  vtkNew<vtkClipPolyData> clip;
  clip->SetInputConnection(plane->GetOutputPort());
  clip->SetClipFunction(function);
  clip->InsideOutOn();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(clip->GetOutputPort());
  vtkNew<vtkMassProperties> mass;
  mass->SetInputConnection(triangles->GetOutputPort());
  mass->Update();
  vtkPolyData* disc = clip->GetOutput();
  FREPKIT_CHECK(failures, disc->GetNumberOfCells() > 0);
  double farthest = 0;
  for (vtkIdType i = 0; i < disc->GetNumberOfPoints(); ++i)
  {
    double x[3];
    disc->GetPoint(i, x);
    farthest = std::max(farthest, std::hypot(x[0], x[1]));
  }
  FREPKIT_CHECK(failures, farthest < 5.01);
  const double area = mass->GetSurfaceArea();
  std::cout << "clip: area " << area << " (25 pi = " << 25 * vtkMath::Pi() << ")" << std::endl;
  FREPKIT_CHECK(failures, std::abs(area - 25 * vtkMath::Pi()) < 0.01 * 25 * vtkMath::Pi());
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);

  // --- MTime includes the object's; a change of the object is seen by the function
  const vtkMTimeType before = function->GetMTime();
  source->SetParameter(0, 0.0); // (unused by the sphere) modifies the source, not the object
  source->GetOutput()->SetCoordinateRange(0, -6, 6);
  FREPKIT_CHECK(failures, function->GetMTime() > before);

  // --- run-time errors: outside, counted, one warning per round
  auto failing = MakeSource("my_model(x[3], a[1]) { my_model = 2 - sqrt(x[1]) - x[2]*x[2]; }");
  vtkNew<vtkFRepImplicitFunction> risky;
  vtkNew<frepkit_test::EventCounter> riskyEvents;
  riskyEvents->Observe(risky);
  risky->SetFRepObject(failing->GetOutput());
  double good[3] = { 1, 0, 0 };
  double bad[3] = { -1, 0, 0 };
  FREPKIT_CHECK(failures, risky->EvaluateFunction(good) == -1.0);
  FREPKIT_CHECK(failures, risky->EvaluateFunction(bad) == VTK_FLOAT_MAX);
  FREPKIT_CHECK(failures, risky->EvaluateFunction(bad) == VTK_FLOAT_MAX);
  FREPKIT_CHECK(failures, riskyEvents->Warnings == 1 && riskyEvents->Errors == 0);
  FREPKIT_CHECK(failures, riskyEvents->WarningText.find("<string>:1:") != std::string::npos);
  FREPKIT_CHECK(failures, risky->GetNumberOfEvaluationErrors() == 2);
  double g[3] = { 9, 9, 9 };
  risky->EvaluateGradient(bad, g);
  FREPKIT_CHECK(failures, g[0] == 0 && g[1] == 0 && g[2] == 0);
  FREPKIT_CHECK(failures, risky->GetNumberOfEvaluationErrors() == 3);
  FREPKIT_CHECK(failures, riskyEvents->Warnings == 1);
  // a new round after Modified(): one more warning
  risky->Modified();
  FREPKIT_CHECK(failures, risky->GetNumberOfEvaluationErrors() == 0);
  FREPKIT_CHECK(failures, risky->EvaluateFunction(bad) == VTK_FLOAT_MAX);
  FREPKIT_CHECK(failures, riskyEvents->Warnings == 2);
  FREPKIT_CHECK(failures, risky->GetNumberOfEvaluationErrors() == 1);
  risky->ResetEvaluationErrors();
  FREPKIT_CHECK(failures, risky->GetNumberOfEvaluationErrors() == 0);
  // the batch form: one warning with the count, the failed points outside
  vtkNew<vtkDoubleArray> mixed;
  mixed->SetNumberOfComponents(3);
  for (int i = -5; i < 5; ++i)
  {
    mixed->InsertNextTuple3(i + 0.5, 0, 0); // 5 negative x1: 5 failures
  }
  vtkNew<vtkDoubleArray> mixedValues;
  riskyEvents->Clear();
  risky->EvaluateFunction(mixed, mixedValues);
  FREPKIT_CHECK(failures, riskyEvents->Warnings == 1);
  FREPKIT_CHECK(failures, riskyEvents->WarningText.find("5 of 10 points") != std::string::npos);
  FREPKIT_CHECK(failures, risky->GetNumberOfEvaluationErrors() == 5);
  for (vtkIdType i = 0; i < 10; ++i)
  {
    double x[3];
    mixed->GetTuple(i, x);
    FREPKIT_CHECK(failures,
      x[0] < 0 ? mixedValues->GetValue(i) == VTK_FLOAT_MAX
               : mixedValues->GetValue(i) == -(2 - std::sqrt(x[0])));
  }
  // a 3-component check of the batch input
  vtkNew<vtkDoubleArray> twoComponents;
  twoComponents->SetNumberOfComponents(2);
  twoComponents->InsertNextTuple2(0, 0);
  riskyEvents->Clear();
  risky->EvaluateFunction(twoComponents, mixedValues);
  FREPKIT_CHECK(failures, riskyEvents->Errors == 1);

  // --- an object that is not 3-D is an error; a slice of it to 3-D works
  vtkNew<vtkHyperFunSource> source5;
  source5->SetFileName(FREPKIT_SOURCE_DIR "/Examples/homotopy5d.hf");
  source5->Update();
  vtkNew<vtkFRepObject> object5;
  object5->ShallowCopy(source5->GetOutput());
  vtkNew<vtkFRepImplicitFunction> function5;
  vtkNew<frepkit_test::EventCounter> events5;
  events5->Observe(function5);
  function5->SetFRepObject(object5);
  FREPKIT_CHECK(
    failures, events5->Errors == 1 && events5->ErrorText.find("exactly 3") != std::string::npos);
  FREPKIT_CHECK(failures, function5->EvaluateFunction(origin) == VTK_FLOAT_MAX);
  FREPKIT_CHECK(failures, events5->Errors == 2);
  object5->FixCoordinate(3, 0.0);
  object5->FixCoordinate(4, 0.0); // the ball of radius 3
  double onBall[3] = { 3, 0, 0 };
  double inBall[3] = { 1, 1, 1 };
  FREPKIT_CHECK(failures, std::abs(function5->EvaluateFunction(onBall)) < 1e-9);
  FREPKIT_CHECK(failures, function5->EvaluateFunction(inBall) < 0);
  FREPKIT_CHECK(failures, events5->Errors == 2);

  // --- PrintSelf
  std::ostringstream printed;
  function->Print(printed);
  risky->Print(printed);
  FREPKIT_CHECK(failures, printed.str().find("ErrorValue") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("my_model, dimension 3") != std::string::npos);
  function->SetFRepObject(nullptr);
  function->Print(printed);

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
