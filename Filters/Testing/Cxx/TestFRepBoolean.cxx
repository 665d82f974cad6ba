// vtkFRepBoolean: two vtkHyperFunSource balls combined by every set operation and blend give,
// bit for bit, the values of the single HyperFun program written with the operator; the
// product of a 2-D disc and a 1-D interval is the 3-D cylinder with the inputs' names and
// intervals; the output can be sliced (FixCoordinate on a shallow copy) and deep-copied;
// mismatched dimensions and empty inputs are one error each and an empty output; the filter
// re-executes when an input's parameter or its own properties change; Set/Get, PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepBoolean.h"
#include "vtkFRepObject.h"
#include "vtkFieldData.h"
#include "vtkHyperFunSource.h"
#include "vtkNew.h"
#include "vtkStringArray.h"

#include "Compiler/model.h"
#include "Eval/point_evaluator.h"
#include "Language/parser.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const char* BallA = "ball(x[3], a[1]) { ball = a[1]^2 - ((x[1] - 0.5)^2 + x[2]^2 + x[3]^2); }";
const char* BallB =
  "other(x[3], a[1]) { other = a[1]^2 - ((x[1] + 0.7)^2 + (x[2] - 0.2)^2 + x[3]^2); }";

// The same two balls in one program, radii written in, combined by `expression` (s1, s2).
std::string TwoBalls(double ra, double rb, const std::string& expression)
{
  std::ostringstream os;
  os << "my_model(x[3], a[1]) {\n  s1 = " << ra << "^2 - ((x[1] - 0.5)^2 + x[2]^2 + x[3]^2);\n"
     << "  s2 = " << rb << "^2 - ((x[1] + 0.7)^2 + (x[2] - 0.2)^2 + x[3]^2);\n"
     << "  my_model = " << expression << ";\n}\n";
  return os.str();
}

std::shared_ptr<const frep::Tape> CompileTape(const std::string& text)
{
  const frep::ParseResult parsed = frep::parse_program(text, "<reference>");
  if (!parsed.ok())
  {
    std::cerr << frep::format_diagnostics(parsed.diagnostics);
    return nullptr;
  }
  const frep::Model::CompileResult compiled = frep::Model::compile(parsed.program, 0);
  return compiled.model ? compiled.model->tape() : nullptr;
}

bool SameBits(double a, double b)
{
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

std::vector<std::vector<double>> RandomPoints(int dim, int count)
{
  std::mt19937_64 random(4242);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::vector<std::vector<double>> points(count);
  for (auto& p : points)
  {
    for (int k = 0; k < dim; ++k)
    {
      p.push_back(u(random));
    }
  }
  return points;
}

// Points where the object's tape and the reference tape differ (bit for bit, F only).
int Mismatches(vtkFRepObject* object, const std::shared_ptr<const frep::Tape>& reference, int dim)
{
  if (!object || !object->HasModel() || !reference || object->GetDimension() != dim)
  {
    return -1;
  }
  frep::PointEvaluator actual(object->GetTape());
  frep::PointEvaluator expected(reference);
  int mismatches = 0;
  for (const auto& p : RandomPoints(dim, 300))
  {
    mismatches += SameBits(actual.value(p), expected.value(p)) ? 0 : 1;
  }
  return mismatches;
}

double ValueAt(vtkFRepObject* object, std::vector<double> p)
{
  frep::PointEvaluator evaluator(object->GetTape());
  return evaluator.value(p);
}

std::string ObjectNameInFieldData(vtkFRepObject* object)
{
  auto* names =
    vtkStringArray::SafeDownCast(object->GetFieldData()->GetAbstractArray("FRepObjectName"));
  return names && names->GetNumberOfValues() == 1 ? names->GetValue(0) : std::string();
}
}

