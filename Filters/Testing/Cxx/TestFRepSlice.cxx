// vtkFRepSlice: a 4-D model sliced at x4 = 0.5 evaluates bit for bit like the 4-D tape with
// x4 = 0.5 (by index and by name), with a tape no longer than the 4-D one; FreeCoordinateOrder
// permutes the tape inputs; field data follows; every bad request is one error and an empty
// output; an empty input is quiet; NaN releases; MTime, Set/Get, PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepObject.h"
#include "vtkFRepSlice.h"
#include "vtkFieldData.h"
#include "vtkHyperFunSource.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkStringArray.h"

#include "Eval/point_evaluator.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

namespace
{
// A ball whose radius and centre depend on x4, squashed differently along x1, x2, x3 so that
// a permutation of the inputs shows.
const char* Model4D = R"(my_model(x[4], a[1])
{
  r = 2 + 1.5 * sin(3 * x[4]);
  c = x[4] * x[4] - 0.25;
  my_model = r * r - (x[1] - c) ^ 2 - 2 * x[2] * x[2] - 3 * x[3] * x[3];
}
)";

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

bool SameBits(double a, double b)
{
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

std::vector<std::array<double, 3>> RandomPoints(int count)
{
  std::mt19937_64 random(20261124);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  std::vector<std::array<double, 3>> points(count);
  for (auto& p : points)
  {
    p = { u(random), u(random), u(random) };
  }
  return points;
}

// Points where the 3-D tape (inputs in `order`: tape input k is model coordinate order[k])
// and the 4-D tape at x4 = 0.5 differ in F or s[] (bit for bit).
int Mismatches(vtkFRepObject* sliced, vtkFRepObject* full, const std::vector<int>& order)
{
  frep::PointEvaluator slice(sliced->GetTape());
  frep::PointEvaluator whole(full->GetTape());
  std::vector<double> sOut(slice.tape().outputs.size());
  std::vector<double> wOut(whole.tape().outputs.size());
  if (sOut.size() != wOut.size())
  {
    return -1;
  }
  int mismatches = 0;
  for (const auto& p : RandomPoints(3000))
  {
    const double x4[4] = { p[0], p[1], p[2], 0.5 };
    double x3[3];
    for (int k = 0; k < 3; ++k)
    {
      x3[k] = p[order[k]];
    }
    const int e1 = slice.evaluate(std::span<const double>(x3, 3), sOut);
    const int e2 = whole.evaluate(std::span<const double>(x4, 4), wOut);
    bool same = e1 == e2;
    for (std::size_t k = 0; k < sOut.size(); ++k)
    {
      same = same && SameBits(sOut[k], wOut[k]);
    }
    mismatches += same ? 0 : 1;
  }
  return mismatches;
}

int FieldDimension(vtkFRepObject* object)
{
  auto* a = vtkIntArray::SafeDownCast(object->GetFieldData()->GetArray("FRepDimension"));
  return a ? a->GetValue(0) : -1;
}

std::string FieldNames(vtkFRepObject* object)
{
  auto* a = vtkStringArray::SafeDownCast(
    object->GetFieldData()->GetAbstractArray("FRepCoordinateNames"));
  std::string names;
  for (vtkIdType i = 0; a && i < a->GetNumberOfValues(); ++i)
  {
    names += (i ? "," : "") + a->GetValue(i);
  }
  return names;
}

bool IsEmpty(vtkFRepObject* object)
{
  return !object->HasModel() && object->GetDimension() == 0 && !object->GetTape();
}
}

