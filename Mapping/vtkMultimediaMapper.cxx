#include "vtkMultimediaMapper.h"

#include "vtkMultimediaMapping.h"

#include "Mapping/mapping_plan.h"
#include "Scene/section_mesh.h"
#include "Scene/section_model.h"
#include "Media/tone_synthesis.h"

#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkFRepPolygonizer.h"

#include "Eval/thread_pool.h"

#include "vtkCompositeDataSet.h"
#include "vtkDataAssembly.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkMultimediaMapper);
vtkCxxSetObjectMacro(vtkMultimediaMapper, Mapping, vtkMultimediaMapping);

struct vtkMultimediaMapper::Internals
{
  bool Valid = false;
  frep::mapping::Plan Plan;
  std::vector<double> Parameters;
  vtkNew<vtkMultimediaMapping> FileMapping; // MappingFileName's contents
  std::string LoadedFile;
  vtkMTimeType LoadedAt = 0;
  int PoolRequest = -1;
  std::shared_ptr<frep::ThreadPool> Pool;
  // The whole sound track of the plan's frames (synthesised once per plan, sliced per frame).
  std::vector<float> Sound;
  int SampleRate = 0;
  double Fps = 0;
};

namespace
{

// The object's fixed coordinates join the mapping as fixed channels, so a mapping written for
// the free coordinates of a slice applies to it.
bool CompleteSpec(
  const vtkFRepInformation::Metadata& object, frep::mapping::Spec& spec, std::string& problem)
{
  for (int i = 0; i < object.GetModelDimension(); ++i)
  {
    const std::string name = object.GetCoordinateName(i);
    auto it = std::find_if(spec.coordinates.begin(),
      spec.coordinates.end(),
      [&](const frep::mapping::CoordinateMapping& c) { return c.name == name; });
    if (!object.IsCoordinateFixed(i))
    {
      continue;
    }
    if (it != spec.coordinates.end())
    {
      problem += "coordinates." + name + ": the input object has fixed it (at " +
                 std::to_string(object.FixedValues[i]) + "); map only its free coordinates\n";
      continue;
    }
    frep::mapping::CoordinateMapping fixed;
    fixed.name = name;
    frep::mapping::Channel channel;
    channel.type = frep::mapping::Channel::Type::Fixed;
    channel.value = object.FixedValues[i];
    fixed.channels.push_back(channel);
    spec.coordinates.push_back(fixed);
  }
  return problem.empty();
}

template<typename Array>
vtkSmartPointer<Array> MakeArray(const char* name, int components)
{
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  return array;
}

void AddSampleFieldData(vtkFieldData* fd,
  const frep::mapping::Sample& s,
  const std::vector<std::string>& names)
{
  auto cell = MakeArray<vtkIntArray>("CellIndex", 3);
  cell->InsertNextTypedTuple(s.cell.data());
  fd->AddArray(cell);
  auto scalar = [fd](const char* name, double v)
  {
    auto a = MakeArray<vtkDoubleArray>(name, 1);
    a->InsertNextValue(v);
    fd->AddArray(a);
  };
  scalar("Time", s.time);
  scalar("PathParameter", s.path_parameter);
  scalar("Opacity", s.opacity);
  scalar("LightIntensity", s.light_intensity);
  auto coordinateNames = MakeArray<vtkStringArray>("CoordinateNames", 1);
  auto values = MakeArray<vtkDoubleArray>("CoordinateValues", 1);
  for (std::size_t i = 0; i < s.values.size(); ++i)
  {
    coordinateNames->InsertNextValue(i < names.size() ? names[i] : "x" + std::to_string(i + 1));
    values->InsertNextValue(s.values[i]);
  }
  fd->AddArray(coordinateNames);
  fd->AddArray(values);
  auto label = MakeArray<vtkStringArray>("Label", 1);
  label->InsertNextValue(s.label);
  fd->AddArray(label);
  auto colour = MakeArray<vtkDoubleArray>("Colour", 3);
  colour->InsertNextTuple(s.colour.data());
  fd->AddArray(colour);
  auto background = MakeArray<vtkDoubleArray>("Background", 3);
  background->InsertNextTuple(s.background.data());
  fd->AddArray(background);
  auto transform = MakeArray<vtkDoubleArray>("Transform", 16);
  transform->InsertNextTuple(s.transform.data());
  fd->AddArray(transform);
  auto pitch = MakeArray<vtkDoubleArray>("VoicePitch", 1);
  auto loudness = MakeArray<vtkDoubleArray>("VoiceLoudness", 1);
  auto timbre = MakeArray<vtkDoubleArray>("VoiceTimbre", 1);
  for (const auto& v : s.voices)
  {
    pitch->InsertNextValue(v.pitch);
    loudness->InsertNextValue(v.loudness);
    timbre->InsertNextValue(v.timbre);
  }
  fd->AddArray(pitch);
  fd->AddArray(loudness);
  fd->AddArray(timbre);
}

vtkSmartPointer<vtkPolyData> ToPolyData(const frep::mapping::Section& section,
  const frep::mapping::Sample& sample)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkFRepPolygonizer::ConvertSurface(section.surface, vtkAlgorithm::SINGLE_PRECISION, poly);
  const vtkIdType n = static_cast<vtkIdType>(section.surface.point_count());
  auto colours = MakeArray<vtkUnsignedCharArray>("Colors", 3);
  colours->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = section.colours.empty() ? sample.colour[c]
                                               : static_cast<double>(section.colours[3 * i + c]);
      colours->SetValue(
        3 * i + c, static_cast<unsigned char>(std::lround(255 * std::clamp(v, 0.0, 1.0))));
    }
  }
  poly->GetPointData()->SetScalars(colours);
  return poly;
}

} // namespace

