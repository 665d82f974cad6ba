#include "vtkFRepSampler.h"

#include "vtkDoubleArray.h"
#include "vtkFRepInformation.h"
#include "vtkFRepObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "Eval/batch_evaluator.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/thread_pool.h"
#include "Language/diagnostic.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <span>
#include <sstream>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkFRepSampler);

namespace
{
// Samples per slab: enough blocks (256 samples each) for the batch evaluator to spread over
// the pool (it runs fewer than 32 blocks on the caller alone), small enough for progress
// reports and abort checks several times a second and for slab buffers that stay in cache.
constexpr vtkIdType SlabSamples = vtkIdType(1) << 16;
// Samples per gradient task: one GradientEvaluator call is ~0.1-1 us, so a task is well above
// the pool's hand-off cost and a slab still makes 64 tasks.
constexpr std::size_t GradientChunk = 1024;

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

// "file:line:col: error: message" for error id `id` of `tape` (1-based), as the policy wants.
std::string DescribeError(const frep::Tape& tape, std::uint32_t id, const vtkFRepObject* object)
{
  if (id == 0 || id > tape.errors.size())
  {
    return "the value is not a number (NaN)";
  }
  frep::Diagnostic d;
  const auto model = object->GetModel();
  d.file = model && model->program() ? model->program()->file : std::string();
  d.location = tape.errors[id - 1].location;
  d.message = tape.errors[id - 1].message;
  return d.format();
}

template <typename T>
using ArrayOf = std::conditional_t<std::is_same_v<T, float>, vtkFloatArray, vtkDoubleArray>;

// A named array of `tuples` x `components`; throws std::bad_alloc when it cannot be allocated
// (RequestData turns that into an error and an empty output).
template <typename T>
vtkSmartPointer<ArrayOf<T>> MakeArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<ArrayOf<T>>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  if (!array->SetNumberOfValues(tuples * components))
  {
    throw std::bad_alloc();
  }
  return array;
}
}

// The grid decided by RequestInformation, and the evaluators kept between executions (the
// pool's threads and the batch program are reused while the tape stays the same).
struct vtkFRepSampler::Internals
{
  bool Valid = false;
  int Dimension = 0;
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };

  int PoolRequest = -1; // NumberOfThreads the pool was made for
  std::shared_ptr<frep::ThreadPool> Pool;
  std::shared_ptr<const frep::Tape> Tape;
  std::unique_ptr<frep::BatchEvaluator> Batch;
  std::vector<std::unique_ptr<frep::GradientEvaluator>> Gradients; // one per pool slot
};

//------------------------------------------------------------------------------
vtkFRepSampler::vtkFRepSampler()
  : ModelBounds{ 0, -1, 0, -1, 0, -1 }
  , SampleDimensions{ 64, 64, 64 }
  , OutputScalarType(VTK_DOUBLE)
  , ComputeGradients(0)
  , ComputeNormals(0)
  , ComputeAttributes(0)
  , HfpErrors(0)
  , MaximumNumberOfSamples(vtkIdType(1) << 31)
  , NumberOfThreads(0)
  , Internal(new Internals)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkFRepSampler::~vtkFRepSampler() = default;

