// vtkFRepEvaluator: F and s[] of an object at many points from VTK arrays, bit for bit the
// values of frep::PointEvaluator (double and float inputs, vtkPoints, one point, a 5-D object
// and its slice), run-time errors as NaN with an id and file:line:col, and bad calls (wrong
// component count, no object, no model, null arrays, 4-D vtkPoints) as one VTK error each and a
// false return with empty outputs.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepEvaluator.h"
#include "vtkFRepObject.h"
#include "vtkHyperFunSource.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"

#include "Eval/point_evaluator.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace
{
bool SameBits(double a, double b)
{
  std::uint64_t x = 0, y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}
}

int TestFRepEvaluator(int, char*[])
{
  int failures = 0;
  vtkNew<frepkit_test::EventCounter> events;

  vtkNew<vtkHyperFunSource> source;
  source->SetFileName(FREPKIT_SOURCE_DIR "/Examples/homotopy5d.hf");
  source->Update();
  vtkFRepObject* object = source->GetOutput();
  FREPKIT_CHECK(failures, object->GetDimension() == 5);

  vtkNew<vtkFRepEvaluator> evaluator;
  events->Observe(evaluator);
  FREPKIT_CHECK(failures, evaluator->GetNumberOfThreads() == 0);
  FREPKIT_CHECK(failures, evaluator->GetDimension() == 0);
  evaluator->SetObject(object);
  FREPKIT_CHECK(failures, evaluator->GetDimension() == 5);
  // A model without s[] has s_dim 1 (HyperFun: s[1], 0).
  FREPKIT_CHECK(failures, evaluator->GetNumberOfAttributes() == 1);

  // 5-D points, 100000 of them (several blocks, all threads): bit-equal to the point evaluator.
  const vtkIdType n = 100000;
  std::mt19937_64 random(14);
  std::uniform_real_distribution<double> uniform(-4.0, 4.0);
  vtkNew<vtkDoubleArray> points;
  points->SetNumberOfComponents(5);
  points->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> floats;
  floats->SetNumberOfComponents(5);
  floats->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 5; ++c)
    {
      const double v = c < 3 ? uniform(random) : 0.5 + 0.125 * uniform(random);
      points->SetComponent(i, c, v);
      floats->SetComponent(i, c, v);
    }
  }
  vtkNew<vtkDoubleArray> values;
  FREPKIT_CHECK(failures, evaluator->Evaluate(points, values));
  FREPKIT_CHECK(failures, values->GetNumberOfTuples() == n && values->GetNumberOfComponents() == 1);
  FREPKIT_CHECK(failures, std::string(values->GetName()) == "F");
  frep::PointEvaluator point(object->GetTape());
  int mismatches = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[5];
    points->GetTuple(i, x);
    if (!SameBits(values->GetValue(i), point.value(x)))
    {
      ++mismatches;
    }
  }
  FREPKIT_CHECK(failures, mismatches == 0);
  FREPKIT_CHECK(failures, evaluator->GetNumberOfErrorPoints() == 0);

  // Float input: evaluated at the float values converted to double; one thread gives the same.
  evaluator->SetNumberOfThreads(1);
  FREPKIT_CHECK(failures, evaluator->Evaluate(floats, values));
  mismatches = 0;
  for (vtkIdType i = 0; i < n; i += 97)
  {
    double x[5];
    floats->GetTuple(i, x);
    if (!SameBits(values->GetValue(i), point.value(x)))
    {
      ++mismatches;
    }
  }
  FREPKIT_CHECK(failures, mismatches == 0);
  evaluator->SetNumberOfThreads(5000);
  FREPKIT_CHECK(failures, evaluator->GetNumberOfThreads() == 1024); // clamped

  // One point.
  double x0[5] = { 0.0, 0.0, 0.0, 0.5, 0.25 };
  FREPKIT_CHECK(failures, SameBits(evaluator->EvaluatePoint(x0, 5), point.value(x0)));
  FREPKIT_CHECK(failures, events->Errors == 0);

  // Bad calls: one error each, false, empty outputs; never a crash.
  vtkNew<vtkDoubleArray> three;
  three->SetNumberOfComponents(3);
  three->SetNumberOfTuples(4);
  three->Fill(0.0);
  events->Clear();
  FREPKIT_CHECK(failures, !evaluator->Evaluate(three, values));
  FREPKIT_CHECK(failures, events->Errors == 1 && values->GetNumberOfTuples() == 0);
  FREPKIT_CHECK(failures, events->ErrorText.find("3 components") != std::string::npos);
  events->Clear();
  FREPKIT_CHECK(failures, !evaluator->Evaluate(nullptr, values) && events->Errors == 1);
  events->Clear();
  FREPKIT_CHECK(failures, !evaluator->Evaluate(points, nullptr) && events->Errors == 1);
  events->Clear();
  vtkNew<vtkPoints> xyz;
  xyz->SetNumberOfPoints(2);
  FREPKIT_CHECK(failures, !evaluator->EvaluatePoints(xyz, values) && events->Errors == 1);
  events->Clear();
  FREPKIT_CHECK(failures, std::isnan(evaluator->EvaluatePoint(x0, 3)) && events->Errors == 1);
  vtkNew<vtkFRepObject> empty;
  evaluator->SetObject(empty);
  events->Clear();
  FREPKIT_CHECK(failures, !evaluator->Evaluate(points, values) && events->Errors == 1);
  FREPKIT_CHECK(failures, events->ErrorText.find("no model") != std::string::npos);
  evaluator->SetObject(nullptr);
  events->Clear();
  FREPKIT_CHECK(failures, !evaluator->Evaluate(points, values) && events->Errors == 1);

  // A 3-D slice through vtkPoints; s[] and a run-time error with its place.
  vtkNew<vtkHyperFunSource> attributed;
  attributed->SetModelText("my_model(x[3], a[1], s[2]) {\n  s[1] = 2 * x[1];\n"
                           "  s[2] = sqrt(x[2]);\n  my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2;\n}\n");
  attributed->Update();
  evaluator->SetObject(attributed->GetOutput());
  FREPKIT_CHECK(failures, evaluator->GetDimension() == 3 && evaluator->GetNumberOfAttributes() == 2);
  xyz->SetPoint(0, 0.5, 0.25, 0.0);
  xyz->SetPoint(1, 0.1, -1.0, 0.0);
  vtkNew<vtkDoubleArray> s;
  events->Clear();
  FREPKIT_CHECK(failures, evaluator->EvaluatePoints(xyz, values, s));
  FREPKIT_CHECK(failures, values->GetValue(0) == 0.6875 && std::isnan(values->GetValue(1)));
  FREPKIT_CHECK(failures, s->GetNumberOfComponents() == 2 && s->GetNumberOfTuples() == 2);
  FREPKIT_CHECK(failures, s->GetComponent(0, 0) == 1.0 && s->GetComponent(0, 1) == 0.5);
  FREPKIT_CHECK(failures, evaluator->GetNumberOfErrorPoints() == 1 && events->Errors == 0);
  vtkNew<vtkIntArray> ids;
  vtkNew<vtkDoubleArray> xyzArray;
  xyzArray->DeepCopy(xyz->GetData());
  FREPKIT_CHECK(failures, evaluator->Evaluate(xyzArray, values, nullptr, ids));
  FREPKIT_CHECK(failures, ids->GetValue(0) == 0 && ids->GetValue(1) > 0);
  const std::string message = evaluator->GetErrorMessage(ids->GetValue(1));
  FREPKIT_CHECK(failures, message.find(":3:") != std::string::npos);
  FREPKIT_CHECK(failures, evaluator->GetErrorMessage(0).empty());
  FREPKIT_CHECK(failures, evaluator->GetErrorMessage(99).empty());

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