int TestFRepBoolean(int, char*[])
{
  int failures = 0;

  vtkNew<vtkHyperFunSource> sourceA;
  sourceA->SetModelText(BallA);
  sourceA->SetParameter(0, 1.5);
  vtkNew<vtkHyperFunSource> sourceB;
  sourceB->SetModelText(BallB);
  sourceB->SetParameter(0, 1.2);
  sourceB->SetCoordinateRange(0, -12.0, 5.0); // x1 of B reaches further down, A's further up
  // The hull of the intervals is tested with hfp's default box, not the balls' own bounds.
  sourceA->UseSolidBoundsOff();
  sourceB->UseSolidBoundsOff();

  vtkNew<vtkFRepBoolean> boolean;
  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(boolean);

  // --- defaults and Set/Get
  FREPKIT_CHECK(failures, boolean->GetNumberOfInputPorts() == 2);
  FREPKIT_CHECK(failures, boolean->GetNumberOfOutputPorts() == 1);
  FREPKIT_CHECK(failures, boolean->GetOperation() == vtkFRepBoolean::VTK_UNION);
  FREPKIT_CHECK(failures, std::string(boolean->GetOperationAsString()) == "Union");
  FREPKIT_CHECK(failures, boolean->GetBlendDisplacement() == 1.0);
  FREPKIT_CHECK(
    failures, boolean->GetBlendParameters()[0] == 1.0 && boolean->GetBlendParameters()[1] == 1.0);
  boolean->SetOperation(42);
  FREPKIT_CHECK(failures, boolean->GetOperation() == vtkFRepBoolean::VTK_CARTESIAN_PRODUCT);
  boolean->SetOperation(-1);
  FREPKIT_CHECK(failures, boolean->GetOperation() == vtkFRepBoolean::VTK_UNION);
  boolean->SetOperationToBlendIntersection();
  FREPKIT_CHECK(failures, std::string(boolean->GetOperationAsString()) == "BlendIntersection");
  {
    const vtkMTimeType before = boolean->GetMTime();
    boolean->SetBlendDisplacement(1.0); // unchanged: no Modified
    FREPKIT_CHECK(failures, boolean->GetMTime() == before);
    boolean->SetBlendParameters(1.0, 1.0);
    FREPKIT_CHECK(failures, boolean->GetMTime() == before);
    boolean->SetBlendParameters(2.0, 0.7);
    FREPKIT_CHECK(failures, boolean->GetMTime() > before);
  }

  boolean->SetInputConnection(0, sourceA->GetOutputPort());
  boolean->SetSourceConnection(sourceB->GetOutputPort());

  // --- every set operation and blend equals the single program with the operator
  struct Case
  {
    void (vtkFRepBoolean::*select)();
    const char* expression;
    const char* name;
  };
  const Case cases[] = {
    { &vtkFRepBoolean::SetOperationToUnion, "s1 | s2", "union(ball, other)" },
    { &vtkFRepBoolean::SetOperationToIntersection, "s1 & s2", "intersection(ball, other)" },
    { &vtkFRepBoolean::SetOperationToDifference, "s1 \\ s2", "difference(ball, other)" },
    { &vtkFRepBoolean::SetOperationToBlendUnion,
      "hfBlendUni(s1, s2, 0.5, 2, 0.7)",
      "blend_union(ball, other)" },
    { &vtkFRepBoolean::SetOperationToBlendIntersection,
      "hfBlendInt(s1, s2, 0.5, 2, 0.7)",
      "blend_intersection(ball, other)" },
  };
  boolean->SetBlendDisplacement(0.5);
  for (const Case& c : cases)
  {
    (boolean->*c.select)();
    boolean->Update();
    vtkFRepObject* out = boolean->GetOutput();
    FREPKIT_CHECK(failures, out->HasModel());
    FREPKIT_CHECK(failures, out->GetDimension() == 3);
    FREPKIT_CHECK(failures, out->GetNumberOfParameters() == 0);
    FREPKIT_CHECK(failures, out->GetObjectName() == c.name);
    FREPKIT_CHECK(failures, ObjectNameInFieldData(out) == c.name);
    const int bad = Mismatches(out, CompileTape(TwoBalls(1.5, 1.2, c.expression)), 3);
    if (bad != 0)
    {
      std::cerr << c.name << ": " << bad << " points differ from '" << c.expression << "'\n";
    }
    FREPKIT_CHECK(failures, bad == 0);
  }
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);

  // --- names and intervals of a set operation: A's names, the hull of both intervals
  boolean->SetOperationToUnion();
  boolean->Update();
  {
    vtkFRepObject* out = boolean->GetOutput();
    double range[2];
    out->GetCoordinateRange(0, range);
    FREPKIT_CHECK(failures, range[0] == -12.0 && range[1] == 10.0);
    out->GetCoordinateRange(2, range);
    FREPKIT_CHECK(failures, range[0] == -10.0 && range[1] == 10.0);
    FREPKIT_CHECK(failures, out->GetCoordinateName(1) == "x2");
  }

  // --- the output can be sliced: a 2-D section at x2 = 0.25 equals the 3-D values there
  {
    vtkNew<vtkFRepObject> slice;
    slice->ShallowCopy(boolean->GetOutput());
    slice->FixCoordinate(1, 0.25);
    FREPKIT_CHECK(failures, slice->GetDimension() == 2);
    FREPKIT_CHECK(failures, slice->GetTape() && slice->GetTape()->input_count == 2);
    frep::PointEvaluator cut(slice->GetTape());
    frep::PointEvaluator full(boolean->GetOutput()->GetTape());
    int bad = 0;
    for (const auto& p : RandomPoints(2, 200))
    {
      bad += SameBits(cut.value(p), full.value(std::vector<double>{ p[0], 0.25, p[1] })) ? 0 : 1;
    }
    FREPKIT_CHECK(failures, bad == 0);
    // The slice does not touch the filter's output.
    FREPKIT_CHECK(failures, boolean->GetOutput()->GetDimension() == 3);

    // A deep copy shares the composed model (no program to recompile) and evaluates the same.
    vtkNew<vtkFRepObject> deep;
    deep->DeepCopy(boolean->GetOutput());
    FREPKIT_CHECK(failures, deep->GetModel() == boolean->GetOutput()->GetModel());
    FREPKIT_CHECK(failures,
      SameBits(ValueAt(deep, { 0.1, 0.2, 0.3 }), ValueAt(boolean->GetOutput(), { 0.1, 0.2, 0.3 })));
  }

  // --- re-execution when an input's parameter changes, and only then
  {
    auto model = boolean->GetOutput()->GetModel();
    boolean->Update();
    FREPKIT_CHECK(failures, boolean->GetOutput()->GetModel() == model); // nothing changed
    sourceA->SetParameter(0, 2.0);
    boolean->Update();
    FREPKIT_CHECK(failures, boolean->GetOutput()->GetModel() != model);
    FREPKIT_CHECK(failures,
      Mismatches(boolean->GetOutput(), CompileTape(TwoBalls(2.0, 1.2, "s1 | s2")), 3) == 0);
    // Fixing a coordinate upstream: the filter combines what it gets (a 2-D operand A now).
    sourceA->SetParameter(0, 1.5);
  }

  // --- mismatched dimensions: one error naming both inputs, an empty output
  vtkNew<vtkHyperFunSource> disc;
  disc->SetModelText("disc(x[2], a[1]) { disc = 1 - (x[1]^2 + x[2]^2); }");
  disc->SetCoordinateRange(0, -1.5, 1.5);
  disc->SetCoordinateRange(1, -2.0, 2.0);
  boolean->SetSourceConnection(disc->GetOutputPort());
  events->Clear();
  boolean->Update();
  FREPKIT_CHECK(failures, events->Errors == 1);
  FREPKIT_CHECK(failures, events->ErrorText.find("same dimension") != std::string::npos);
  FREPKIT_CHECK(failures,
    events->ErrorText.find("3 free coordinates (x1, x2, x3) of ball") != std::string::npos);
  FREPKIT_CHECK(
    failures, events->ErrorText.find("2 free coordinates (x1, x2) of disc") != std::string::npos);
  FREPKIT_CHECK(failures, !boolean->GetOutput()->HasModel());
  FREPKIT_CHECK(failures, boolean->GetOutput()->GetDimension() == 0);
  FREPKIT_CHECK(failures, boolean->GetOutput()->GetTape() == nullptr);

  // --- the Cartesian product: a 2-D disc times a 1-D interval is a 3-D cylinder
  vtkNew<vtkHyperFunSource> slab;
  slab->SetModelText("slab(x[1], a[1]) { slab = (x[1] + 2) & (2 - x[1]); }");
  slab->SetCoordinateRange(0, -3.0, 3.0);
  boolean->SetInputConnection(0, disc->GetOutputPort());
  boolean->SetSourceConnection(slab->GetOutputPort());
  boolean->SetOperationToCartesianProduct();
  events->Clear();
  boolean->Update();
  FREPKIT_CHECK(failures, events->Errors == 0);
  {
    vtkFRepObject* out = boolean->GetOutput();
    FREPKIT_CHECK(failures, out->GetDimension() == 3);
    FREPKIT_CHECK(failures, out->GetObjectName() == "product(disc, slab)");
    // Names stay unique: the slab's x1 becomes x3.
    FREPKIT_CHECK(failures, out->GetCoordinateName(0) == "x1");
    FREPKIT_CHECK(failures, out->GetCoordinateName(1) == "x2");
    FREPKIT_CHECK(failures, out->GetCoordinateName(2) == "x3");
    double range[2];
    out->GetCoordinateRange(1, range);
    FREPKIT_CHECK(failures, range[0] == -2.0 && range[1] == 2.0);
    out->GetCoordinateRange(2, range);
    FREPKIT_CHECK(failures, range[0] == -3.0 && range[1] == 3.0);
    const auto cylinder = CompileTape(R"(my_model(x[3], a[1]) {
  d = 1 - (x[1]^2 + x[2]^2);
  h = (x[3] + 2) & (2 - x[3]);
  my_model = d @ h;
})");
    FREPKIT_CHECK(failures, Mismatches(out, cylinder, 3) == 0);
    FREPKIT_CHECK(failures, ValueAt(out, { 0.0, 0.5, 1.9 }) > 0.0);
    FREPKIT_CHECK(failures, ValueAt(out, { 0.0, 0.5, 2.1 }) < 0.0);
    FREPKIT_CHECK(failures, ValueAt(out, { 1.1, 0.0, 0.0 }) < 0.0);

    // Its cross-section at height 1 is the disc.
    vtkNew<vtkFRepObject> section;
    section->ShallowCopy(out);
    section->FixCoordinate(2, 1.0);
    FREPKIT_CHECK(failures, section->GetDimension() == 2);
    FREPKIT_CHECK(failures, ValueAt(section, { 0.0, 0.0 }) > 0.0);
    FREPKIT_CHECK(failures, ValueAt(section, { 0.8, 0.8 }) < 0.0);
  }

  // Names of the inputs are kept where they are unique (input data without a pipeline).
  {
    slab->Update();
    vtkNew<vtkFRepObject> named;
    named->ShallowCopy(slab->GetOutput());
    named->SetCoordinateName(0, "height");
    boolean->SetSourceData(named);
    boolean->Update();
    FREPKIT_CHECK(failures, boolean->GetOutput()->GetCoordinateName(2) == "height");
    FREPKIT_CHECK(failures, boolean->GetOutput()->GetDimension() == 3);
  }

  // --- an empty operand (a source whose text does not parse): an error and an empty output
  {
    vtkNew<vtkHyperFunSource> broken;
    broken->SetModelText("broken(x[3], a[1]) { broken = 1 +; }");
    vtkNew<frepkit_test::EventCounter> sourceEvents;
    sourceEvents->Observe(broken);
    boolean->SetOperationToUnion();
    boolean->SetInputConnection(0, sourceA->GetOutputPort());
    boolean->SetSourceConnection(broken->GetOutputPort());
    events->Clear();
    boolean->Update();
    FREPKIT_CHECK(failures, sourceEvents->Errors >= 1); // the parse error, where it belongs
    FREPKIT_CHECK(failures, events->Errors == 1);
    FREPKIT_CHECK(failures, events->ErrorText.find("operand B") != std::string::npos);
    FREPKIT_CHECK(failures, events->ErrorText.find("empty") != std::string::npos);
    FREPKIT_CHECK(failures, !boolean->GetOutput()->HasModel());

    // Repairing the input repairs the output.
    boolean->SetSourceConnection(sourceB->GetOutputPort());
    events->Clear();
    boolean->Update();
    FREPKIT_CHECK(failures, events->Errors == 0);
    FREPKIT_CHECK(failures,
      Mismatches(boolean->GetOutput(), CompileTape(TwoBalls(1.5, 1.2, "s1 | s2")), 3) == 0);
  }

  // --- A sliced upstream: its free coordinates are what counts
  {
    sourceA->Update();
    vtkNew<vtkFRepObject> cut;
    cut->ShallowCopy(sourceA->GetOutput());
    cut->FixCoordinate(2, 0.0);
    boolean->SetInputData(0, cut);
    boolean->SetSourceConnection(disc->GetOutputPort());
    events->Clear();
    boolean->Update();
    FREPKIT_CHECK(failures, events->Errors == 0);
    FREPKIT_CHECK(failures, boolean->GetOutput()->GetDimension() == 2);
    const auto expected = CompileTape(R"(my_model(x[2], a[1]) {
  s1 = 1.5^2 - ((x[1] - 0.5)^2 + x[2]^2 + 0^2);
  s2 = 1 - (x[1]^2 + x[2]^2);
  my_model = s1 | s2;
})");
    FREPKIT_CHECK(failures, Mismatches(boolean->GetOutput(), expected, 2) == 0);
  }

  // --- PrintSelf
  {
    std::ostringstream os;
    boolean->Print(os);
    FREPKIT_CHECK(failures, os.str().find("Operation: Union") != std::string::npos);
    FREPKIT_CHECK(failures, os.str().find("BlendDisplacement: 0.5") != std::string::npos);
    FREPKIT_CHECK(failures, os.str().find("BlendParameters: (2, 0.7)") != std::string::npos);
  }

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