//------------------------------------------------------------------------------
void vtkFRepSampler::SetOutputScalarType(int type)
{
  if (type != VTK_DOUBLE && type != VTK_FLOAT)
  {
    vtkErrorMacro(<< "SetOutputScalarType: type " << type
                  << " is neither VTK_DOUBLE nor VTK_FLOAT; keeping "
                  << (this->OutputScalarType == VTK_FLOAT ? "VTK_FLOAT" : "VTK_DOUBLE"));
    return;
  }
  if (this->OutputScalarType != type)
  {
    this->OutputScalarType = type;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkFRepSampler::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkFRepObject");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkFRepSampler::PlanGrid(const vtkFRepInformation::Metadata& object, std::string& problem)
{
  Internals& in = *this->Internal;
  std::ostringstream why;
  const int dimension = object.GetDimension();
  if (dimension != 2 && dimension != 3)
  {
    why << object.ObjectName << " has " << dimension
        << " free coordinates; the sampler needs 2 or 3 (fix the others with vtkFRepSlice)";
    problem = why.str();
    return false;
  }
  const int dims[3] = { this->SampleDimensions[0], this->SampleDimensions[1],
    dimension == 3 ? this->SampleDimensions[2] : 1 };
  for (int a = 0; a < 3; ++a)
  {
    if (dims[a] < 1)
    {
      why << "SampleDimensions (" << dims[0] << ", " << dims[1] << ", " << dims[2]
          << "): every dimension must be at least 1";
      problem = why.str();
      return false;
    }
  }
  // The product of three positive ints can exceed 64 bits only in theory (2^93), but check.
  vtkIdType samples = 1;
  bool overflow = false;
  for (int a = 0; a < 3; ++a)
  {
    overflow = overflow || __builtin_mul_overflow(samples, vtkIdType(dims[a]), &samples);
  }
  if (overflow || samples > this->MaximumNumberOfSamples)
  {
    why << "SampleDimensions " << dims[0] << " x " << dims[1] << " x " << dims[2] << " = "
        << static_cast<double>(dims[0]) * dims[1] * dims[2]
        << " samples exceed MaximumNumberOfSamples (" << this->MaximumNumberOfSamples
        << "); refused before allocating anything";
    problem = why.str();
    return false;
  }

  for (int a = 0; a < 3; ++a)
  {
    if (a >= dimension)
    {
      in.Origin[a] = 0.0;
      in.Spacing[a] = 1.0;
      continue;
    }
    double lo = this->ModelBounds[2 * a];
    double hi = this->ModelBounds[2 * a + 1];
    const int coordinate = object.FreeCoordinates[a];
    if (lo > hi) // unset: the object's interval
    {
      lo = object.Ranges[coordinate][0];
      hi = object.Ranges[coordinate][1];
    }
    const double spacing = dims[a] > 1 ? (hi - lo) / (dims[a] - 1) : 1.0;
    if (!std::isfinite(lo) || !std::isfinite(hi) || !std::isfinite(spacing) ||
      !(spacing > 0.0))
    {
      why << "axis " << a << " (" << object.Names[coordinate] << "): cannot place " << dims[a]
          << " samples in [" << lo << ", " << hi << "]"
          << (std::isfinite(lo) && std::isfinite(hi) ? " (zero width)" : " (not finite)");
      problem = why.str();
      return false;
    }
    in.Origin[a] = lo;
    in.Spacing[a] = spacing;
  }
  in.Dimension = dimension;
  for (int a = 0; a < 3; ++a)
  {
    in.WholeExtent[2 * a] = 0;
    in.WholeExtent[2 * a + 1] = dims[a] - 1;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkFRepSampler::RequestInformation(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  in.Valid = false;
  // The grid comes from the input's metadata keys: nothing upstream is executed. No keys: an
  // empty object, reported upstream: an empty image, quietly.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkFRepInformation::CompleteInputInformation(inInfo); // an input given as data
  vtkFRepInformation::Metadata object;
  if (vtkFRepInformation::Get(inInfo, object))
  {
    std::string problem;
    in.Valid = this->PlanGrid(object, problem);
    if (!in.Valid)
    {
      vtkErrorMacro(<< problem << "; the output is empty");
    }
  }
  if (!in.Valid)
  {
    const int empty[6] = { 0, -1, 0, -1, 0, -1 };
    std::copy(empty, empty + 6, in.WholeExtent);
    std::fill(in.Origin, in.Origin + 3, 0.0);
    std::fill(in.Spacing, in.Spacing + 3, 1.0);
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkFRepInformation::Remove(outInfo); // copied from the input by the executive: not an image's
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), in.WholeExtent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), in.Origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), in.Spacing, 3);
  outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, this->OutputScalarType, 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepSampler::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  vtkFRepInformation::RequestWholeObject(inputVector[0]->GetInformationObject(0));
  return 1;
}

//------------------------------------------------------------------------------
int vtkFRepSampler::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  this->NumberOfThreadsUsed = 0;
  this->NumberOfEvaluationErrors = 0;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!output)
  {
    vtkErrorMacro(<< "the output is not a vtkImageData");
    return 0;
  }
  output->Initialize();
  Internals& in = *this->Internal;
  vtkFRepObject* object = vtkFRepObject::GetData(inputVector[0]);
  if (!in.Valid || !object || !object->HasModel())
  {
    return 1; // refused in RequestInformation (reported there), or an empty input
  }
  if (object->GetDimension() != in.Dimension)
  {
    vtkErrorMacro(<< "the input changed between the information and the data pass (dimension "
                  << in.Dimension << " -> " << object->GetDimension()
                  << "); call Modified() on the sampler; the output is empty");
    return 1;
  }

  // The requested extent, within the whole extent.
  int extent[6];
  std::copy(in.WholeExtent, in.WholeExtent + 6, extent);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  }
  for (int a = 0; a < 3; ++a)
  {
    extent[2 * a] = std::max(extent[2 * a], in.WholeExtent[2 * a]);
    extent[2 * a + 1] = std::min(extent[2 * a + 1], in.WholeExtent[2 * a + 1]);
  }
  output->SetOrigin(in.Origin);
  output->SetSpacing(in.Spacing);
  output->SetExtent(extent);
  if (extent[0] > extent[1] || extent[2] > extent[3] || extent[4] > extent[5])
  {
    return 1; // nothing requested
  }

  try
  {
    const bool done = this->OutputScalarType == VTK_FLOAT
      ? this->Sample<float>(object, output, extent)
      : this->Sample<double>(object, output, extent);
    if (!done)
    {
      output->Initialize(); // aborted: no half-computed image
    }
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "not enough memory for " << output->GetNumberOfPoints()
                  << " samples (extent " << extent[0] << ".." << extent[1] << " x " << extent[2]
                  << ".." << extent[3] << " x " << extent[4] << ".." << extent[5]
                  << "); the output is empty");
    output->Initialize();
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "sampling " << object->GetObjectName() << " failed: " << e.what()
                  << "; the output is empty");
    output->Initialize();
  }
  return 1;
}

