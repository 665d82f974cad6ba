#include "vtkFRepImplicitFunction.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFRepObject.h"
#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkSMPThreadLocal.h"

#include "Eval/batch_evaluator.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Language/diagnostic.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <span>
#include <vector>

vtkStandardNewMacro(vtkFRepImplicitFunction);

// Evaluation state of one thread: evaluators over the tape of one round (MTime).
struct vtkFRepImplicitFunction::ThreadState
{
  ThreadState() = default;
  // vtkSMPThreadLocal creates each thread's state by copying an exemplar: a copy starts empty
  // (evaluators are never shared between threads).
  ThreadState(const ThreadState&) {}
  ThreadState& operator=(const ThreadState&)
  {
    *this = ThreadState();
    return *this;
  }
  ThreadState(ThreadState&&) = default;
  ThreadState& operator=(ThreadState&&) = default;

  vtkMTimeType Key = 0;
  std::shared_ptr<const frep::Tape> Tape;
  std::unique_ptr<frep::PointEvaluator> Point;
  std::unique_ptr<frep::GradientEvaluator> Gradient;
  std::vector<double> Outputs;
};

namespace
{
// Points per batch call: bounds the temporary structure-of-arrays copy (4 doubles per point).
constexpr vtkIdType BatchChunk = vtkIdType(1) << 20;
}

struct vtkFRepImplicitFunction::Internals
{
  vtkSMPThreadLocal<ThreadState> Threads;

  // The current round: failures are counted and the first one is reported once per round.
  std::atomic<vtkMTimeType> Round{ 0 };
  std::atomic<vtkIdType> ErrorCount{ 0 };
  std::atomic<bool> ErrorWarned{ false };
  std::atomic<bool> ConfigurationReported{ false };

  // The batch evaluator (its own threads), rebuilt when the MTime changes.
  std::mutex BatchMutex;
  vtkMTimeType BatchKey = 0;
  std::unique_ptr<frep::BatchEvaluator> Batch;
};

//------------------------------------------------------------------------------
vtkFRepImplicitFunction::vtkFRepImplicitFunction()
  : ErrorValue(VTK_FLOAT_MAX)
  , Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkFRepImplicitFunction::~vtkFRepImplicitFunction()
{
  this->SetFRepObject(nullptr);
}

