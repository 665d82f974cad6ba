// vtkHyperFunSource: text and file input (FileName wins), object selection (my_model, first,
// case-insensitive, unknown -> error listing the objects), parameters, ranges, every parse
// diagnostic as file:line:col through vtkErrorMacro with an empty output and no crash, MTime
// per property, CAN_HANDLE_PIECE_REQUEST, Set/Get, PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepObject.h"
#include "vtkHyperFunSource.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTestErrorObserver.h"

#include "Eval/point_evaluator.h"
#include "Language/parser.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace
{
const char* TwoObjects = R"(Ball(x[3], a[1])
{
  Ball = a[1] * a[1] - x[1] * x[1] - x[2] * x[2] - x[3] * x[3];
}

Slab(x[3], a[2])
{
  Slab = (x[3] - a[1]) & (a[2] - x[3]);
}
)";

// Two errors the parser recovers from: a missing operand, then a missing ';'.
const char* BadText = R"(first(x[3], a[1])
{
  first = 1 +;
}

second(x[3], a[1])
{
  second = x[1]
}
)";

double Value(vtkFRepObject* object, std::vector<double> p)
{
  frep::PointEvaluator evaluator(object->GetTape());
  return evaluator.value(p);
}

int CountMatches(const std::string& text, const std::regex& re)
{
  return static_cast<int>(
    std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}
}