//------------------------------------------------------------------------------
vtkMultimediaMapper::vtkMultimediaMapper()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkMultimediaMapper::~vtkMultimediaMapper()
{
  this->SetMapping(nullptr);
  this->SetMappingFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkMultimediaMapper::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkFRepObject");
  return 1;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkMultimediaMapper::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Mapping)
  {
    t = std::max(t, this->Mapping->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
int vtkMultimediaMapper::GetNumberOfFrames() const
{
  return this->Internal->Valid ? static_cast<int>(this->Internal->Plan.frames.size()) : 0;
}

//------------------------------------------------------------------------------
int vtkMultimediaMapper::GetNumberOfCells() const
{
  return this->Internal->Valid ? static_cast<int>(this->Internal->Plan.cells.size()) : 0;
}

//------------------------------------------------------------------------------
int vtkMultimediaMapper::RequestInformation(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  in.Valid = false;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  outInfo->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);

  // The plan (and so the time steps) depends on the object's coordinates, which its producer
  // publishes as vtkFRepInformation keys in its own information pass: nothing upstream runs.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkFRepInformation::Remove(outInfo); // copied from the input by the executive
  vtkFRepInformation::CompleteInputInformation(inInfo); // an input given as data
  vtkFRepInformation::Metadata object;
  if (!vtkFRepInformation::Get(inInfo, object))
  {
    return 1; // reported upstream: an empty output, quietly
  }

  vtkMultimediaMapping* mapping = this->Mapping;
  if (!mapping && this->MappingFileName && *this->MappingFileName)
  {
    const std::string file = this->MappingFileName;
    if (file != in.LoadedFile || in.LoadedAt < this->GetMTime())
    {
      in.LoadedFile.clear();
      if (!in.FileMapping->LoadFile(file))
      {
        return 1; // every error reported by the mapping; an empty output
      }
      in.LoadedFile = file;
      in.LoadedAt = this->GetMTime();
    }
    mapping = in.FileMapping;
  }
  if (!mapping)
  {
    vtkErrorMacro(<< "no mapping: set Mapping or MappingFileName; the output is empty");
    return 1;
  }

  frep::mapping::Spec spec = mapping->GetSpec();
  if (this->Resolution > 0)
  {
    spec.world.resolution = this->Resolution;
  }
  std::string problem;
  frep::mapping::ModelCoordinates coordinates;
  for (int i = 0; i < object.GetModelDimension(); ++i)
  {
    coordinates.names.push_back(object.Names[i]);
    coordinates.intervals.push_back({ object.Ranges[i][0], object.Ranges[i][1] });
  }
  if (CompleteSpec(object, spec, problem))
  {
    const frep::mapping::PlanResult planned = frep::mapping::make_plan(spec, coordinates);
    for (const auto& e : planned.errors)
    {
      problem += (e.place.empty() ? "" : e.place + ": ") + e.message + "\n";
    }
    if (planned.ok())
    {
      in.Plan = planned.plan;
    }
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< "the mapping does not fit " << object.ObjectName << ":\n"
                  << problem << "the output is empty");
    return 1;
  }
  in.Parameters = spec.parameters.empty() ? object.Parameters : spec.parameters;
  in.Valid = true;
  in.Sound.clear();
  in.SampleRate = spec.audio.sample_rate;
  in.Fps = spec.animation.fps;
  if (in.Plan.voice_count > 0 && !in.Plan.frames.empty())
  {
    frep::media::VoiceFrames voices;
    for (const auto& f : in.Plan.frames)
    {
      std::vector<frep::media::VoiceParams> v;
      for (const auto& voice : f.voices)
      {
        v.push_back({ voice.pitch, voice.loudness, voice.timbre });
      }
      voices.push_back(v);
    }
    frep::media::SynthesisResult sound = frep::media::synthesise(voices, in.Fps, in.SampleRate);
    if (sound.ok())
    {
      in.Sound = std::move(sound.samples);
    }
    else
    {
      vtkWarningMacro(<< "sound track: " << sound.error << "; frames without AudioSamples");
    }
  }

  if (this->OutputMode == FRAME && !in.Plan.frames.empty())
  {
    std::vector<double> times;
    times.reserve(in.Plan.frames.size());
    for (const auto& f : in.Plan.frames)
    {
      times.push_back(f.time);
    }
    outInfo->Set(
      vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
    const double range[2] = { times.front(), times.back() };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkMultimediaMapper::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // Every rank builds the whole (indivisible) object; time is ours, not the source's.
  if (vtkInformation* inInfo = inputVector[0]->GetInformationObject(0))
  {
    vtkFRepInformation::RequestWholeObject(inInfo);
    inInfo->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkMultimediaMapper::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  auto* output = vtkPartitionedDataSetCollection::GetData(outInfo);
  vtkFRepObject* object = vtkFRepObject::GetData(inputVector[0]);
  if (!output || !object || !object->HasModel() || !in.Valid)
  {
    return 1;
  }

  // Which samples: every cell, or the frame at the requested time.
  std::vector<const frep::mapping::Sample*> samples;
  if (this->OutputMode == SPREADSHEET)
  {
    for (const auto& c : in.Plan.cells)
    {
      samples.push_back(&c);
    }
    if (samples.empty())
    {
      vtkWarningMacro(<< "the mapping has no spreadsheet coordinate: no cells");
    }
  }
  else if (!in.Plan.frames.empty())
  {
    std::size_t k = 0;
    if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    {
      const double t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
      while (k + 1 < in.Plan.frames.size() && in.Plan.frames[k + 1].time <= t + 1e-9)
      {
        ++k;
      }
      output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), in.Plan.frames[k].time);
    }
    samples.push_back(&in.Plan.frames[k]);
  }
  else
  {
    vtkWarningMacro(<< "the mapping has no dynamic coordinate: no frames");
  }

  if (in.PoolRequest != this->NumberOfThreads || !in.Pool)
  {
    in.Pool = std::make_shared<frep::ThreadPool>(this->NumberOfThreads);
    in.PoolRequest = this->NumberOfThreads;
  }
  std::vector<std::string> names;
  for (int i = 0; i < object->GetModelDimension(); ++i)
  {
    names.push_back(object->GetCoordinateName(i));
  }

  // The model itself, or its projection when the mapping projects coordinates.
  const auto sectioned = frep::mapping::section_model(object->GetModel(), in.Plan, in.Parameters);
  if (!sectioned.ok())
  {
    vtkErrorMacro(<< sectioned.error << "; the output is empty");
    return 1;
  }
  const std::shared_ptr<const frep::Model>& model = sectioned.model;
  // Distributed runs: piece p of n meshes the samples i with i % n == p (the others stay empty
  // partitioned data sets, so every rank has the same structure and names); the pieces
  // together hold every sample once.
  const int piece = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
                      ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
                      : 0;
  const int pieces =
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
      ? std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
      : 1;
  this->SamplesMeshed = 0;
  output->SetNumberOfPartitionedDataSets(static_cast<unsigned>(samples.size()));
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    if (static_cast<int>(i % static_cast<std::size_t>(pieces)) != piece)
    {
      vtkNew<vtkPartitionedDataSet> empty;
      output->SetPartitionedDataSet(static_cast<unsigned>(i), empty);
      output->GetMetaData(static_cast<unsigned>(i))
        ->Set(vtkCompositeDataSet::NAME(), samples[i]->label.c_str());
      continue;
    }
    ++this->SamplesMeshed;
    if (this->CheckAbort())
    {
      output->Initialize();
      return 1;
    }
    const double base = static_cast<double>(i) / samples.size();
    frep::mapping::SectionOptions options;
    options.pool = in.Pool;
    options.progress = [this, base, &samples](double fraction)
    {
      this->UpdateProgress(base + fraction / samples.size());
      return !this->CheckAbort();
    };
    const frep::mapping::Section section =
      frep::mapping::make_section(*model, in.Parameters, in.Plan, *samples[i], options);
    if (section.cancelled || this->GetAbortExecute())
    {
      output->Initialize();
      return 1;
    }
    if (!section.error.empty())
    {
      vtkErrorMacro(<< samples[i]->label << ": " << section.error << "; the output is empty");
      output->Initialize();
      return 1;
    }
    if (section.statistics.failed_samples > 0)
    {
      vtkWarningMacro(<< samples[i]->label << ": " << section.statistics.failed_samples
                      << " samples raised a run-time error (taken as outside)");
    }
    vtkSmartPointer<vtkPolyData> poly = ToPolyData(section, *samples[i]);
    AddSampleFieldData(poly->GetFieldData(), *samples[i], names);
    if (this->OutputMode == FRAME && !in.Sound.empty())
    {
      // The frame's share of the sound track: [k, k + 1) / fps.
      const double t = samples[i]->time;
      const std::size_t first =
        std::min(in.Sound.size(), static_cast<std::size_t>(std::llround(t * in.SampleRate)));
      const std::size_t last = std::min(in.Sound.size(),
        static_cast<std::size_t>(std::llround((t + 1.0 / in.Fps) * in.SampleRate)));
      auto audio = MakeArray<vtkFloatArray>("AudioSamples", 1);
      audio->SetNumberOfTuples(static_cast<vtkIdType>(last - first));
      std::copy(in.Sound.begin() + first, in.Sound.begin() + last, audio->GetPointer(0));
      poly->GetFieldData()->AddArray(audio);
      auto rate = MakeArray<vtkIntArray>("AudioSampleRate", 1);
      rate->InsertNextValue(in.SampleRate);
      poly->GetFieldData()->AddArray(rate);
    }
    auto worldBounds = MakeArray<vtkDoubleArray>("WorldBounds", 6);
    const auto& wb = in.Plan.world_box;
    const double bounds[6] = { wb[0].lo, wb[0].hi, wb[1].lo, wb[1].hi, wb[2].lo, wb[2].hi };
    worldBounds->InsertNextTuple(bounds);
    poly->GetFieldData()->AddArray(worldBounds);
    vtkNew<vtkPartitionedDataSet> cell;
    cell->SetPartition(0, poly);
    output->SetPartitionedDataSet(static_cast<unsigned>(i), cell);
    output->GetMetaData(static_cast<unsigned>(i))
      ->Set(vtkCompositeDataSet::NAME(), samples[i]->label.c_str());
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkMultimediaMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapping: " << this->Mapping << "\n";
  os << indent << "MappingFileName: " << (this->MappingFileName ? this->MappingFileName : "(none)")
     << "\n";
  os << indent << "OutputMode: " << (this->OutputMode == SPREADSHEET ? "Spreadsheet" : "Frame")
     << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