//------------------------------------------------------------------------------
void vtkFRepImplicitFunction::SetFRepObject(vtkFRepObject* object)
{
  if (object == this->FRepObject)
  {
    return;
  }
  vtkFRepObject* old = this->FRepObject;
  this->FRepObject = object;
  if (object)
  {
    object->Register(this);
  }
  if (old)
  {
    old->UnRegister(this);
  }
  if (object && object->GetDimension() != 3)
  {
    vtkErrorMacro(<< "SetFRepObject: the object " << object->GetObjectName() << " has "
                  << object->GetDimension()
                  << " free coordinates; an implicit function needs exactly 3 (slice it first)");
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkFRepImplicitFunction::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->FRepObject)
  {
    t = std::max(t, this->FRepObject->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
vtkIdType vtkFRepImplicitFunction::GetNumberOfEvaluationErrors()
{
  // A modification since the failures were counted starts a new round.
  if (this->Internal->Round.load() != this->GetMTime())
  {
    return 0;
  }
  return this->Internal->ErrorCount.load();
}

//------------------------------------------------------------------------------
void vtkFRepImplicitFunction::ResetEvaluationErrors()
{
  this->Internal->ErrorCount = 0;
  this->Internal->ErrorWarned = false;
  this->Internal->ConfigurationReported = false;
}

namespace
{
// Starts a new round when the function or the object changed; returns the round's key.
vtkMTimeType UpdateRound(vtkFRepImplicitFunction* self,
  std::atomic<vtkMTimeType>& round,
  std::atomic<vtkIdType>& count,
  std::atomic<bool>& warned,
  std::atomic<bool>& configuration)
{
  const vtkMTimeType t = self->GetMTime();
  vtkMTimeType old = round.load();
  if (old != t && round.compare_exchange_strong(old, t))
  {
    count = 0;
    warned = false;
    configuration = false;
  }
  return t;
}

std::string DescribeError(const frep::Tape& tape, int id, const vtkFRepObject* object)
{
  if (id <= 0 || id > static_cast<int>(tape.errors.size()))
  {
    return "the value is not a number (NaN)";
  }
  frep::Diagnostic d;
  auto model = object ? object->GetModel() : nullptr;
  // A composed model has no program of its own; its errors name their operand's file.
  d.file = tape.errors[id - 1].file;
  if (d.file.empty() && model && model->program())
  {
    d.file = model->program()->file;
  }
  d.location = tape.errors[id - 1].location;
  d.message = tape.errors[id - 1].message;
  return d.format();
}
}

//------------------------------------------------------------------------------
bool vtkFRepImplicitFunction::BeginEvaluation(const char* caller, vtkMTimeType& key)
{
  Internals& in = *this->Internal;
  key = UpdateRound(this, in.Round, in.ErrorCount, in.ErrorWarned, in.ConfigurationReported);
  vtkFRepObject* object = this->FRepObject;
  if (object && object->GetDimension() == 3 && object->HasModel())
  {
    return true;
  }
  if (!in.ConfigurationReported.exchange(true))
  {
    vtkErrorMacro(<< caller << ": "
                  << (object && object->HasModel() ? "the object does not have 3 free coordinates"
                                                   : "no FRep object (or an empty one) is set")
                  << "; every point is outside");
  }
  return false;
}

//------------------------------------------------------------------------------
vtkFRepImplicitFunction::ThreadState& vtkFRepImplicitFunction::ThreadStateFor(vtkMTimeType key)
{
  ThreadState& s = this->Internal->Threads.Local();
  if (!s.Point || s.Key != key)
  {
    s.Tape = this->FRepObject->GetTape();
    s.Point = std::make_unique<frep::PointEvaluator>(s.Tape);
    s.Gradient.reset();
    s.Outputs.assign(s.Tape->outputs.size(), 0.0);
    s.Key = key;
  }
  return s;
}

//------------------------------------------------------------------------------
double vtkFRepImplicitFunction::EvaluateFunction(double x[3])
{
  vtkMTimeType key = 0;
  if (!this->BeginEvaluation("EvaluateFunction", key))
  {
    return this->ErrorValue;
  }
  Internals& in = *this->Internal;
  vtkFRepObject* object = this->FRepObject;
  ThreadState& s = this->ThreadStateFor(key);
  const int error = s.Point->evaluate(std::span<const double>(x, 3), s.Outputs);
  const double f = s.Outputs[0];
  if (error == 0 && !std::isnan(f))
  {
    return -f;
  }
  ++in.ErrorCount;
  if (!in.ErrorWarned.exchange(true))
  {
    vtkWarningMacro(<< "run-time error at (" << x[0] << ", " << x[1] << ", " << x[2]
                    << "): " << DescribeError(*s.Tape, error, object)
                    << "; such points are outside (" << this->ErrorValue
                    << "); further ones are counted (GetNumberOfEvaluationErrors) and not "
                       "reported again until the function or the object is modified");
  }
  return this->ErrorValue;
}

//------------------------------------------------------------------------------
void vtkFRepImplicitFunction::EvaluateGradient(double x[3], double g[3])
{
  g[0] = g[1] = g[2] = 0.0;
  vtkMTimeType key = 0;
  if (!this->BeginEvaluation("EvaluateGradient", key))
  {
    return;
  }
  Internals& in = *this->Internal;
  vtkFRepObject* object = this->FRepObject;
  ThreadState& s = this->ThreadStateFor(key);
  if (!s.Gradient)
  {
    s.Gradient = std::make_unique<frep::GradientEvaluator>(s.Tape);
  }
  double grad[3];
  const double f = s.Gradient->evaluate(std::span<const double>(x, 3), grad);
  if (!std::isnan(f))
  {
    g[0] = -grad[0];
    g[1] = -grad[1];
    g[2] = -grad[2];
    return;
  }
  ++in.ErrorCount;
  if (!in.ErrorWarned.exchange(true))
  {
    const int error = s.Point->evaluate(std::span<const double>(x, 3), s.Outputs);
    vtkWarningMacro(<< "run-time error in the gradient at (" << x[0] << ", " << x[1] << ", " << x[2]
                    << "): " << DescribeError(*s.Tape, error, object)
                    << "; the gradient there is (0, 0, 0); further failures are counted and "
                       "not reported again until the function or the object is modified");
  }
}

//------------------------------------------------------------------------------
void vtkFRepImplicitFunction::EvaluateFunction(vtkDataArray* input, vtkDataArray* output)
{
  if (!input || !output)
  {
    vtkErrorMacro(<< "EvaluateFunction: null array");
    return;
  }
  if (input->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro(<< "EvaluateFunction: the input array has " << input->GetNumberOfComponents()
                  << " components, not 3");
    return;
  }
  const vtkIdType n = input->GetNumberOfTuples();
  output->SetNumberOfComponents(1);
  output->SetNumberOfTuples(n);

  vtkMTimeType key = 0;
  if (!this->BeginEvaluation("EvaluateFunction", key))
  {
    output->Fill(this->ErrorValue);
    return;
  }
  Internals& in = *this->Internal;
  vtkFRepObject* object = this->FRepObject;

  std::lock_guard<std::mutex> lock(in.BatchMutex);
  if (!in.Batch || in.BatchKey != key)
  {
    in.Batch = std::make_unique<frep::BatchEvaluator>(object->GetTape());
    in.BatchKey = key;
  }
  const frep::Tape& tape = in.Batch->tape();

  auto* din = vtkDoubleArray::FastDownCast(input);
  auto* fin = vtkFloatArray::FastDownCast(input);
  auto* dout = vtkDoubleArray::FastDownCast(output);
  const vtkIdType chunk = std::min(n, BatchChunk);
  std::vector<double> xs(chunk), ys(chunk), zs(chunk), values(chunk);
  std::vector<std::uint32_t> errors(chunk);
  vtkIdType failed = 0;
  vtkIdType firstFailed = -1;
  int firstError = 0;
  for (vtkIdType begin = 0; begin < n; begin += chunk)
  {
    const vtkIdType count = std::min(chunk, n - begin);
    for (vtkIdType i = 0; i < count; ++i)
    {
      const vtkIdType t = begin + i;
      if (din)
      {
        const double* p = din->GetPointer(3 * t);
        xs[i] = p[0], ys[i] = p[1], zs[i] = p[2];
      }
      else if (fin)
      {
        const float* p = fin->GetPointer(3 * t);
        xs[i] = p[0], ys[i] = p[1], zs[i] = p[2];
      }
      else
      {
        xs[i] = input->GetComponent(t, 0);
        ys[i] = input->GetComponent(t, 1);
        zs[i] = input->GetComponent(t, 2);
      }
    }
    const double* inputs[] = { xs.data(), ys.data(), zs.data() };
    in.Batch->evaluate(inputs, static_cast<std::size_t>(count), values.data(), errors.data());
    for (vtkIdType i = 0; i < count; ++i)
    {
      double v = -values[i];
      if (errors[i] != 0 || std::isnan(v))
      {
        if (firstFailed < 0)
        {
          firstFailed = begin + i;
          firstError = static_cast<int>(errors[i]);
        }
        ++failed;
        v = this->ErrorValue;
      }
      if (dout)
      {
        dout->SetValue(begin + i, v);
      }
      else
      {
        output->SetComponent(begin + i, 0, v);
      }
    }
  }
  if (failed > 0)
  {
    in.ErrorCount += failed;
    in.ErrorWarned = true;
    double p[3];
    input->GetTuple(firstFailed, p);
    vtkWarningMacro(<< failed << " of " << n << " points raised run-time errors and are outside ("
                    << this->ErrorValue << "); the first, at (" << p[0] << ", " << p[1] << ", "
                    << p[2] << "): " << DescribeError(tape, firstError, object));
  }
}

//------------------------------------------------------------------------------
void vtkFRepImplicitFunction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FRepObject: ";
  if (this->FRepObject)
  {
    os << this->FRepObject << " (" << this->FRepObject->GetObjectName() << ", dimension "
       << this->FRepObject->GetDimension() << ")\n";
  }
  else
  {
    os << "(none)\n";
  }
  os << indent << "ErrorValue: " << this->ErrorValue << "\n";
  os << indent << "NumberOfEvaluationErrors: " << this->GetNumberOfEvaluationErrors() << "\n";
}
