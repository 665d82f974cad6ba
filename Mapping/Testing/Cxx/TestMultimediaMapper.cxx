// vtkMultimediaMapper: a 4-D model (a ball whose radius is x4) mapped with x1..x3 world and x4
// as a spreadsheet axis gives cells whose meshes have the balls' volumes in order; with x4
// dynamic the pipeline publishes the frames as time steps and UPDATE_TIME_STEP t gives the
// section at the path point of t; field data name every sample; a mapping that does not fit
// the model is one error naming the place and an empty output; progress and abort.
#include "FRepKitSourcesTestHelpers.h"

#include "vtkMultimediaMapper.h"
#include "vtkMultimediaMapping.h"

#include "vtkFRepObject.h"
#include "vtkHyperFunSource.h"

#include "vtkCallbackCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <cmath>
#include <string>

namespace
{

// Expected error text, printed so that ctest's "ERROR: " failure pattern does not match it.
std::string Quoted(std::string text)
{
  for (std::size_t at = text.find("ERROR:"); at != std::string::npos; at = text.find("ERROR:", at))
  {
    text.replace(at, 6, "(expected) error:");
  }
  return text;
}

const char* const BallModel = R"(
-- A 4-D object: the 3-D ball of radius x4.
my_model(x[4], a[1])
{
  my_model = x[4] * x[4] - x[1] * x[1] - x[2] * x[2] - x[3] * x[3];
}
)";

const char* const SpreadsheetMapping = R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "spreadsheet", "axis": "columns", "values": [0.5, 1.0, 1.5] },
           { "type": "colour", "colormap": "viridis", "range": [0.5, 1.5] }]
  },
  "world": { "resolution": 64 }
})";

const char* const AnimationMapping = R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2, 2] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2, 2] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2, 2] }],
    "x4": [{ "type": "dynamic", "range": [0.5, 1.5] },
           { "type": "audio", "parameter": "pitch", "range": [0.5, 1.5], "target": [220, 440] }]
  },
  "animation": { "duration": 2, "fps": 5 },
  "world": { "resolution": 64 }
})";

// Signed volume of a closed triangle mesh (divergence theorem).
double Volume(vtkPolyData* poly)
{
  double volume = 0;
  vtkCellArray* polys = poly->GetPolys();
  vtkIdType n;
  const vtkIdType* ids;
  double a[3], b[3], c[3];
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    poly->GetPoint(ids[0], a);
    poly->GetPoint(ids[1], b);
    poly->GetPoint(ids[2], c);
    volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0])) /
              6.0;
  }
  return volume;
}

vtkPolyData* Cell(vtkPartitionedDataSetCollection* c, unsigned i)
{
  vtkPartitionedDataSet* p = c->GetPartitionedDataSet(i);
  return p ? vtkPolyData::SafeDownCast(p->GetPartition(0)) : nullptr;
}

double BallVolume(double r)
{
  return 4.0 / 3.0 * 3.14159265358979323846 * r * r * r;
}

} // namespace

