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

#include "Eval/thread_pool.h"
#include "Language/diagnostic.h"
#include "Sample/grid_sampler.h"

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

// Each block of the engine into the arrays: F and s[] as computed (the failure policy is applied
// already), gradients padded to 3 components (dF/dz = 0 for a 2-D object), normals from them
// (NaN for a failed sample unless hfp's policy gave it the previous values).
template <typename T>
struct BlockStore
{
  T* F;
  T* Gradient;   // null: not computed
  T* Normals;    // null: not computed
  T* Attributes; // null: none
  int AttributeCount;
  int Dimension;
  bool Hfp;

  void operator()(const frep::SampleBlock& b) const
  {
    const std::size_t base = b.first;
    for (std::size_t p = 0; p < b.count; ++p)
    {
      this->F[base + p] = static_cast<T>(b.values[p]);
    }
    for (int j = 0; j < this->AttributeCount; ++j)
    {
      T* s = this->Attributes + base * this->AttributeCount + j;
      const double* column = b.attributes[j];
      for (std::size_t p = 0; p < b.count; ++p)
      {
        s[p * this->AttributeCount] = static_cast<T>(column[p]);
      }
    }
    if (this->Gradient || this->Normals)
    {
      for (std::size_t p = 0; p < b.count; ++p)
      {
        this->StoreGradient(base + p, b.failed[p] && !this->Hfp, b.gradients + p * this->Dimension);
      }
    }
  }

  void StoreGradient(std::size_t id, bool nan, const double* gradient) const
  {
    double g[3] = { NaN, NaN, NaN };
    if (!nan)
    {
      for (int k = 0; k < 3; ++k)
      {
        g[k] = k < this->Dimension ? gradient[k] : 0.0;
      }
    }
    if (this->Gradient)
    {
      for (int k = 0; k < 3; ++k)
      {
        this->Gradient[3 * id + k] = static_cast<T>(g[k]);
      }
    }
    if (this->Normals)
    {
      const double length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      // Outward is where F decreases: -grad F. No direction where the gradient vanishes or is not
      // finite; NaN for a failed sample (NaN policy).
      const double scale = nan ? NaN : length > 0.0 && std::isfinite(length) ? -1.0 / length : 0.0;
      for (int k = 0; k < 3; ++k)
      {
        this->Normals[3 * id + k] = static_cast<T>(g[k] * scale);
      }
    }
  }
};
}

// The grid decided by RequestInformation, and the thread pool kept between executions.
struct vtkFRepSampler::Internals
{
  bool Valid = false;
  int Dimension = 0;
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 }; // lo, hi per axis: the engine's grid (Sample/grid.h)

  int PoolRequest = -1; // NumberOfThreads the pool was made for
  std::shared_ptr<frep::ThreadPool> Pool;
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
    const double spacing = frep::grid_step(lo, hi, dims[a]);
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
    in.Bounds[2 * a] = lo;
    in.Bounds[2 * a + 1] = hi;
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

  // The engine's grid: the whole grid of RequestInformation, of which the extent is the part.
  frep::GridSpec grid;
  for (int a = 0; a < dimension; ++a)
  {
    frep::GridAxis axis;
    axis.lo = in.Bounds[2 * a];
    axis.hi = in.Bounds[2 * a + 1];
    axis.samples = in.WholeExtent[2 * a + 1] + 1;
    axis.begin = extent[2 * a];
    axis.end = extent[2 * a + 1] + 1;
    grid.axes.push_back(axis);
  }
  // The pool (all cores by default), reused while NumberOfThreads stays the same.
  if (!in.Pool || in.PoolRequest != this->NumberOfThreads)
  {
    in.Pool = std::make_shared<frep::ThreadPool>(this->NumberOfThreads);
    in.PoolRequest = this->NumberOfThreads;
  }
  const int attributeCount = this->ComputeAttributes
    ? std::min(description.AttributeCount, static_cast<int>(tape->outputs.size()) - 1)
    : 0;
  const bool hfp = this->HfpErrors;
  frep::SampleOptions options;
  options.attribute_count = std::max(attributeCount, 0);
  options.gradients = this->ComputeGradients || this->ComputeNormals;
  options.failures = hfp ? frep::FailurePolicy::Previous : frep::FailurePolicy::NaN;
  options.max_samples = static_cast<double>(this->MaximumNumberOfSamples);
  options.pool = in.Pool;
  options.progress = [this](double fraction)
  {
    this->UpdateProgress(fraction);
    return !this->CheckAbort();
  };
  // The engine's size limit, before the arrays are allocated (RequestInformation checked it
  // already; this keeps the engine's guarantee whoever calls).
  if (const std::string problem = frep::check_grid(grid, tape->input_count, options);
      !problem.empty())
  {
    vtkErrorMacro(<< problem << "; the output is empty");
    return false;
  }

  const vtkIdType total = static_cast<vtkIdType>(frep::grid_part_size(grid));
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
  const BlockStore<T> store{ F->GetPointer(0), gradient ? gradient->GetPointer(0) : nullptr,
    normals ? normals->GetPointer(0) : nullptr, attributes ? attributes->GetPointer(0) : nullptr,
    attributeCount, dimension, hfp };
  const frep::SampleResult result = frep::sample_grid(tape, grid, options, store);
  this->NumberOfThreadsUsed = result.threads;
  if (!result.error.empty())
  {
    vtkErrorMacro(<< "sampling " << object->GetObjectName() << ": " << result.error
                  << "; the output is empty");
    return false;
  }
  if (result.cancelled)
  {
    return false;
  }

  const vtkIdType failures = static_cast<vtkIdType>(result.failed);
  this->NumberOfEvaluationErrors = failures;
  if (failures > 0)
  {
    const std::vector<double>& at = result.first_failed_at;
    vtkWarningMacro(<< failures << " of " << total << " samples of " << object->GetObjectName()
                    << " raised run-time errors; "
                    << (hfp ? "they took the previous sample's values (HfpErrors, as hfp does)"
                            : "they are NaN (outside)")
                    << ". The first, sample " << result.first_failed << " at (" << at[0]
                    << ", " << at[1] << ", " << (dimension == 3 ? at[2] : 0.0)
                    << "): " << DescribeError(*tape, result.first_error, object));
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