int TestHyperFunSource(int, char*[])
{
  int failures = 0;
  vtkNew<frepkit_test::EventCounter> events;
  vtkNew<vtkTest::ErrorObserver> errors;

  vtkNew<vtkHyperFunSource> source;
  events->Observe(source);
  source->AddObserver(vtkCommand::ErrorEvent, errors);

  // --- defaults
  FREPKIT_CHECK(failures, source->GetModelText() == nullptr);
  FREPKIT_CHECK(failures, source->GetFileName() == nullptr);
  FREPKIT_CHECK(failures, source->GetObjectName() == nullptr);
  FREPKIT_CHECK(failures, source->GetNumberOfParameters() == 0);
  FREPKIT_CHECK(failures, source->GetNumberOfInputPorts() == 0);
  FREPKIT_CHECK(failures, source->GetNumberOfOutputPorts() == 1);
  double range[2];
  source->GetDefaultCoordinateRange(range);
  FREPKIT_CHECK(failures, range[0] == -10 && range[1] == 10);
  source->GetCoordinateRange(7, range);
  FREPKIT_CHECK(failures, range[0] == -10 && range[1] == 10);

  // --- nothing set: an error, an empty output
  source->Update();
  FREPKIT_CHECK(failures, errors->CheckErrorMessage("neither FileName nor ModelText") == 0);
  FREPKIT_CHECK(failures, source->GetOutput() && !source->GetOutput()->HasModel());

  // --- the first object when there is no my_model; parameters
  source->SetModelText(TwoObjects);
  source->SetParameter(0, 2.0);
  FREPKIT_CHECK(failures, source->GetNumberOfParameters() == 1 && source->GetParameter(0) == 2.0);
  events->Clear();
  source->Update();
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  vtkFRepObject* out = source->GetOutput();
  FREPKIT_CHECK(failures, out->GetObjectName() == "ball");
  FREPKIT_CHECK(failures, out->GetParameters() == std::vector<double>({ 2.0 }));
  FREPKIT_CHECK(failures, Value(out, { 1, 1, 1 }) == 4.0 - 3.0);

  // --- ObjectName is case-insensitive; a[] grows with zeros
  source->SetObjectName("SLAB");
  source->SetParameter(1, 1.0);  // a = [2, 1]: empty slab 2 <= z <= 1
  source->SetParameter(0, -1.0); // a = [-1, 1]
  FREPKIT_CHECK(failures, source->GetNumberOfParameters() == 2);
  source->Update();
  out = source->GetOutput();
  FREPKIT_CHECK(failures, out->GetObjectName() == "slab");
  FREPKIT_CHECK(failures, Value(out, { 0, 0, 0 }) > 0);
  FREPKIT_CHECK(failures, Value(out, { 0, 0, 2 }) < 0);
  source->SetNumberOfParameters(1);
  FREPKIT_CHECK(failures, source->GetNumberOfParameters() == 1 && source->GetParameter(1) == 0.0);
  source->Update();
  FREPKIT_CHECK(failures, source->GetOutput()->GetParameters() == std::vector<double>({ -1.0 }));
  // a[2] = 0 now: the slab is -1 <= z <= 0
  FREPKIT_CHECK(failures, Value(source->GetOutput(), { 0, 0, 0.5 }) < 0);
  FREPKIT_CHECK(failures, Value(source->GetOutput(), { 0, 0, -0.5 }) > 0);
  source->RemoveAllParameters();
  FREPKIT_CHECK(failures, source->GetNumberOfParameters() == 0);

  // too many parameters: a warning, not an error
  source->SetObjectName("ball");
  source->SetParameter(3, 1.0);
  events->Clear();
  source->Update();
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 1);
  FREPKIT_CHECK(failures, events->WarningText.find("extra ones are ignored") != std::string::npos);
  source->RemoveAllParameters();

  // --- an unknown object: an error listing the objects, an empty output
  source->SetObjectName("cube");
  events->Clear();
  source->Update();
  FREPKIT_CHECK(failures, events->Errors == 1);
  FREPKIT_CHECK(failures, errors->CheckErrorMessage("no object named 'cube'") == 0);
  FREPKIT_CHECK(failures, events->ErrorText.find("no object named 'cube'") != std::string::npos);
  FREPKIT_CHECK(failures, events->ErrorText.find("ball, slab") != std::string::npos);
  FREPKIT_CHECK(failures, !source->GetOutput()->HasModel());
  FREPKIT_CHECK(failures, source->GetOutput()->GetDimension() == 0);
  source->SetObjectName(nullptr);

  // --- coordinate ranges (the default range's mechanics; the solid's bounds:
  // TestHyperFunSourceSolidBounds)
  FREPKIT_CHECK(failures, source->GetUseSolidBounds() == 1);
  source->UseSolidBoundsOff();
  source->SetCoordinateRange(1, -2, 3);
  source->SetDefaultCoordinateRange(-5, 5);
  source->Update();
  out = source->GetOutput();
  out->GetCoordinateRange(1, range);
  FREPKIT_CHECK(failures, range[0] == -2 && range[1] == 3);
  out->GetCoordinateRange(0, range);
  FREPKIT_CHECK(failures, range[0] == -5 && range[1] == 5);
  source->GetCoordinateRange(1, range);
  FREPKIT_CHECK(failures, range[0] == -2 && range[1] == 3);
  events->Clear();
  source->SetCoordinateRange(0, 1, -1);
  source->SetCoordinateRange(-1, 0, 1);
  source->SetParameter(-1, 0);
  source->SetNumberOfParameters(-2);
  FREPKIT_CHECK(failures, events->Errors == 4);
  source->RemoveAllCoordinateRanges();
  source->SetDefaultCoordinateRange(-10, 10);
  source->GetCoordinateRange(1, range);
  FREPKIT_CHECK(failures, range[0] == -10 && range[1] == 10);
  source->UseSolidBoundsOn();

  // --- MTime changes with every property
  auto changes = [&](const char* what, auto&& change)
  {
    const vtkMTimeType before = source->GetMTime();
    change();
    if (!(source->GetMTime() > before))
    {
      std::cerr << "MTime did not change with " << what << std::endl;
      ++failures;
    }
    // the same value again does not modify
    const vtkMTimeType after = source->GetMTime();
    change();
    if (source->GetMTime() != after)
    {
      std::cerr << "MTime changed when " << what << " was set to the same value" << std::endl;
      ++failures;
    }
  };
  changes("ModelText", [&] { source->SetModelText("my_model(x[3], a[1]) { my_model = 1; }"); });
  changes("FileName", [&] { source->SetFileName("/nonexistent.hf"); });
  changes("ObjectName", [&] { source->SetObjectName("my_model"); });
  changes("SetParameter", [&] { source->SetParameter(2, 0.5); });
  changes("SetNumberOfParameters", [&] { source->SetNumberOfParameters(5); });
  changes("SetCoordinateRange", [&] { source->SetCoordinateRange(0, -1, 1); });
  changes("UseSolidBounds", [&] { source->SetUseSolidBounds(0); });
  changes("DefaultCoordinateRange", [&] { source->SetDefaultCoordinateRange(-3, 3); });
  changes("RemoveAllCoordinateRanges", [&] { source->RemoveAllCoordinateRanges(); });
  changes("RemoveAllParameters", [&] { source->RemoveAllParameters(); });
  changes("FileName reset", [&] { source->SetFileName(nullptr); });
  changes("ObjectName reset", [&] { source->SetObjectName(nullptr); });

  // an unreadable file: an error naming it
  source->SetFileName("/nonexistent/model.hf");
  events->Clear();
  source->Update();
  FREPKIT_CHECK(failures,
    events->Errors == 1 &&
      events->ErrorText.find("/nonexistent/model.hf: cannot open") != std::string::npos);
  FREPKIT_CHECK(failures, !source->GetOutput()->HasModel());

  // --- parse errors in text: every diagnostic, each as <string>:line:col, no crash
  const frep::ParseResult expected = frep::parse_program(BadText, "<string>");
  FREPKIT_CHECK(failures, expected.diagnostics.size() >= 2);
  source->SetFileName(nullptr);
  source->SetModelText(BadText);
  events->Clear();
  errors->Clear();
  source->Update();
  FREPKIT_CHECK(failures, events->Errors == static_cast<int>(expected.diagnostics.size()));
  const std::regex position(R"(<string>:([0-9]+):([0-9]+): error: )");
  FREPKIT_CHECK(failures,
    CountMatches(events->ErrorText, position) == static_cast<int>(expected.diagnostics.size()));
  for (const frep::Diagnostic& d : expected.diagnostics)
  {
    FREPKIT_CHECK(failures, events->ErrorText.find(d.format()) != std::string::npos);
  }
  FREPKIT_CHECK(failures, errors->CheckErrorMessage("<string>:3:") == 0);
  FREPKIT_CHECK(failures, !source->GetOutput()->HasModel());
  FREPKIT_CHECK(failures, source->GetOutput()->GetDimension() == 0);

  // --- a .hf file: FileName wins over ModelText; errors name the file
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::string good = (dir / "frepkit_TestHyperFunSource_good.hf").string();
  const std::string bad = (dir / "frepkit_TestHyperFunSource_bad.hf").string();
  {
    std::ofstream(good) << "my_model(x[4], a[1])\n{\n  my_model = 1 - x[4];\n}\n";
    std::ofstream(bad) << "my_model(x[3], a[1])\n{\n  my_model = x[1] +* 2;\n}\n";
  }
  source->SetFileName(good.c_str());
  source->SetModelText(TwoObjects);
  events->Clear();
  source->Update();
  FREPKIT_CHECK(failures, events->Errors == 0);
  FREPKIT_CHECK(failures, source->GetOutput()->GetDimension() == 4);
  FREPKIT_CHECK(failures, source->GetOutput()->GetObjectName() == "my_model");
  source->SetFileName(bad.c_str());
  events->Clear();
  source->Update();
  FREPKIT_CHECK(failures, events->Errors >= 1);
  FREPKIT_CHECK(failures, events->ErrorText.find(bad + ":3:") != std::string::npos);
  FREPKIT_CHECK(failures, !source->GetOutput()->HasModel());
  // a file with no object
  {
    std::ofstream(bad) << "-- nothing here\n";
  }
  source->Modified();
  events->Clear();
  source->Update();
  FREPKIT_CHECK(failures,
    events->Errors == 1 && events->ErrorText.find("defines no object") != std::string::npos);
  std::filesystem::remove(good);
  std::filesystem::remove(bad);

  // --- recovery after errors: good text again
  source->SetFileName(nullptr);
  source->SetModelText(TwoObjects);
  events->Clear();
  source->Update();
  FREPKIT_CHECK(failures, events->Errors == 0 && source->GetOutput()->GetDimension() == 3);

  // --- every rank builds the whole object
  source->UpdateInformation();
  vtkInformation* outInfo = source->GetOutputInformation(0);
  FREPKIT_CHECK(failures, outInfo->Get(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST()) == 1);
  // a piece request of another rank still gives the full object
  source->UpdatePiece(1, 2, 0);
  FREPKIT_CHECK(failures, source->GetOutput()->GetDimension() == 3);

  // --- parameters change the output without reparsing (same model instance)
  const auto model = source->GetOutput()->GetModel();
  source->SetParameter(0, 3.0);
  source->Update();
  FREPKIT_CHECK(failures, source->GetOutput()->GetModel() == model);
  FREPKIT_CHECK(failures, Value(source->GetOutput(), { 0, 0, 0 }) == 9.0);

  // --- PrintSelf
  std::ostringstream printed;
  source->Print(printed);
  FREPKIT_CHECK(failures, printed.str().find("Parameters (1): 3") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("CachedModel: ball") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("UseSolidBounds: Off") != std::string::npos);

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