int TestMultimediaMapper(int, char*[])
{
  int failures = 0;

  vtkNew<vtkHyperFunSource> source;
  source->SetModelText(BallModel);

  // 1. Spreadsheet: three cells, volumes in order and close to the balls'.
  vtkNew<vtkMultimediaMapping> mapping;
  FREPKIT_CHECK(failures, mapping->LoadJSON(SpreadsheetMapping));
  vtkNew<vtkMultimediaMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->SetMapping(mapping);
  FREPKIT_CHECK(failures, mapper->GetOutputMode() == vtkMultimediaMapper::SPREADSHEET);
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> countProgress;
  countProgress->SetClientData(&progressEvents);
  countProgress->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  mapper->AddObserver(vtkCommand::ProgressEvent, countProgress);
  mapper->Update();
  auto* cells = mapper->GetOutput();
  FREPKIT_CHECK(failures, cells->GetNumberOfPartitionedDataSets() == 3);
  FREPKIT_CHECK(failures, mapper->GetNumberOfCells() == 3);
  FREPKIT_CHECK(failures, progressEvents >= 3);
  const double radii[3] = { 0.5, 1.0, 1.5 };
  double previous = 0;
  for (unsigned i = 0; i < cells->GetNumberOfPartitionedDataSets() && i < 3; ++i)
  {
    vtkPolyData* poly = Cell(cells, i);
    FREPKIT_CHECK(failures, poly && poly->GetNumberOfPolys() > 100);
    if (!poly)
    {
      continue;
    }
    const double v = Volume(poly);
    std::cout << "cell " << i << ": " << poly->GetNumberOfPolys() << " triangles, volume " << v
              << " (ball " << BallVolume(radii[i]) << ")\n";
    FREPKIT_CHECK(failures, v > previous);
    FREPKIT_CHECK(failures, std::abs(v - BallVolume(radii[i])) < 0.03 * BallVolume(radii[i]));
    previous = v;
    auto* index = vtkIntArray::SafeDownCast(poly->GetFieldData()->GetArray("CellIndex"));
    FREPKIT_CHECK(failures, index && index->GetValue(0) == static_cast<int>(i));
    auto* values = vtkDoubleArray::SafeDownCast(poly->GetFieldData()->GetArray("CoordinateValues"));
    FREPKIT_CHECK(failures, values && values->GetNumberOfTuples() == 4);
    FREPKIT_CHECK(failures, values && std::isnan(values->GetValue(0)));
    FREPKIT_CHECK(failures, values && values->GetValue(3) == radii[i]);
    auto* label = vtkStringArray::SafeDownCast(poly->GetFieldData()->GetAbstractArray("Label"));
    FREPKIT_CHECK(failures, label && label->GetValue(0).find("x4 = ") == 0);
    const char* name = cells->GetMetaData(i)->Get(vtkCompositeDataSet::NAME());
    FREPKIT_CHECK(failures, name && std::string(name) == label->GetValue(0));
    // the colour channel on x4: one colour per cell, different cells different colours
    FREPKIT_CHECK(failures, poly->GetPointData()->GetArray("Colors") != nullptr);
    FREPKIT_CHECK(failures, poly->GetPointData()->GetNormals() != nullptr);
  }
  if (Cell(cells, 0) && Cell(cells, 2))
  {
    double c0[3], c2[3];
    Cell(cells, 0)->GetPointData()->GetArray("Colors")->GetTuple(0, c0);
    Cell(cells, 2)->GetPointData()->GetArray("Colors")->GetTuple(0, c2);
    FREPKIT_CHECK(failures, c0[0] != c2[0] || c0[1] != c2[1] || c0[2] != c2[2]);
  }

  // 2. Time: the frames are time steps, and time t gives the ball of radius x4(t).
  vtkNew<vtkMultimediaMapping> animation;
  FREPKIT_CHECK(failures, animation->LoadJSON(AnimationMapping));
  vtkNew<vtkMultimediaMapper> player;
  player->SetInputConnection(source->GetOutputPort());
  player->SetMapping(animation);
  player->SetOutputModeToFrame();
  player->UpdateInformation();
  vtkInformation* info = player->GetOutputInformation(0);
  FREPKIT_CHECK(failures, info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  FREPKIT_CHECK(failures, info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 10);
  FREPKIT_CHECK(failures, player->GetNumberOfFrames() == 10);
  if (info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 10)
  {
    const double* steps = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    FREPKIT_CHECK(failures, steps[0] == 0.0 && std::abs(steps[9] - 1.8) < 1e-12);
  }
  for (double t : { 0.0, 0.8, 1.8 })
  {
    player->UpdateTimeStep(t);
    auto* frame = player->GetOutput();
    FREPKIT_CHECK(failures, frame->GetNumberOfPartitionedDataSets() == 1);
    vtkPolyData* poly = Cell(frame, 0);
    FREPKIT_CHECK(failures, poly != nullptr);
    if (!poly)
    {
      continue;
    }
    const double r = 0.5 + t / 2.0; // x4 runs linearly from 0.5 to 1.5 over the 2 s
    const double v = Volume(poly);
    std::cout << "t = " << t << ": volume " << v << " (ball of radius " << r << ": "
              << BallVolume(r) << ")\n";
    FREPKIT_CHECK(failures, std::abs(v - BallVolume(r)) < 0.03 * BallVolume(r));
    auto* time = vtkDoubleArray::SafeDownCast(poly->GetFieldData()->GetArray("Time"));
    FREPKIT_CHECK(failures, time && std::abs(time->GetValue(0) - t) < 1e-9);
    auto* pitch = vtkDoubleArray::SafeDownCast(poly->GetFieldData()->GetArray("VoicePitch"));
    FREPKIT_CHECK(failures, pitch && pitch->GetNumberOfTuples() == 1);
    FREPKIT_CHECK(failures, pitch && std::abs(pitch->GetValue(0) - (220 + 220 * t / 2.0)) < 1e-6);
    FREPKIT_CHECK(
      failures, std::abs(frame->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) - t) < 1e-9);
    // the frame's 1/5 s of the sound track at 44100 Hz, not silent
    auto* audio = vtkFloatArray::SafeDownCast(poly->GetFieldData()->GetArray("AudioSamples"));
    FREPKIT_CHECK(failures, audio && audio->GetNumberOfTuples() == 8820);
    double energy = 0;
    for (vtkIdType k = 0; audio && k < audio->GetNumberOfTuples(); ++k)
    {
      energy += audio->GetValue(k) * audio->GetValue(k);
    }
    FREPKIT_CHECK(failures, energy > 1.0);
  }

  // 3. A mapping that does not fit: x4 unmapped, a coordinate the model lacks.
  vtkNew<vtkMultimediaMapping> bad;
  FREPKIT_CHECK(failures, bad->LoadJSON(R"({ "coordinates": {
      "x1": [{ "type": "world", "axis": "x" }], "x2": [{ "type": "world", "axis": "y" }],
      "x3": [{ "type": "world", "axis": "z" }], "x9": [{ "type": "fixed", "value": 1 }] } })"));
  vtkNew<vtkMultimediaMapper> wrong;
  wrong->SetInputConnection(source->GetOutputPort());
  wrong->SetMapping(bad);
  vtkNew<frepkit_test::EventCounter> errors;
  errors->Observe(wrong);
  wrong->Update();
  std::cout << "expected error: " << Quoted(errors->ErrorText) << "\n";
  FREPKIT_CHECK(failures, errors->Errors == 1);
  FREPKIT_CHECK(failures, errors->ErrorText.find("x9") != std::string::npos);
  FREPKIT_CHECK(failures, errors->ErrorText.find("x4") != std::string::npos);
  FREPKIT_CHECK(failures, wrong->GetOutput()->GetNumberOfPartitionedDataSets() == 0);

  // 4. No mapping at all: one error, empty output.
  vtkNew<vtkMultimediaMapper> none;
  none->SetInputConnection(source->GetOutputPort());
  vtkNew<frepkit_test::EventCounter> noneErrors;
  noneErrors->Observe(none);
  none->Update();
  FREPKIT_CHECK(failures, noneErrors->Errors == 1);

  // 5. Abort from a progress observer: empty output.
  vtkNew<vtkMultimediaMapper> aborted;
  aborted->SetInputConnection(source->GetOutputPort());
  aborted->SetMapping(mapping);
  vtkNew<vtkCallbackCommand> abort;
  abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
    { static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1); });
  aborted->AddObserver(vtkCommand::ProgressEvent, abort);
  aborted->Update();
  FREPKIT_CHECK(failures, aborted->GetOutput()->GetNumberOfPartitionedDataSets() == 0);

  // 6. Pieces: piece p of 2 meshes every other cell; the two pieces hold every cell once.
  vtkIdType triangles[2] = { 0, 0 };
  for (int p = 0; p < 2; ++p)
  {
    vtkNew<vtkMultimediaMapper> piece;
    piece->SetInputConnection(source->GetOutputPort());
    piece->SetMapping(mapping);
    piece->UpdatePiece(p, 2, 0);
    auto* out = piece->GetOutput();
    FREPKIT_CHECK(failures, out->GetNumberOfPartitionedDataSets() == 3);
    FREPKIT_CHECK(failures, piece->GetNumberOfSamplesMeshed() == (p == 0 ? 2 : 1));
    for (unsigned i = 0; i < out->GetNumberOfPartitionedDataSets(); ++i)
    {
      const bool mine = static_cast<int>(i % 2) == p;
      vtkPolyData* poly = Cell(out, i);
      FREPKIT_CHECK(failures, mine == (poly != nullptr));
      triangles[p] += poly ? poly->GetNumberOfPolys() : 0;
      const char* name = out->GetMetaData(i)->Get(vtkCompositeDataSet::NAME());
      FREPKIT_CHECK(failures, name && std::string(name).find("x4 = ") == 0);
    }
  }
  vtkIdType whole = 0;
  for (unsigned i = 0; i < 3; ++i)
  {
    whole += Cell(cells, i) ? Cell(cells, i)->GetNumberOfPolys() : 0;
  }
  FREPKIT_CHECK(failures, triangles[0] + triangles[1] == whole);
  FREPKIT_CHECK(failures, mapper->GetNumberOfSamplesMeshed() == 3);

  // 7. Set/Get and PrintSelf.
  mapper->SetResolution(32);
  FREPKIT_CHECK(failures, mapper->GetResolution() == 32);
  mapper->SetNumberOfThreads(1);
  FREPKIT_CHECK(failures, mapper->GetNumberOfThreads() == 1);
  mapper->SetMappingFileName("none.json");
  FREPKIT_CHECK(failures, std::string(mapper->GetMappingFileName()) == "none.json");
  mapper->Print(std::cout);

  return failures == 0 ? 0 : 1;
}
