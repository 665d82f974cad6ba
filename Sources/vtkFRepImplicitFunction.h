/**
 * @class   vtkFRepImplicitFunction
 * @brief   a vtkImplicitFunction over a 3-D vtkFRepObject
 *
 * vtkFRepImplicitFunction lets every VTK filter that takes an implicit function
 * (vtkSampleFunction, vtkCutter, vtkClipPolyData, vtkExtractGeometry, ...) use an FRep shape: a
 * vtkFRepObject whose dimension (number of free coordinates) is 3. In ParaView, whose own Clip
 * and Slice list a fixed set of functions, the plug-in's FRep Clip and FRep Cut take it.
 * Its free coordinates, in axis order, are x, y, z.
 *
 * SIGN CONVENTION: VTK's implicit functions are negative inside, FRep functions are positive
 * inside. EvaluateFunction returns -F and EvaluateGradient returns -grad F, so the inside of
 * the FRep object is the inside of the implicit function, and the gradient points outwards.
 *
 * RUN-TIME ERRORS: a point where the model raises a run-time error (division by ~0, sqrt of a
 * negative number, ...) is outside: EvaluateFunction returns ErrorValue (default VTK_FLOAT_MAX,
 * finite so that it survives a conversion to float) and EvaluateGradient returns (0, 0, 0). The
 * failed points are counted (GetNumberOfEvaluationErrors). The first failure after the function
 * or the object was modified is reported through one vtkWarningMacro naming the point, the
 * message and its file:line:col; the later ones in the same round are only counted, until
 * Modified() or ResetEvaluationErrors() starts a new round. EvaluateFunction(vtkDataArray*,
 * vtkDataArray*) reports the count of its call in one warning. Never silent, never a warning
 * per point (see Documentation/compatibility.md, "Run-time errors").
 *
 * THREADS: EvaluateFunction and EvaluateGradient may be called from many SMP threads at once
 * (vtkSampleFunction, vtkCutter): each thread evaluates with its own frep::PointEvaluator /
 * frep::GradientEvaluator over the shared, immutable tape (vtkSMPThreadLocal); there is no lock
 * on the per-point path (the states follow vtkSMPThreadLocal: with the STDThread backend any
 * thread gets its own; with the Sequential backend there is one state, so call it from one
 * thread at a time there). EvaluateFunction(vtkDataArray*, vtkDataArray*) evaluates all points
 * with the engine's frep::BatchEvaluator (SIMD lanes on all cores), much faster than one point
 * at a time; concurrent calls of it are serialised. Do not modify the function or the object
 * while another thread evaluates it.
 *
 * Without an object, or with one whose dimension is not 3, evaluation reports an error once
 * and returns ErrorValue (outside).
 *
 * @sa vtkFRepObject vtkHyperFunSource vtkImplicitFunction
 */
#ifndef vtkFRepImplicitFunction_h
#define vtkFRepImplicitFunction_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkImplicitFunction.h"

#include <atomic> // for std::atomic
#include <memory> // for std::unique_ptr

class vtkFRepObject;

class FREPKITSOURCES_EXPORT vtkFRepImplicitFunction : public vtkImplicitFunction
{
public:
  static vtkFRepImplicitFunction* New();
  vtkTypeMacro(vtkFRepImplicitFunction, vtkImplicitFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The object (default none). Its dimension must be 3: setting another one is an error (the
   * object is still kept, and evaluation returns ErrorValue).
   */
  void SetFRepObject(vtkFRepObject* object);
  vtkGetObjectMacro(FRepObject, vtkFRepObject);
  ///@}

  ///@{
  /**
   * The value returned where the model raises a run-time error or cannot be evaluated
   * (default VTK_FLOAT_MAX: far outside).
   */
  vtkSetMacro(ErrorValue, double);
  vtkGetMacro(ErrorValue, double);
  ///@}

  ///@{
  /**
   * -F at x (negative inside), ErrorValue where the model raises a run-time error.
   * The array form evaluates the 3-component points of `input` into the 1-component `output`
   * with the batch evaluator.
   */
  using vtkImplicitFunction::EvaluateFunction;
  double EvaluateFunction(double x[3]) override;
  void EvaluateFunction(vtkDataArray* input, vtkDataArray* output) override;
  ///@}

  /**
   * -grad F at x (the outward normal direction); (0, 0, 0) on a run-time error.
   */
  void EvaluateGradient(double x[3], double g[3]) override;

  /**
   * Points that raised a run-time error since the last Modified() of the function or the
   * object (or ResetEvaluationErrors()).
   */
  vtkIdType GetNumberOfEvaluationErrors();
  void ResetEvaluationErrors();

  /**
   * Includes the object's MTime.
   */
  vtkMTimeType GetMTime() override;

protected:
  /**
   * Defaults: no FRepObject, ErrorValue VTK_FLOAT_MAX.
   */
  vtkFRepImplicitFunction();
  ~vtkFRepImplicitFunction() override;

  vtkFRepObject* FRepObject = nullptr;
  double ErrorValue;

private:
  vtkFRepImplicitFunction(const vtkFRepImplicitFunction&) = delete;
  void operator=(const vtkFRepImplicitFunction&) = delete;

  struct ThreadState; // one thread's evaluators
  struct Internals;
  std::unique_ptr<Internals> Internal;

  // Starts (or continues) an evaluation round; false, after reporting it once, when there is
  // no usable 3-D object. `key` identifies the round's tape.
  bool BeginEvaluation(const char* caller, vtkMTimeType& key);
  // The calling thread's evaluators, rebuilt when the round's tape changed.
  ThreadState& ThreadStateFor(vtkMTimeType key);
};

#endif