//------------------------------------------------------------------------------
template <typename T>
bool vtkFRepSampler::Sample(vtkFRepObject* object, vtkImageData* output, const int extent[6])
{
  Internals& in = *this->Internal;
  const vtkFRepObject::EvaluationDescription description = object->GetEvaluationDescription();
  const std::shared_ptr<const frep::Tape>& tape = description.Tape;
  if (!tape || static_cast<int>(tape->input_count) != in.Dimension)
  {
    vtkErrorMacro(<< "the object's tape does not have " << in.Dimension
                  << " inputs; the output is empty");
    return false;
  }
  const int dimension = in.Dimension;

  // The pool (all cores by default) and the evaluators, reused while nothing changed.
  if (!in.Pool || in.PoolRequest != this->NumberOfThreads)
  {
    in.Pool = std::make_shared<frep::ThreadPool>(this->NumberOfThreads);
    in.PoolRequest = this->NumberOfThreads;
    in.Batch.reset();
  }
  if (!in.Batch || in.Tape != tape)
  {
    frep::BatchOptions options;
    options.pool = in.Pool;
    in.Batch = std::make_unique<frep::BatchEvaluator>(tape, options);
    in.Tape = tape;
    in.Gradients.clear();
  }
  in.Gradients.resize(static_cast<std::size_t>(in.Pool->size()));
  this->NumberOfThreadsUsed = in.Batch->threads();

  const int attributeCount = this->ComputeAttributes
    ? std::min(description.AttributeCount, static_cast<int>(tape->outputs.size()) - 1)
    : 0;
  const bool gradients = this->ComputeGradients || this->ComputeNormals;
  const bool hfp = this->HfpErrors;

  const vtkIdType nx = extent[1] - extent[0] + 1;
  const vtkIdType ny = extent[3] - extent[2] + 1;
  const vtkIdType nz = extent[5] - extent[4] + 1;
  const vtkIdType total = nx * ny * nz;
  const vtkIdType rows = ny * nz;
  const vtkIdType rowsPerSlab = std::max<vtkIdType>(1, SlabSamples / nx);
  const vtkIdType slab = std::min(total, rowsPerSlab * nx);

  // Output arrays first: if memory runs out, it does so before any evaluation.
  vtkPointData* pd = output->GetPointData();
  auto F = MakeArray<T>("F", 1, total);
  pd->SetScalars(F);
  vtkSmartPointer<ArrayOf<T>> gradient, normals, attributes;
  if (this->ComputeGradients)
  {
    gradient = MakeArray<T>("Gradient", 3, total);
    pd->AddArray(gradient);
  }
  if (this->ComputeNormals)
  {
    normals = MakeArray<T>("Normals", 3, total);
    pd->SetNormals(normals);
  }
  if (attributeCount > 0)
  {
    attributes = MakeArray<T>("s", attributeCount, total);
    pd->AddArray(attributes);
  }
  T* const fOut = F->GetPointer(0);
  T* const gOut = gradient ? gradient->GetPointer(0) : nullptr;
  T* const nOut = normals ? normals->GetPointer(0) : nullptr;
  T* const sOut = attributes ? attributes->GetPointer(0) : nullptr;

  // Per-slab buffers: the coordinates of the slab's samples (structure of arrays, as the batch
  // evaluator reads them), F (unless it goes straight into a double output), s[] rows, errors.
  std::vector<double> xRow(static_cast<std::size_t>(nx));
  for (vtkIdType i = 0; i < nx; ++i)
  {
    xRow[i] = SamplePosition(in.Origin[0], in.Spacing[0], extent[0] + static_cast<int>(i));
  }
  std::vector<std::vector<double>> coordinates(dimension, std::vector<double>(slab));
  std::vector<double> values(std::is_same_v<T, double> ? 0 : slab);
  std::vector<double> sRows(static_cast<std::size_t>(attributeCount) * slab);
  std::vector<double*> sPointers(attributeCount);
  for (int j = 0; j < attributeCount; ++j)
  {
    sPointers[j] = sRows.data() + static_cast<std::size_t>(j) * slab;
  }
  std::vector<std::uint32_t> errors(slab);

  vtkIdType failures = 0;
  vtkIdType firstFailure = -1;
  std::uint32_t firstError = 0;
  double firstPosition[3] = { 0, 0, 0 };

  this->UpdateProgress(0.0);
  for (vtkIdType row0 = 0; row0 < rows; row0 += rowsPerSlab)
  {
    if (this->CheckAbort())
    {
      return false;
    }
    const vtkIdType row1 = std::min(rows, row0 + rowsPerSlab);
    const vtkIdType base = row0 * nx; // first sample of the slab in the output
    const std::size_t count = static_cast<std::size_t>((row1 - row0) * nx);

    // Coordinates, row by row: x from the precomputed row, y and z constant along a row.
    for (vtkIdType r = row0; r < row1; ++r)
    {
      const std::size_t offset = static_cast<std::size_t>((r - row0) * nx);
      std::copy(xRow.begin(), xRow.end(), coordinates[0].begin() + offset);
      const int j = extent[2] + static_cast<int>(r % ny);
      std::fill_n(coordinates[1].begin() + offset, nx,
        SamplePosition(in.Origin[1], in.Spacing[1], j));
      if (dimension == 3)
      {
        const int k = extent[4] + static_cast<int>(r / ny);
        std::fill_n(coordinates[2].begin() + offset, nx,
          SamplePosition(in.Origin[2], in.Spacing[2], k));
      }
    }
    const double* inputs[3] = { coordinates[0].data(), coordinates[1].data(),
      dimension == 3 ? coordinates[2].data() : nullptr };

    // F (and s[]) on every core.
    double* f = nullptr;
    if constexpr (std::is_same_v<T, double>)
    {
      f = fOut + base;
    }
    else
    {
      f = values.data();
    }
    in.Batch->evaluate(std::span<const double* const>(inputs, dimension), count, f,
      errors.data(), std::span<double* const>(sPointers.data(), sPointers.size()));
    const auto failed = [&](std::size_t p) { return errors[p] != 0 || std::isnan(f[p]); };

    if constexpr (!std::is_same_v<T, double>)
    {
      std::transform(f, f + count, fOut + base, [](double v) { return static_cast<T>(v); });
    }
    for (int j = 0; j < attributeCount; ++j)
    {
      T* s = sOut + base * attributeCount + j;
      const double* row = sPointers[j];
      for (std::size_t p = 0; p < count; ++p)
      {
        s[p * attributeCount] = static_cast<T>(row[p]);
      }
    }

    // Gradients: pointwise evaluators, one per pool slot, over chunks of the slab.
    if (gradients)
    {
      const std::size_t tasks = (count + GradientChunk - 1) / GradientChunk;
      in.Pool->parallel_for(tasks,
        [&](std::size_t task, int slot)
        {
          std::unique_ptr<frep::GradientEvaluator>& evaluator = in.Gradients[slot];
          if (!evaluator)
          {
            evaluator = std::make_unique<frep::GradientEvaluator>(tape);
          }
          const std::size_t end = std::min(count, (task + 1) * GradientChunk);
          for (std::size_t p = task * GradientChunk; p < end; ++p)
          {
            double g[3] = { NaN, NaN, NaN };
            if (!failed(p))
            {
              const double point[3] = { inputs[0][p], inputs[1][p],
                dimension == 3 ? inputs[2][p] : 0.0 };
              g[2] = 0.0; // dF/dz of a 2-D object
              evaluator->evaluate(
                std::span<const double>(point, dimension), std::span<double>(g, dimension));
            }
            const std::size_t id = static_cast<std::size_t>(base) + p;
            if (gOut)
            {
              for (int k = 0; k < 3; ++k)
              {
                gOut[3 * id + k] = static_cast<T>(g[k]);
              }
            }
            if (nOut)
            {
              const double length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
              // Outward is where F decreases: -grad F. No direction where the gradient
              // vanishes or is not finite (failed samples are filled in below).
              const double scale = length > 0.0 && std::isfinite(length) ? -1.0 / length : 0.0;
              for (int k = 0; k < 3; ++k)
              {
                nOut[3 * id + k] = static_cast<T>(g[k] * scale);
              }
            }
          }
        });
    }

    // Failed samples, in point order: counted; NaN, or hfp's previous sample's values (the
    // previous sample is final by then: it succeeded or was itself filled in before).
    for (std::size_t p = 0; p < count; ++p)
    {
      if (!failed(p))
      {
        continue;
      }
      const vtkIdType id = base + static_cast<vtkIdType>(p);
      if (failures++ == 0)
      {
        firstFailure = id;
        firstError = errors[p];
        firstPosition[0] = inputs[0][p];
        firstPosition[1] = inputs[1][p];
        firstPosition[2] = dimension == 3 ? inputs[2][p] : 0.0;
      }
      const auto fill = [&](T* array, int components)
      {
        if (!array)
        {
          return;
        }
        for (int k = 0; k < components; ++k)
        {
          T& v = array[id * components + k];
          v = !hfp ? static_cast<T>(NaN) : id == 0 ? T(0) : array[(id - 1) * components + k];
        }
      };
      fill(fOut, 1);
      fill(gOut, 3);
      fill(nOut, 3);
      fill(sOut, attributeCount);
    }
    this->UpdateProgress(static_cast<double>(row1) / static_cast<double>(rows));
  }

  this->NumberOfEvaluationErrors = failures;
  if (failures > 0)
  {
    vtkWarningMacro(<< failures << " of " << total << " samples of " << object->GetObjectName()
                    << " raised run-time errors; "
                    << (hfp ? "they took the previous sample's values (HfpErrors, as hfp does)"
                            : "they are NaN (outside)")
                    << ". The first, sample " << firstFailure << " at (" << firstPosition[0]
                    << ", " << firstPosition[1] << ", " << firstPosition[2]
                    << "): " << DescribeError(*tape, firstError, object));
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkFRepSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ModelBounds: (" << this->ModelBounds[0] << ", " << this->ModelBounds[1]
     << ", " << this->ModelBounds[2] << ", " << this->ModelBounds[3] << ", "
     << this->ModelBounds[4] << ", " << this->ModelBounds[5] << ")\n";
  os << indent << "SampleDimensions: (" << this->SampleDimensions[0] << ", "
     << this->SampleDimensions[1] << ", " << this->SampleDimensions[2] << ")\n";
  os << indent << "OutputScalarType: "
     << (this->OutputScalarType == VTK_FLOAT ? "VTK_FLOAT" : "VTK_DOUBLE") << "\n";
  os << indent << "ComputeGradients: " << (this->ComputeGradients ? "On" : "Off") << "\n";
  os << indent << "ComputeNormals: " << (this->ComputeNormals ? "On" : "Off") << "\n";
  os << indent << "ComputeAttributes: " << (this->ComputeAttributes ? "On" : "Off") << "\n";
  os << indent << "HfpErrors: " << (this->HfpErrors ? "On" : "Off") << "\n";
  os << indent << "MaximumNumberOfSamples: " << this->MaximumNumberOfSamples << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "NumberOfThreadsUsed: " << this->NumberOfThreadsUsed << "\n";
  os << indent << "NumberOfEvaluationErrors: " << this->NumberOfEvaluationErrors << "\n";
}
