// vtkFRepObject: what a HyperFun source puts in it (dimension, names, intervals, field data),
// ShallowCopy shares the model and DeepCopy copies it, slicing by fixing coordinates, the
// cached tape, every Set/Get, PrintSelf.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkDoubleArray.h"
#include "vtkFRepObject.h"
#include "vtkFieldData.h"
#include "vtkHyperFunSource.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkStringArray.h"

#include "Eval/point_evaluator.h"

#include <cmath>
#include <sstream>
#include <string>

namespace
{
const char* SphereText = R"(-- a sphere of radius 5
my_model(x[3], a[1])
{
  array c[3];
  c = [0, 0, 0];
  my_model = hfSphere(x, c, 5);
}
)";

double Evaluate(vtkFRepObject* object, std::vector<double> point)
{
  frep::PointEvaluator evaluator(object->GetTape());
  return evaluator.value(point);
}
}

int TestFRepObject(int, char*[])
{
  int failures = 0;
  vtkNew<frepkit_test::EventCounter> events;

  // --- a sphere through the source
  vtkNew<vtkHyperFunSource> source;
  events->Observe(source);
  source->SetModelText(SphereText);
  source->SetCoordinateRange(2, -3, 4);
  source->UseSolidBoundsOff(); // the other intervals are DefaultCoordinateRange
  source->Update();
  vtkFRepObject* sphere = source->GetOutput();
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);
  FREPKIT_CHECK(failures, sphere != nullptr);
  FREPKIT_CHECK(failures, sphere->GetDataObjectType() == VTK_DATA_OBJECT);
  FREPKIT_CHECK(failures, sphere->IsA("vtkDataObject"));
  FREPKIT_CHECK(failures, sphere->HasModel());
  FREPKIT_CHECK(failures, sphere->GetObjectName() == "my_model");
  FREPKIT_CHECK(failures, sphere->GetDimension() == 3);
  FREPKIT_CHECK(failures, sphere->GetModelDimension() == 3);
  for (int i = 0; i < 3; ++i)
  {
    FREPKIT_CHECK(failures, sphere->GetFreeCoordinate(i) == i);
    FREPKIT_CHECK(failures, sphere->GetCoordinateName(i) == "x" + std::to_string(i + 1));
    FREPKIT_CHECK(failures, !sphere->IsCoordinateFixed(i));
    FREPKIT_CHECK(failures, std::isnan(sphere->GetFixedValue(i)));
  }
  FREPKIT_CHECK(failures, sphere->GetFreeCoordinate(3) == -1);
  double range[2];
  sphere->GetCoordinateRange(0, range);
  FREPKIT_CHECK(failures, range[0] == -10 && range[1] == 10);
  sphere->GetCoordinateRange(2, range);
  FREPKIT_CHECK(failures, range[0] == -3 && range[1] == 4);

  // field data mirrors the metadata
  vtkFieldData* fd = sphere->GetFieldData();
  auto* dimension = vtkIntArray::SafeDownCast(fd->GetAbstractArray("FRepDimension"));
  auto* modelDimension = vtkIntArray::SafeDownCast(fd->GetAbstractArray("FRepModelDimension"));
  auto* names = vtkStringArray::SafeDownCast(fd->GetAbstractArray("FRepCoordinateNames"));
  auto* intervals = vtkDoubleArray::SafeDownCast(fd->GetAbstractArray("FRepIntervals"));
  auto* fixed = vtkDoubleArray::SafeDownCast(fd->GetAbstractArray("FRepFixedValues"));
  auto* objectName = vtkStringArray::SafeDownCast(fd->GetAbstractArray("FRepObjectName"));
  auto* parameters = vtkDoubleArray::SafeDownCast(fd->GetAbstractArray("FRepParameters"));
  FREPKIT_CHECK(failures, dimension && dimension->GetValue(0) == 3);
  FREPKIT_CHECK(failures, modelDimension && modelDimension->GetValue(0) == 3);
  FREPKIT_CHECK(failures, names && names->GetNumberOfValues() == 3 && names->GetValue(1) == "x2");
  FREPKIT_CHECK(failures,
    intervals && intervals->GetNumberOfTuples() == 3 && intervals->GetNumberOfComponents() == 2 &&
      intervals->GetComponent(2, 0) == -3 && intervals->GetComponent(2, 1) == 4 &&
      intervals->GetComponent(0, 0) == -10);
  FREPKIT_CHECK(
    failures, fixed && fixed->GetNumberOfTuples() == 3 && std::isnan(fixed->GetValue(0)));
  FREPKIT_CHECK(failures, objectName && objectName->GetValue(0) == "my_model");
  FREPKIT_CHECK(failures, parameters && parameters->GetNumberOfTuples() == 0);

  // the tape evaluates the sphere and is cached until the object changes
  auto tape = sphere->GetTape();
  FREPKIT_CHECK(failures, tape && tape->input_count == 3);
  FREPKIT_CHECK(failures, sphere->GetTape() == tape);
  FREPKIT_CHECK(failures, Evaluate(sphere, { 1, 2, 2 }) == 25 - 9);
  const auto description = sphere->GetEvaluationDescription();
  FREPKIT_CHECK(failures, description.Tape == tape);
  FREPKIT_CHECK(failures, description.Names.size() == 3 && description.Names[2] == "x3");
  FREPKIT_CHECK(failures, description.Ranges.size() == 3 && description.Ranges[2][0] == -3);
  FREPKIT_CHECK(failures, description.Coordinates == std::vector<int>({ 0, 1, 2 }));
  FREPKIT_CHECK(failures, description.AttributeCount == 1);

  // --- ShallowCopy shares the model; the copy is independent afterwards
  vtkNew<vtkFRepObject> shallow;
  shallow->ShallowCopy(sphere);
  FREPKIT_CHECK(failures, shallow->GetModel() == sphere->GetModel());
  FREPKIT_CHECK(failures, shallow->GetDimension() == 3);
  shallow->GetCoordinateRange(2, range);
  FREPKIT_CHECK(failures, range[0] == -3 && range[1] == 4);
  FREPKIT_CHECK(failures, shallow->GetFieldData()->GetAbstractArray("FRepIntervals") != nullptr);
  // NewInstance + ShallowCopy, as ParaView copies outputs
  vtkFRepObject* instance = sphere->NewInstance();
  instance->ShallowCopy(sphere);
  FREPKIT_CHECK(failures, instance->GetModel() == sphere->GetModel());
  instance->Delete();

  // --- slicing: fix x3 = 3 -> 2-D disc of radius 4; the source's object is untouched
  const vtkMTimeType before = shallow->GetMTime();
  shallow->FixCoordinate(2, 3.0);
  FREPKIT_CHECK(failures, shallow->GetMTime() > before);
  FREPKIT_CHECK(failures, shallow->GetDimension() == 2);
  FREPKIT_CHECK(failures, shallow->GetModelDimension() == 3);
  FREPKIT_CHECK(failures, shallow->IsCoordinateFixed(2) && shallow->GetFixedValue(2) == 3.0);
  FREPKIT_CHECK(failures, shallow->GetTape() != tape && shallow->GetTape()->input_count == 2);
  FREPKIT_CHECK(failures, Evaluate(shallow, { 4, 0 }) == 0.0);
  FREPKIT_CHECK(failures, sphere->GetDimension() == 3);
  FREPKIT_CHECK(failures,
    vtkIntArray::SafeDownCast(sphere->GetFieldData()->GetAbstractArray("FRepDimension"))
        ->GetValue(0) == 3);
  FREPKIT_CHECK(failures,
    vtkIntArray::SafeDownCast(shallow->GetFieldData()->GetAbstractArray("FRepDimension"))
        ->GetValue(0) == 2);
  auto* shallowFixed =
    vtkDoubleArray::SafeDownCast(shallow->GetFieldData()->GetAbstractArray("FRepFixedValues"));
  FREPKIT_CHECK(failures, shallowFixed && shallowFixed->GetValue(2) == 3.0);
  // reorder the free coordinates: (x2, x1)
  FREPKIT_CHECK(failures, shallow->SetFreeCoordinates({ 1, 0 }));
  FREPKIT_CHECK(failures, shallow->GetFreeCoordinate(0) == 1);
  FREPKIT_CHECK(failures, shallow->GetEvaluationDescription().Names[0] == "x2");
  FREPKIT_CHECK(failures, shallow->GetSpecialisation().input_order == std::vector<int>({ 1, 0 }));
  // releasing x3 appends it as the last axis
  shallow->ReleaseCoordinate(2);
  FREPKIT_CHECK(failures, shallow->GetDimension() == 3 && shallow->GetFreeCoordinate(2) == 2);
  FREPKIT_CHECK(failures, Evaluate(shallow, { 2, 1, 2 }) == 25 - 9);
  // errors: bad coordinates, a coordinate neither free nor fixed, an empty interval
  events->Clear();
  events->Observe(shallow);
  FREPKIT_CHECK(failures, !shallow->SetFreeCoordinates({ 0, 1 }));
  FREPKIT_CHECK(failures,
    events->Errors == 1 &&
      events->ErrorText.find("neither listed as free nor fixed") != std::string::npos);
  FREPKIT_CHECK(failures, !shallow->SetFreeCoordinates({ 0, 0, 2 }));
  FREPKIT_CHECK(failures, !shallow->SetFreeCoordinates({ 0, 1, 7 }));
  shallow->FixCoordinate(5, 1.0);
  shallow->SetCoordinateRange(0, 2, 1);
  FREPKIT_CHECK(failures, events->Errors == 5);
  FREPKIT_CHECK(failures, shallow->GetDimension() == 3);

  // names and parameters
  shallow->SetCoordinateName(0, "u");
  FREPKIT_CHECK(failures, shallow->GetCoordinateName(0) == "u");
  shallow->SetParameters({ 1.5, 2.5 });
  FREPKIT_CHECK(failures,
    shallow->GetNumberOfParameters() == 2 && shallow->GetParameter(1) == 2.5 &&
      shallow->GetParameter(7) == 0.0);
  FREPKIT_CHECK(failures, shallow->GetParameters().size() == 2);
  // a[1] only: the extra value is dropped from the specialisation
  FREPKIT_CHECK(failures, shallow->GetSpecialisation().parameters.size() == 1);

  // --- DeepCopy: a model of its own, the same state and values
  vtkNew<vtkFRepObject> deep;
  deep->DeepCopy(shallow);
  FREPKIT_CHECK(failures, deep->GetModel() && deep->GetModel() != shallow->GetModel());
  FREPKIT_CHECK(failures, deep->GetObjectName() == "my_model");
  FREPKIT_CHECK(failures, deep->GetCoordinateName(0) == "u");
  FREPKIT_CHECK(failures, deep->GetFreeCoordinates() == shallow->GetFreeCoordinates());
  FREPKIT_CHECK(failures, deep->GetParameters() == shallow->GetParameters());
  FREPKIT_CHECK(failures, Evaluate(deep, { 2, 1, 2 }) == Evaluate(shallow, { 2, 1, 2 }));
  auto* deepNames =
    vtkStringArray::SafeDownCast(deep->GetFieldData()->GetAbstractArray("FRepCoordinateNames"));
  FREPKIT_CHECK(failures, deepNames && deepNames->GetValue(1) == "u");

  // --- pipeline information helpers
  vtkNew<vtkInformation> info;
  info->Set(vtkDataObject::DATA_OBJECT(), deep);
  FREPKIT_CHECK(failures, vtkFRepObject::GetData(info) == deep.GetPointer());
  vtkNew<vtkInformationVector> infos;
  infos->Append(info);
  FREPKIT_CHECK(failures, vtkFRepObject::GetData(infos, 0) == deep.GetPointer());
  FREPKIT_CHECK(failures, vtkFRepObject::GetData(static_cast<vtkInformation*>(nullptr)) == nullptr);

  // --- Initialize empties the object and its field data
  deep->Initialize();
  FREPKIT_CHECK(failures,
    !deep->HasModel() && deep->GetDimension() == 0 && deep->GetModelDimension() == 0 &&
      !deep->GetTape());
  FREPKIT_CHECK(failures, deep->GetFieldData()->GetAbstractArray("FRepDimension") == nullptr);
  FREPKIT_CHECK(failures, deep->GetEvaluationDescription().Tape == nullptr);
  // copies of an empty object are empty
  vtkNew<vtkFRepObject> empty;
  empty->ShallowCopy(deep);
  FREPKIT_CHECK(failures, !empty->HasModel());
  empty->DeepCopy(deep);
  FREPKIT_CHECK(failures, !empty->HasModel());

  // --- a 5-D model
  vtkNew<vtkHyperFunSource> source5;
  source5->SetFileName(FREPKIT_SOURCE_DIR "/Examples/homotopy5d.hf");
  source5->Update();
  vtkFRepObject* object5 = source5->GetOutput();
  FREPKIT_CHECK(failures, object5->GetDimension() == 5);
  FREPKIT_CHECK(failures, object5->GetCoordinateName(4) == "x5");
  FREPKIT_CHECK(failures, object5->GetTape()->input_count == 5);
  object5->FixCoordinate(3, 0.5);
  object5->FixCoordinate(4, 0.25);
  FREPKIT_CHECK(failures, object5->GetDimension() == 3);
  FREPKIT_CHECK(failures, object5->GetTape()->input_count == 3);
  FREPKIT_CHECK(failures, object5->GetActualMemorySize() > 0);

  // --- PrintSelf
  std::ostringstream printed;
  object5->Print(printed);
  shallow->Print(printed);
  deep->Print(printed);
  FREPKIT_CHECK(failures, printed.str().find("Dimension: 3") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("fixed = 0.5") != std::string::npos);
  FREPKIT_CHECK(failures, printed.str().find("Model: (none)") != std::string::npos);

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
