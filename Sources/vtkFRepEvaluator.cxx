#include "vtkFRepEvaluator.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFRepObject.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"

#include "Eval/batch_evaluator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

vtkStandardNewMacro(vtkFRepEvaluator);
vtkCxxSetObjectMacro(vtkFRepEvaluator, Object, vtkFRepObject);

namespace
{
// Points per batch call: bounds the structure-of-arrays copy of the inputs.
constexpr vtkIdType Chunk = vtkIdType(1) << 18;
}

struct vtkFRepEvaluator::Internals
{
  // The batch evaluator of the last call, and what it was built for.
  std::shared_ptr<const frep::Tape> Tape;
  int Threads = -1;
  std::unique_ptr<frep::BatchEvaluator> Batch;
};

//------------------------------------------------------------------------------
vtkFRepEvaluator::vtkFRepEvaluator()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkFRepEvaluator::~vtkFRepEvaluator()
{
  this->SetObject(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkFRepEvaluator::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Object)
  {
    t = std::max(t, this->Object->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
int vtkFRepEvaluator::GetDimension()
{
  return this->Object && this->Object->HasModel() ? this->Object->GetDimension() : 0;
}

//------------------------------------------------------------------------------
int vtkFRepEvaluator::GetNumberOfAttributes()
{
  if (!this->Object || !this->Object->HasModel())
  {
    return 0;
  }
  const auto tape = this->Object->GetTape();
  return tape && !tape->outputs.empty() ? static_cast<int>(tape->outputs.size()) - 1 : 0;
}

//------------------------------------------------------------------------------
bool vtkFRepEvaluator::Evaluate(vtkDataArray* points, vtkDoubleArray* values)
{
  return this->Evaluate(points, values, nullptr, nullptr);
}

//------------------------------------------------------------------------------
bool vtkFRepEvaluator::Evaluate(
  vtkDataArray* points, vtkDoubleArray* values, vtkDoubleArray* attributes)
{
  return this->Evaluate(points, values, attributes, nullptr);
}

//------------------------------------------------------------------------------
bool vtkFRepEvaluator::Evaluate(
  vtkDataArray* points, vtkDoubleArray* values, vtkDoubleArray* attributes, vtkIntArray* errors)
{
  if (!points)
  {
    vtkErrorMacro(<< "Evaluate: no points array");
    return false;
  }
  return this->Run(
    "Evaluate", points, points->GetNumberOfComponents(), values, attributes, errors);
}

//------------------------------------------------------------------------------
bool vtkFRepEvaluator::EvaluatePoints(vtkPoints* points, vtkDoubleArray* values)
{
  return this->EvaluatePoints(points, values, nullptr);
}

//------------------------------------------------------------------------------
bool vtkFRepEvaluator::EvaluatePoints(
  vtkPoints* points, vtkDoubleArray* values, vtkDoubleArray* attributes)
{
  if (!points || !points->GetData())
  {
    vtkErrorMacro(<< "EvaluatePoints: no points");
    return false;
  }
  const int k = this->GetDimension();
  if (k > 3)
  {
    vtkErrorMacro(<< "EvaluatePoints: the object is " << k
                  << "-D; vtkPoints hold 3 coordinates (use Evaluate with a " << k
                  << "-component array, or slice the object first)");
    return false;
  }
  return this->Run("EvaluatePoints", points->GetData(), k, values, attributes, nullptr);
}

//------------------------------------------------------------------------------
double vtkFRepEvaluator::EvaluatePoint(const double* x, int k)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!x || k < 1)
  {
    vtkErrorMacro(<< "EvaluatePoint: no coordinates");
    return nan;
  }
  vtkNew<vtkDoubleArray> point;
  point->SetNumberOfComponents(k);
  point->SetNumberOfTuples(1);
  for (int i = 0; i < k; ++i)
  {
    point->SetComponent(0, i, x[i]);
  }
  vtkNew<vtkDoubleArray> value;
  if (!this->Run("EvaluatePoint", point, k, value, nullptr, nullptr))
  {
    return nan;
  }
  return value->GetValue(0);
}

//------------------------------------------------------------------------------
std::string vtkFRepEvaluator::GetErrorMessage(int id)
{
  if (!this->Object || !this->Object->HasModel())
  {
    return "";
  }
  const auto tape = this->Object->GetTape();
  if (!tape || id < 1 || static_cast<std::size_t>(id) > tape->errors.size())
  {
    return "";
  }
  const frep::TapeError& error = tape->errors[static_cast<std::size_t>(id - 1)];
  std::string text = error.file.empty() ? std::string("<model>") : error.file;
  if (error.location.valid())
  {
    text += ":" + std::to_string(error.location.line) + ":" + std::to_string(error.location.column);
  }
  return text + ": " + error.message;
}

//------------------------------------------------------------------------------
bool vtkFRepEvaluator::CanRun(
  const char* method, vtkDataArray* points, int columns, vtkDoubleArray* values)
{
  if (!values)
  {
    vtkErrorMacro(<< method << ": no output array for F");
    return false;
  }
  if (!this->Object || !this->Object->HasModel())
  {
    vtkErrorMacro(<< method << ": "
                  << (this->Object ? "the object has no model (did its source fail?)"
                                   : "no object (SetObject)"));
    return false;
  }
  const int k = this->Object->GetDimension();
  if (columns != k || points->GetNumberOfComponents() < k)
  {
    vtkErrorMacro(<< method << ": the points have " << points->GetNumberOfComponents()
                  << " components, the object is " << k << "-D");
    return false;
  }
  if (k == 0)
  {
    vtkErrorMacro(<< method << ": the object has no free coordinate (a 0-D slice)");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkFRepEvaluator::Run(const char* method, vtkDataArray* points, int columns,
  vtkDoubleArray* values, vtkDoubleArray* attributes, vtkIntArray* errors)
{
  // Empty outputs until the call succeeds.
  auto clear = [&]
  {
    for (vtkDataArray* a : { static_cast<vtkDataArray*>(values),
           static_cast<vtkDataArray*>(attributes), static_cast<vtkDataArray*>(errors) })
    {
      if (a)
      {
        a->SetNumberOfTuples(0);
      }
    }
  };
  clear();
  if (!this->CanRun(method, points, columns, values))
  {
    return false;
  }
  const int k = this->Object->GetDimension();
  const std::shared_ptr<const frep::Tape> tape = this->Object->GetTape();
  if (!tape || tape->outputs.empty() || static_cast<int>(tape->input_count) != k)
  {
    vtkErrorMacro(<< method << ": the object's tape does not match its dimension");
    return false;
  }

  Internals& in = *this->Internal;
  if (!in.Batch || in.Tape != tape || in.Threads != this->NumberOfThreads)
  {
    frep::BatchOptions options;
    options.threads = this->NumberOfThreads;
    in.Batch = std::make_unique<frep::BatchEvaluator>(tape, options);
    in.Tape = tape;
    in.Threads = this->NumberOfThreads;
  }

  const vtkIdType n = points->GetNumberOfTuples();
  const int m = static_cast<int>(tape->outputs.size()) - 1;
  values->SetNumberOfComponents(1);
  values->SetNumberOfTuples(n);
  values->SetName("F");
  if (attributes)
  {
    attributes->SetNumberOfComponents(std::max(m, 1));
    attributes->SetNumberOfTuples(m > 0 ? n : 0);
    attributes->SetName("s");
  }
  if (errors)
  {
    errors->SetNumberOfComponents(1);
    errors->SetNumberOfTuples(n);
    errors->SetName("ErrorId");
  }

  const vtkIdType chunk = std::max<vtkIdType>(1, std::min(n, Chunk));
  std::vector<std::vector<double>> columnsIn(static_cast<std::size_t>(k),
    std::vector<double>(static_cast<std::size_t>(chunk)));
  std::vector<const double*> inputPointers(static_cast<std::size_t>(k));
  std::vector<std::vector<double>> attributeColumns;
  std::vector<double*> attributePointers;
  if (attributes && m > 0)
  {
    attributeColumns.assign(
      static_cast<std::size_t>(m), std::vector<double>(static_cast<std::size_t>(chunk)));
    for (auto& column : attributeColumns)
    {
      attributePointers.push_back(column.data());
    }
  }
  std::vector<double> chunkValues(static_cast<std::size_t>(chunk));
  std::vector<std::uint32_t> chunkErrors(static_cast<std::size_t>(chunk));
  const int stride = points->GetNumberOfComponents();
  auto* doubles = vtkDoubleArray::FastDownCast(points);

  vtkIdType failed = 0;
  for (vtkIdType begin = 0; begin < n; begin += chunk)
  {
    const vtkIdType count = std::min(chunk, n - begin);
    for (vtkIdType i = 0; i < count; ++i)
    {
      const vtkIdType t = begin + i;
      if (doubles)
      {
        const double* p = doubles->GetPointer(t * stride);
        for (int c = 0; c < k; ++c)
        {
          columnsIn[static_cast<std::size_t>(c)][static_cast<std::size_t>(i)] = p[c];
        }
      }
      else
      {
        for (int c = 0; c < k; ++c)
        {
          columnsIn[static_cast<std::size_t>(c)][static_cast<std::size_t>(i)] =
            points->GetComponent(t, c);
        }
      }
    }
    for (int c = 0; c < k; ++c)
    {
      inputPointers[static_cast<std::size_t>(c)] = columnsIn[static_cast<std::size_t>(c)].data();
    }
    failed += static_cast<vtkIdType>(in.Batch->evaluate(
      std::span<const double* const>(inputPointers.data(), inputPointers.size()),
      static_cast<std::size_t>(count), chunkValues.data(), chunkErrors.data(),
      std::span<double* const>(attributePointers.data(), attributePointers.size())));
    double* out = values->GetPointer(begin);
    std::copy(chunkValues.begin(), chunkValues.begin() + count, out);
    if (!attributePointers.empty())
    {
      double* s = attributes->GetPointer(begin * m);
      for (vtkIdType i = 0; i < count; ++i)
      {
        for (int j = 0; j < m; ++j)
        {
          s[i * m + j] = attributeColumns[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)];
        }
      }
    }
    if (errors)
    {
      int* e = errors->GetPointer(begin);
      for (vtkIdType i = 0; i < count; ++i)
      {
        e[i] = static_cast<int>(chunkErrors[static_cast<std::size_t>(i)]);
      }
    }
  }
  this->NumberOfErrorPoints = failed;
  return true;
}

//------------------------------------------------------------------------------
void vtkFRepEvaluator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Object: " << this->Object << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "NumberOfErrorPoints: " << this->NumberOfErrorPoints << "\n";
}
