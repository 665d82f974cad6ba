// Upstream executions of FRep pipelines, counted (RequestData of every stage, by EndEvent):
// vtkHyperFunSource -> vtkFRepSlice -> vtkFRepSampler, and a vtkFRepBoolean of the slice and a
// second source. UpdateInformation of the downstream end executes nobody and still knows the
// grid (the vtkFRepInformation keys); one Update executes each stage once; a downstream change
// re-executes nobody upstream; the keys equal the objects that are then produced; a failed
// source leaves no stale keys downstream; keys cross a generic pass-through filter; an input
// given as data is described from the object.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkFRepBoolean.h"
#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkFRepSampler.h"
#include "vtkFRepSlice.h"
#include "vtkHyperFunSource.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationStringKey.h"
#include "vtkInformationStringVectorKey.h"
#include "vtkNew.h"
#include "vtkPassThrough.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
#include <string>

namespace
{
const char* const Model4D = R"(my_model(x[4], a[1])
{
  r = 2 + a[1] + x[4];
  my_model = r * r - x[1] * x[1] - x[2] * x[2] - x[3] * x[3];
}
)";

const char* const Box3D = R"(box(x[3], a[1])
{
  box = 1 - x[1] * x[1];
}
)";


// The keys of an output port equal the description of the object it holds.
bool KeysDescribe(vtkAlgorithm* algorithm, int port = 0)
{
  vtkFRepInformation::Metadata keys;
  vtkFRepInformation::Metadata object;
  const bool hasKeys =
    vtkFRepInformation::Get(algorithm->GetOutputInformation(port), keys);
  const bool hasObject = vtkFRepInformation::Describe(
    vtkFRepObject::SafeDownCast(algorithm->GetOutputDataObject(port)), object);
  if (hasKeys != hasObject)
  {
    std::cerr << algorithm->GetClassName() << ": keys " << hasKeys << ", object " << hasObject
              << std::endl;
    return false;
  }
  bool fixedEqual = keys.FixedValues.size() == object.FixedValues.size();
  for (std::size_t c = 0; fixedEqual && c < keys.FixedValues.size(); ++c)
  {
    fixedEqual = (std::isnan(keys.FixedValues[c]) && std::isnan(object.FixedValues[c])) ||
      keys.FixedValues[c] == object.FixedValues[c];
  }
  const bool same = keys.ObjectName == object.ObjectName && keys.Names == object.Names &&
    keys.Ranges == object.Ranges && fixedEqual && keys.FreeCoordinates == object.FreeCoordinates &&
    keys.Parameters == object.Parameters;
  if (!same)
  {
    std::cerr << algorithm->GetClassName() << ": the keys (" << keys.ObjectName << ", "
              << keys.GetDimension() << "-D) differ from the object (" << object.ObjectName
              << ", " << object.GetDimension() << "-D)" << std::endl;
  }
  return same;
}

bool WholeExtentIs(vtkAlgorithm* algorithm, int nx, int ny, int nz)
{
  int e[6];
  algorithm->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), e);
  return e[0] == 0 && e[1] == nx - 1 && e[2] == 0 && e[3] == ny - 1 && e[4] == 0 && e[5] == nz - 1;
}
}

