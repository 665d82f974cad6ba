// vtkHyperFunSource (5-D) -> vtkFRepSlice (x5 fixed) -> vtkMultimediaMapper (x4 dynamic):
// executions counted (RequestData, by EndEvent). The mapper's information pass publishes the
// time steps from the vtkFRepInformation keys and executes nobody upstream; one frame executes
// each stage once; further frames, a new resolution or a new mapping re-execute only the mapper;
// a slice value re-executes the slice, not the source.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkMultimediaMapper.h"
#include "vtkMultimediaMapping.h"

#include "vtkFRepSlice.h"
#include "vtkHyperFunSource.h"

#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>

namespace
{
// The 3-D ball of radius x4 (+ 0 * x5, so that x5 is a coordinate to slice away).
const char* const BallModel = R"(
my_model(x[5], a[1])
{
  my_model = x[4] * x[4] + 0 * x[5] - x[1] * x[1] - x[2] * x[2] - x[3] * x[3];
}
)";

const char* const AnimationMapping = R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "dynamic", "range": [0.5, 1.5] }]
  },
  "animation": { "duration": 2, "fps": 5 },
  "world": { "resolution": 24 }
})";

const char* const ShortAnimationMapping = R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "dynamic", "range": [0.5, 1.5] }]
  },
  "animation": { "duration": 1, "fps": 4 },
  "world": { "resolution": 24 }
})";


int TimeSteps(vtkAlgorithm* algorithm)
{
  vtkInformation* info = algorithm->GetOutputInformation(0);
  return info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS())
    ? info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS())
    : 0;
}
}

int TestMultimediaMapperPipeline(int, char*[])
{
  int failures = 0;
  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(BallModel);
  vtkNew<vtkFRepSlice> slice;
  slice->SetInputConnection(source->GetOutputPort());
  slice->SetFixedValueByName("x5", 0.0);
  vtkNew<vtkMultimediaMapping> mapping;
  FREPKIT_CHECK(failures, mapping->LoadJSON(AnimationMapping));
  vtkNew<vtkMultimediaMapper> mapper;
  mapper->SetInputConnection(slice->GetOutputPort());
  mapper->SetMapping(mapping);
  mapper->SetOutputModeToFrame();

  vtkNew<frepkit_test::EventCounter> events;
  events->Observe(source);
  events->Observe(slice);
  events->Observe(mapper);
  vtkNew<frepkit_test::ExecutionCounter> sourceRuns;
  vtkNew<frepkit_test::ExecutionCounter> sliceRuns;
  vtkNew<frepkit_test::ExecutionCounter> mapperRuns;
  source->AddObserver(vtkCommand::EndEvent, sourceRuns);
  slice->AddObserver(vtkCommand::EndEvent, sliceRuns);
  mapper->AddObserver(vtkCommand::EndEvent, mapperRuns);
  const auto runs = [&](int s, int l, int m)
  {
    const bool ok = sourceRuns->Count == s && sliceRuns->Count == l && mapperRuns->Count == m;
    if (!ok)
    {
      std::cerr << "executions: source " << sourceRuns->Count << ", slice " << sliceRuns->Count
                << ", mapper " << mapperRuns->Count << "; expected " << s << ", " << l << ", "
                << m << std::endl;
    }
    return ok;
  };

  // --- the information pass: 10 time steps, nobody executed
  mapper->UpdateInformation();
  FREPKIT_CHECK(failures, runs(0, 0, 0));
  FREPKIT_CHECK(failures, TimeSteps(mapper) == 10 && mapper->GetNumberOfFrames() == 10);
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);

  // --- one frame: each stage once; more frames: the mapper only
  mapper->UpdateTimeStep(0.0);
  FREPKIT_CHECK(failures, runs(1, 1, 1));
  FREPKIT_CHECK(failures, mapper->GetOutput()->GetNumberOfPartitionedDataSets() == 1);
  mapper->UpdateTimeStep(0.8);
  mapper->UpdateTimeStep(1.8);
  FREPKIT_CHECK(failures, runs(1, 1, 3));

  // --- mapper changes: the mapper only
  mapper->SetResolution(16);
  mapper->UpdateTimeStep(0.8);
  FREPKIT_CHECK(failures, runs(1, 1, 4));
  FREPKIT_CHECK(failures, mapping->LoadJSON(ShortAnimationMapping));
  mapper->UpdateInformation();
  FREPKIT_CHECK(failures, runs(1, 1, 4) && TimeSteps(mapper) == 4);
  mapper->UpdateTimeStep(0.5);
  FREPKIT_CHECK(failures, runs(1, 1, 5));

  // --- a slice value: the slice and the mapper, not the source
  slice->SetFixedValueByName("x5", 1.0);
  mapper->UpdateInformation();
  FREPKIT_CHECK(failures, runs(1, 1, 5) && TimeSteps(mapper) == 4);
  mapper->UpdateTimeStep(0.5);
  FREPKIT_CHECK(failures, runs(1, 2, 6));
  FREPKIT_CHECK(failures, events->Errors == 0 && events->Warnings == 0);

  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