int TestFRepSlice(int, char*[])
{
  int failures = 0;
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(Model4D);
  source->Update();
  vtkFRepObject* full = source->GetOutput();
  FREPKIT_CHECK(failures, full->GetDimension() == 4);

  vtkNew<vtkFRepSlice> slice;
  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(slice);
  slice->SetInputConnection(source->GetOutputPort());

  // --- defaults
  FREPKIT_CHECK(failures, slice->GetNumberOfInputPorts() == 1);
  FREPKIT_CHECK(failures, slice->GetNumberOfOutputPorts() == 1);
  FREPKIT_CHECK(failures, slice->GetNumberOfFixedValues() == 0);
  FREPKIT_CHECK(failures, slice->GetFreeCoordinateOrder() == nullptr);
  FREPKIT_CHECK(failures, !slice->IsCoordinateFixed(3));
  FREPKIT_CHECK(failures, std::isnan(slice->GetFixedValue(3)));
  FREPKIT_CHECK(failures, std::isnan(slice->GetFixedValueByName("x4")));

  // --- nothing fixed: the input passes through (same model, shared)
  slice->Update();
  FREPKIT_CHECK(failures, slice->GetOutput()->GetDimension() == 4);
  FREPKIT_CHECK(failures, slice->GetOutput()->GetModel() == full->GetModel());

  // --- x4 = 0.5 by index: 3-D, exact, shorter tape, field data
  slice->SetFixedValue(3, 0.5);
  FREPKIT_CHECK(failures, slice->IsCoordinateFixed(3) && slice->GetFixedValue(3) == 0.5);
  FREPKIT_CHECK(failures, slice->GetNumberOfFixedValues() == 1);
  slice->Update();
  vtkFRepObject* sliced = slice->GetOutput();
  FREPKIT_CHECK(failures, sliced->GetDimension() == 3);
  FREPKIT_CHECK(failures, sliced->GetModelDimension() == 4);
  FREPKIT_CHECK(failures, sliced->GetModel() == full->GetModel()); // ShallowCopy shares it
  FREPKIT_CHECK(failures, sliced->IsCoordinateFixed(3) && sliced->GetFixedValue(3) == 0.5);
  FREPKIT_CHECK(failures, (sliced->GetFreeCoordinates() == std::vector<int>{ 0, 1, 2 }));
  FREPKIT_CHECK(failures, sliced->GetTape()->input_count == 3);
  FREPKIT_CHECK(failures, sliced->GetTape()->code.size() <= full->GetTape()->code.size());
  std::cout << "tape: 4-D " << full->GetTape()->code.size() << " instructions, sliced "
            << sliced->GetTape()->code.size() << std::endl;
  FREPKIT_CHECK(failures, Mismatches(sliced, full, { 0, 1, 2 }) == 0);
  FREPKIT_CHECK(failures, FieldDimension(sliced) == 3);
  FREPKIT_CHECK(failures, FieldDimension(full) == 4); // the input is untouched
  FREPKIT_CHECK(failures, FieldNames(sliced) == "x1,x2,x3");
  FREPKIT_CHECK(failures, full->GetDimension() == 4 && !full->IsCoordinateFixed(3));
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);

  // the check can fail: another value of x4 differs somewhere
  slice->SetFixedValue(3, 0.75);
  slice->Update();
  FREPKIT_CHECK(failures, Mismatches(slice->GetOutput(), full, { 0, 1, 2 }) > 0);

  // --- MTime: only real changes modify
  vtkMTimeType t = slice->GetMTime();
  slice->SetFixedValue(3, 0.75);
  FREPKIT_CHECK(failures, slice->GetMTime() == t);
  slice->SetFixedValue(3, 0.5);
  FREPKIT_CHECK(failures, slice->GetMTime() > t);

  // --- NaN releases; by name gives the same tape
  slice->SetFixedValue(3, NaN);
  FREPKIT_CHECK(failures, !slice->IsCoordinateFixed(3) && slice->GetNumberOfFixedValues() == 0);
  slice->SetFixedValueByName("x4", 0.5);
  FREPKIT_CHECK(failures, slice->GetFixedValueByName("x4") == 0.5);
  FREPKIT_CHECK(failures, slice->GetNumberOfFixedValues() == 1);
  slice->Update();
  FREPKIT_CHECK(failures, slice->GetOutput()->GetDimension() == 3);
  FREPKIT_CHECK(failures, Mismatches(slice->GetOutput(), full, { 0, 1, 2 }) == 0);
  // the same value by index and by name is not a conflict
  slice->SetFixedValue(3, 0.5);
  slice->Update();
  FREPKIT_CHECK(failures, slice->GetOutput()->GetDimension() == 3 && events->Errors == 0);
  slice->ReleaseCoordinate(3);

  // --- FreeCoordinateOrder "x3,x1,x2": tape input 0 is x3, 1 is x1, 2 is x2
  slice->SetFreeCoordinateOrder(" x3, x1 ,x2 ");
  slice->Update();
  sliced = slice->GetOutput();
  FREPKIT_CHECK(failures, (sliced->GetFreeCoordinates() == std::vector<int>{ 2, 0, 1 }));
  FREPKIT_CHECK(failures, FieldNames(sliced) == "x3,x1,x2");
  FREPKIT_CHECK(failures, Mismatches(sliced, full, { 2, 0, 1 }) == 0);
  FREPKIT_CHECK(failures, Mismatches(sliced, full, { 0, 1, 2 }) > 0); // it is a permutation
  FREPKIT_CHECK(failures, events->Errors == 0);
  // empty order = the input's order again
  slice->SetFreeCoordinateOrder("");
  slice->Update();
  FREPKIT_CHECK(failures, (slice->GetOutput()->GetFreeCoordinates() == std::vector<int>{ 0, 1, 2 }));
  // a 4-D permutation without fixing anything
  slice->ReleaseAllCoordinates();
  FREPKIT_CHECK(failures, slice->GetNumberOfFixedValues() == 0);
  slice->SetFreeCoordinateOrder("x4,x3,x2,x1");
  slice->Update();
  FREPKIT_CHECK(failures,
    (slice->GetOutput()->GetFreeCoordinates() == std::vector<int>{ 3, 2, 1, 0 }));
  slice->SetFreeCoordinateOrder(nullptr);

  // --- a value outside the interval [-10, 10] is allowed, silently
  slice->SetFixedValue(3, 50.0);
  slice->Update();
  FREPKIT_CHECK(failures, slice->GetOutput()->GetDimension() == 3);
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  slice->ReleaseAllCoordinates();

  // --- bad requests: one error each, an empty output, never a crash
  struct BadCase
  {
    const char* what;
    std::function<void(vtkFRepSlice*)> request;
    const char* expected; // part of the message
  };
  const std::vector<BadCase> bad = {
    { "unknown name", [](vtkFRepSlice* s) { s->SetFixedValueByName("x9", 0.5); }, "'x9'" },
    { "null name", [](vtkFRepSlice* s) { s->SetFixedValueByName(nullptr, 0.5); }, "''" },
    { "coordinate out of range", [](vtkFRepSlice* s) { s->SetFixedValue(7, 0.5); },
      "coordinate 7 does not exist" },
    { "negative coordinate", [](vtkFRepSlice* s) { s->SetFixedValue(-1, 0.5); },
      "coordinate -1 does not exist" },
    { "infinite value",
      [](vtkFRepSlice* s) { s->SetFixedValue(0, std::numeric_limits<double>::infinity()); },
      "not finite" },
    { "fixed twice",
      [](vtkFRepSlice* s)
      {
        s->SetFixedValue(3, 0.5);
        s->SetFixedValueByName("x4", 0.7);
      },
      "fixed twice" },
    { "order names a fixed coordinate",
      [](vtkFRepSlice* s)
      {
        s->SetFixedValue(3, 0.5);
        s->SetFreeCoordinateOrder("x4,x1,x2,x3");
      },
      "which is fixed" },
    { "order leaves one out",
      [](vtkFRepSlice* s)
      {
        s->SetFixedValue(3, 0.5);
        s->SetFreeCoordinateOrder("x1,x2");
      },
      "neither fixed nor named" },
    { "order repeats", [](vtkFRepSlice* s) { s->SetFreeCoordinateOrder("x1,x1,x2,x3,x4"); },
      "twice" },
    { "order unknown name", [](vtkFRepSlice* s) { s->SetFreeCoordinateOrder("x1,x2,x3,y"); },
      "'y'" },
    { "order empty item", [](vtkFRepSlice* s) { s->SetFreeCoordinateOrder("x1,,x2,x3,x4"); },
      "empty name" },
    { "order trailing comma", [](vtkFRepSlice* s) { s->SetFreeCoordinateOrder("x1,x2,x3,x4,"); },
      "empty name" },
  };
  for (const BadCase& c : bad)
  {
    slice->ReleaseAllCoordinates();
    slice->SetFreeCoordinateOrder(nullptr);
    slice->Update();
    FREPKIT_CHECK(failures, slice->GetOutput()->HasModel());
    events->Clear();
    c.request(slice);
    slice->Update();
    const bool ok = events->Errors == 1 && IsEmpty(slice->GetOutput()) &&
      events->ErrorText.find(c.expected) != std::string::npos;
    if (!ok)
    {
      std::cerr << "bad request '" << c.what << "': " << events->Errors << " errors: \""
                << events->ErrorText << "\"" << std::endl;
    }
    FREPKIT_CHECK(failures, ok);
    FREPKIT_CHECK(failures, FieldDimension(slice->GetOutput()) == -1); // no metadata
  }
  // and it recovers once the request is valid
  slice->ReleaseAllCoordinates();
  slice->SetFreeCoordinateOrder(nullptr);
  slice->SetFixedValue(3, 0.5);
  events->Clear();
  slice->Update();
  FREPKIT_CHECK(failures, slice->GetOutput()->GetDimension() == 3 && events->Errors == 0);

  // --- a slice of a slice: the second fixes x1; fixing x4 again is refused
  vtkNew<vtkFRepSlice> second;
  vtkNew<frepkit_test::EventCounter> secondEvents;
  secondEvents->Observe(second);
  second->SetInputConnection(slice->GetOutputPort());
  second->SetFixedValueByName("x1", 1.0);
  second->SetFreeCoordinateOrder("x3,x2");
  second->Update();
  FREPKIT_CHECK(failures, second->GetOutput()->GetDimension() == 2);
  FREPKIT_CHECK(failures, (second->GetOutput()->GetFreeCoordinates() == std::vector<int>{ 2, 1 }));
  {
    frep::PointEvaluator two(second->GetOutput()->GetTape());
    frep::PointEvaluator four(full->GetTape());
    const double x2[2] = { 0.3, -0.7 };
    const double x4[4] = { 1.0, -0.7, 0.3, 0.5 };
    FREPKIT_CHECK(failures, SameBits(two.value(x2), four.value(x4)));
  }
  second->SetFixedValue(3, 0.25);
  second->Update();
  FREPKIT_CHECK(failures, secondEvents->Errors == 1 && IsEmpty(second->GetOutput()));
  FREPKIT_CHECK(failures, secondEvents->ErrorText.find("already fixed by the input") !=
      std::string::npos);

  // --- names as the input has them: a renamed coordinate, an ambiguous name
  vtkNew<vtkFRepObject> renamed;
  renamed->ShallowCopy(full);
  renamed->SetCoordinateName(3, "t");
  vtkNew<vtkFRepSlice> byName;
  vtkNew<frepkit_test::EventCounter> byNameEvents;
  byNameEvents->Observe(byName);
  byName->SetInputData(renamed);
  byName->SetFixedValueByName("t", 0.5);
  byName->Update();
  FREPKIT_CHECK(failures, byName->GetOutput()->GetDimension() == 3);
  FREPKIT_CHECK(failures, Mismatches(byName->GetOutput(), full, { 0, 1, 2 }) == 0);
  renamed->SetCoordinateName(0, "t");
  byName->Modified();
  byName->Update();
  FREPKIT_CHECK(failures, byNameEvents->Errors == 1 && IsEmpty(byName->GetOutput()));
  FREPKIT_CHECK(failures, byNameEvents->ErrorText.find("2 coordinates are called 't'") !=
      std::string::npos);

  // --- an empty input (a parse error upstream): empty output, no further message
  vtkNew<vtkHyperFunSource> broken;
  vtkNew<frepkit_test::EventCounter> brokenEvents;
  brokenEvents->Observe(broken);
  broken->SetModelText("my_model(x[4], a[1]) { my_model = ; }");
  vtkNew<vtkFRepSlice> afterBroken;
  vtkNew<frepkit_test::EventCounter> afterEvents;
  afterEvents->Observe(afterBroken);
  afterBroken->SetInputConnection(broken->GetOutputPort());
  afterBroken->SetFixedValue(3, 0.5);
  afterBroken->Update();
  FREPKIT_CHECK(failures, brokenEvents->Errors >= 1); // the source says why
  FREPKIT_CHECK(failures, afterEvents->Errors == 0 && afterEvents->Warnings == 0);
  FREPKIT_CHECK(failures, IsEmpty(afterBroken->GetOutput()));

  // --- PrintSelf names the requests
  slice->SetFixedValueByName("x2", 1.5);
  slice->SetFreeCoordinateOrder("x3,x1");
  std::ostringstream printed;
  slice->Print(printed);
  FREPKIT_CHECK(failures, printed.str().find("[3]=0.5") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("'x2'=1.5") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("FreeCoordinateOrder: x3,x1") != std::string::npos);

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