int TestFRepPipelineExecutions(int, char*[])
{
  int failures = 0;
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(Model4D);
  source->SetCoordinateRange(0, -4, 4);
  source->UseSolidBoundsOff(); // the grid below is over hfp's default box
  vtkNew<vtkFRepSlice> slice;
  slice->SetInputConnection(source->GetOutputPort());
  slice->SetFixedValue(3, 0.5);
  vtkNew<vtkFRepSampler> sampler;
  sampler->SetInputConnection(slice->GetOutputPort());
  sampler->SetSampleDimensions(16, 15, 14);

  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(source);
  events->Observe(slice);
  events->Observe(sampler);
  vtkNew<frepkit_test::ExecutionCounter> sourceRuns;
  vtkNew<frepkit_test::ExecutionCounter> sliceRuns;
  vtkNew<frepkit_test::ExecutionCounter> samplerRuns;
  source->AddObserver(vtkCommand::EndEvent, sourceRuns);
  slice->AddObserver(vtkCommand::EndEvent, sliceRuns);
  sampler->AddObserver(vtkCommand::EndEvent, samplerRuns);
  const auto runs = [&](int s, int l, int m)
  {
    const bool ok = sourceRuns->Count == s && sliceRuns->Count == l && samplerRuns->Count == m;
    if (!ok)
    {
      std::cerr << "executions: source " << sourceRuns->Count << ", slice " << sliceRuns->Count
                << ", sampler " << samplerRuns->Count << "; expected " << s << ", " << l << ", "
                << m << std::endl;
    }
    return ok;
  };

  // --- the information pass of the downstream end executes nobody, and knows the grid
  sampler->UpdateInformation();
  FREPKIT_CHECK(failures, runs(0, 0, 0));
  FREPKIT_CHECK(failures, WholeExtentIs(sampler, 16, 15, 14));
  {
    double origin[3];
    sampler->GetOutputInformation(0)->Get(vtkDataObject::ORIGIN(), origin);
    FREPKIT_CHECK(failures, origin[0] == -4 && origin[1] == -10 && origin[2] == -10);
    vtkInformation* sourceInfo = source->GetOutputInformation(0);
    FREPKIT_CHECK(failures, sourceInfo->Get(vtkFRepInformation::DIMENSION()) == 4);
    FREPKIT_CHECK(failures,
      std::string(sourceInfo->Get(vtkFRepInformation::OBJECT_NAME())) == "my_model");
    FREPKIT_CHECK(failures,
      std::string(vtkFRepInformation::COORDINATE_NAMES()->Get(sourceInfo, 3)) == "x4");
    vtkInformation* sliceInfo = slice->GetOutputInformation(0);
    FREPKIT_CHECK(failures, sliceInfo->Get(vtkFRepInformation::DIMENSION()) == 3);
    FREPKIT_CHECK(failures, sliceInfo->Get(vtkFRepInformation::MODEL_DIMENSION()) == 4);
    FREPKIT_CHECK(failures, sliceInfo->Get(vtkFRepInformation::FIXED_VALUES())[3] == 0.5);
    FREPKIT_CHECK(failures, std::isnan(sliceInfo->Get(vtkFRepInformation::FIXED_VALUES())[0]));
    // the sampler's image describes no FRep object
    FREPKIT_CHECK(failures, !vtkFRepInformation::Has(sampler->GetOutputInformation(0)));
  }
  sampler->UpdateInformation(); // again: still nothing
  FREPKIT_CHECK(failures, runs(0, 0, 0));

  // --- one update executes each stage once; the keys describe what was produced
  sampler->Update();
  FREPKIT_CHECK(failures, runs(1, 1, 1));
  FREPKIT_CHECK(failures, sampler->GetOutput()->GetNumberOfPoints() == 16 * 15 * 14);
  FREPKIT_CHECK(failures, KeysDescribe(source) && KeysDescribe(slice));
  sampler->Update();
  FREPKIT_CHECK(failures, runs(1, 1, 1));

  // --- downstream changes re-execute nobody upstream
  sampler->SetSampleDimensions(8, 9, 10);
  sampler->UpdateInformation();
  FREPKIT_CHECK(failures, runs(1, 1, 1) && WholeExtentIs(sampler, 8, 9, 10));
  sampler->Update();
  FREPKIT_CHECK(failures, runs(1, 1, 2));
  sampler->SetModelBounds(-1, 1, -1, 1, -1, 1);
  sampler->Update();
  FREPKIT_CHECK(failures, runs(1, 1, 3));
  slice->SetFixedValue(3, 1.0);
  sampler->UpdateInformation();
  FREPKIT_CHECK(failures, runs(1, 1, 3));
  FREPKIT_CHECK(failures,
    slice->GetOutputInformation(0)->Get(vtkFRepInformation::FIXED_VALUES())[3] == 1.0);
  sampler->Update();
  FREPKIT_CHECK(failures, runs(1, 2, 4) && KeysDescribe(slice));
  slice->SetFreeCoordinateOrder("x3,x1,x2");
  sampler->Update();
  FREPKIT_CHECK(failures, runs(1, 3, 5) && KeysDescribe(slice));
  FREPKIT_CHECK(failures,
    slice->GetOutputInformation(0)->Get(vtkFRepInformation::FREE_COORDINATES())[0] == 2);
  // pieces (as MPI ranks ask for them) re-execute nobody upstream either
  sampler->UpdatePiece(1, 2, 0);
  sampler->UpdatePiece(0, 2, 0);
  FREPKIT_CHECK(failures, sourceRuns->Count == 1 && sliceRuns->Count == 3);

  // --- an upstream change: the information pass still executes nobody; the update, each once
  source->SetParameter(0, 0.5);
  sampler->UpdateInformation();
  FREPKIT_CHECK(failures, sourceRuns->Count == 1 && sliceRuns->Count == 3);
  {
    vtkInformation* sliceInfo = slice->GetOutputInformation(0);
    FREPKIT_CHECK(failures,
      sliceInfo->Length(vtkFRepInformation::PARAMETERS()) == 1 &&
        sliceInfo->Get(vtkFRepInformation::PARAMETERS())[0] == 0.5);
  }
  const int samplerBefore = samplerRuns->Count;
  sampler->Update();
  FREPKIT_CHECK(failures, runs(2, 4, samplerBefore + 1) && KeysDescribe(slice));

  // --- a source that fails: one error (from the source, once), no stale keys downstream
  events->Clear();
  source->SetModelText("my_model(x[4], a[1]) { my_model = ; }");
  sampler->Update();
  FREPKIT_CHECK(failures, events->Errors == 1 && events->Warnings == 0);
  FREPKIT_CHECK(failures, !vtkFRepInformation::Has(source->GetOutputInformation(0)));
  FREPKIT_CHECK(failures, !vtkFRepInformation::Has(slice->GetOutputInformation(0)));
  FREPKIT_CHECK(failures, sampler->GetOutput()->GetNumberOfPoints() == 0);
  source->SetModelText(Model4D);
  events->Clear();
  sampler->Update();
  FREPKIT_CHECK(failures, events->Errors == 0 && sampler->GetOutput()->GetNumberOfPoints() > 0);
  FREPKIT_CHECK(failures, KeysDescribe(source) && KeysDescribe(slice));

  // --- a boolean of the slice and a 3-D source: keys from keys, nobody executed before Update
  {
    vtkNew<vtkHyperFunSource> box;
    box->SetModelText(Box3D);
    box->SetCoordinateRange(1, -20, 3);
    vtkNew<vtkFRepBoolean> boolean;
    boolean->SetInputConnection(0, slice->GetOutputPort());
    boolean->SetSourceConnection(box->GetOutputPort());
    vtkNew<vtkFRepSampler> grid;
    grid->SetInputConnection(boolean->GetOutputPort());
    grid->SetSampleDimensions(6, 7, 8);
    vtkNew<frepkit_test::ExecutionCounter> boxRuns;
    vtkNew<frepkit_test::ExecutionCounter> booleanRuns;
    box->AddObserver(vtkCommand::EndEvent, boxRuns);
    boolean->AddObserver(vtkCommand::EndEvent, booleanRuns);
    const int sources = sourceRuns->Count;
    const int slices = sliceRuns->Count;
    grid->UpdateInformation();
    FREPKIT_CHECK(failures, boxRuns->Count == 0 && booleanRuns->Count == 0);
    FREPKIT_CHECK(failures, sourceRuns->Count == sources && sliceRuns->Count == slices);
    FREPKIT_CHECK(failures, WholeExtentIs(grid, 6, 7, 8));
    vtkInformation* info = boolean->GetOutputInformation(0);
    FREPKIT_CHECK(failures, info->Get(vtkFRepInformation::DIMENSION()) == 3);
    grid->Update();
    FREPKIT_CHECK(failures, boxRuns->Count == 1 && booleanRuns->Count == 1);
    FREPKIT_CHECK(failures, sourceRuns->Count == sources && sliceRuns->Count == slices);
    FREPKIT_CHECK(failures, KeysDescribe(boolean));
    boolean->SetOperationToCartesianProduct();
    boolean->UpdateInformation(); // (the 6-D product is not for the 3-D grid)
    FREPKIT_CHECK(failures, info->Get(vtkFRepInformation::DIMENSION()) == 6);
    FREPKIT_CHECK(failures, booleanRuns->Count == 1 && boxRuns->Count == 1);
    boolean->Update();
    FREPKIT_CHECK(failures, booleanRuns->Count == 2 && boxRuns->Count == 1);
    FREPKIT_CHECK(failures, KeysDescribe(boolean));
    FREPKIT_CHECK(failures, sourceRuns->Count == sources && sliceRuns->Count == slices);
  }

  // --- the keys cross a generic pass-through filter (CopyDefaultInformation)
  {
    vtkNew<vtkHyperFunSource> other;
    other->SetModelText(Model4D);
    vtkNew<vtkPassThrough> pass;
    pass->SetInputConnection(other->GetOutputPort());
    vtkNew<vtkFRepSlice> cut;
    cut->SetInputConnection(pass->GetOutputPort());
    cut->SetFixedValueByName("x4", 0.0);
    vtkNew<vtkFRepSampler> grid;
    grid->SetInputConnection(cut->GetOutputPort());
    grid->SetSampleDimensions(5, 5, 5);
    vtkNew<frepkit_test::ExecutionCounter> otherRuns;
    other->AddObserver(vtkCommand::EndEvent, otherRuns);
    grid->UpdateInformation();
    FREPKIT_CHECK(failures, otherRuns->Count == 0 && WholeExtentIs(grid, 5, 5, 5));
    FREPKIT_CHECK(failures,
      pass->GetOutputInformation(0)->Get(vtkFRepInformation::DIMENSION()) == 4);
    grid->Update();
    FREPKIT_CHECK(failures, otherRuns->Count == 1 && grid->GetOutput()->GetNumberOfPoints() == 125);
  }

  // --- an input given as data is described from the object
  {
    vtkNew<vtkHyperFunSource> other;
    other->SetModelText(Model4D);
    other->Update();
    vtkNew<vtkFRepSlice> cut;
    cut->SetInputData(other->GetOutput());
    cut->SetFixedValue(3, 0.25);
    vtkNew<vtkFRepSampler> grid;
    grid->SetInputConnection(cut->GetOutputPort());
    grid->SetSampleDimensions(4, 5, 6);
    grid->UpdateInformation();
    FREPKIT_CHECK(failures, WholeExtentIs(grid, 4, 5, 6));
    vtkNew<vtkFRepSampler> direct;
    vtkNew<vtkFRepSlice> alone;
    alone->SetInputData(other->GetOutput());
    alone->SetFixedValue(3, 0.25);
    alone->Update();
    direct->SetInputData(alone->GetOutput());
    direct->SetSampleDimensions(3, 3, 3);
    direct->Update();
    FREPKIT_CHECK(failures, direct->GetOutput()->GetNumberOfPoints() == 27);
  }

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
