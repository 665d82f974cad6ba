/**
 * @class   vtkFRepEvaluator
 * @brief   evaluates F (and s[1..m]) of a vtkFRepObject at many points in one call
 *
 * vtkFRepEvaluator is the wrappable face of the engine's batch evaluator: it takes N points of
 * a k-D object (k = the object's free dimension, vtkFRepObject::GetDimension()) as a vtkDataArray
 * of N tuples with k components (any numeric type; values are converted to double) or as
 * vtkPoints (k <= 3: the first k components of each point are used), and fills vtkDoubleArray
 * outputs: F with 1 component per point, and optionally s[1..m] with m components (m =
 * GetNumberOfAttributes()) and the run-time error id of each point (0 = none). From Python the
 * arrays come from and go to numpy through vtkmodules.util.numpy_support.
 *
 * The values are those of the engine's evaluators, bit for bit (frep::BatchEvaluator, which
 * equals frep::PointEvaluator and the frepkit eval command); a point whose evaluation raised a
 * run-time error (division by ~0, sqrt of a negative, ...) has F = s[] = NaN, its error id in
 * the optional error array, and GetErrorMessage(id) names the place in the model
 * ("file:line:col: message").
 *
 * Bad calls never crash: a null or model-less object, a null array, a wrong number of
 * components or a non-numeric array are reported with vtkErrorMacro (a VTK ErrorEvent, which a
 * Python observer sees) and Evaluate returns false, leaving the outputs empty.
 *
 * The object is evaluated as it is when Evaluate is called (its tape, cached by the object);
 * the evaluator is rebuilt only when the object's tape or NumberOfThreads changes.
 *
 * @sa vtkFRepObject vtkFRepImplicitFunction vtkFRepSampler
 */
#ifndef vtkFRepEvaluator_h
#define vtkFRepEvaluator_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkDataArray;
class vtkDoubleArray;
class vtkFRepObject;
class vtkIntArray;
class vtkPoints;

class FREPKITSOURCES_EXPORT vtkFRepEvaluator : public vtkObject
{
public:
  static vtkFRepEvaluator* New();
  vtkTypeMacro(vtkFRepEvaluator, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The object to evaluate (default none). The evaluator keeps a reference.
   */
  virtual void SetObject(vtkFRepObject* object);
  vtkGetObjectMacro(Object, vtkFRepObject);
  ///@}

  ///@{
  /**
   * Worker threads of the batch evaluator (default 0: every core; 1: the calling thread only;
   * at most 1024, like frepkit eval --threads).
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /** Free dimension k of the object (the components a point needs), 0 without a model. */
  int GetDimension();
  /**
   * Number of s[] attributes m of the object (its s_dim: 1 for a model that declares no s[],
   * whose s[1] is 0, as in HyperFun), 0 without a model.
   */
  int GetNumberOfAttributes();

  ///@{
  /**
   * Evaluates the object at every tuple of `points` (N tuples, GetDimension() components).
   * `values` receives F (N tuples, 1 component, named "F"); `attributes`, if given, s[1..m]
   * (N tuples, m components, named "s"; no tuples when the model has none); `errors`, if
   * given, the run-time error id of each point (0 = none, named "ErrorId").
   * Returns true on success; false (with a VTK error, outputs emptied) on a bad call.
   */
  bool Evaluate(vtkDataArray* points, vtkDoubleArray* values);
  bool Evaluate(vtkDataArray* points, vtkDoubleArray* values, vtkDoubleArray* attributes);
  bool Evaluate(vtkDataArray* points, vtkDoubleArray* values, vtkDoubleArray* attributes,
    vtkIntArray* errors);
  ///@}

  ///@{
  /**
   * The same for vtkPoints: the object must have dimension 1..3; the first GetDimension()
   * components of each point are its coordinates (the others are ignored).
   */
  bool EvaluatePoints(vtkPoints* points, vtkDoubleArray* values);
  bool EvaluatePoints(vtkPoints* points, vtkDoubleArray* values, vtkDoubleArray* attributes);
  ///@}

  /**
   * F at one point of `k` coordinates (k = GetDimension()); NaN on a bad call (with a VTK
   * error) or where the point raises a run-time error. For checks, not for loops: use Evaluate.
   */
  double EvaluatePoint(const double* x, int k) VTK_SIZEHINT(x, k);

  /** Points of the last successful Evaluate that raised a run-time error. */
  vtkGetMacro(NumberOfErrorPoints, vtkIdType);

  /**
   * "file:line:col: message" of run-time error `id` of the object's tape (1-based, as in the
   * error array), "" for an id the tape does not have.
   */
  std::string GetErrorMessage(int id);

  vtkMTimeType GetMTime() override;

protected:
  /**
   * Defaults: no object, NumberOfThreads 0 (every core).
   */
  vtkFRepEvaluator();
  ~vtkFRepEvaluator() override;

  vtkFRepObject* Object = nullptr;
  int NumberOfThreads = 0;
  vtkIdType NumberOfErrorPoints = 0;

private:
  vtkFRepEvaluator(const vtkFRepEvaluator&) = delete;
  void operator=(const vtkFRepEvaluator&) = delete;

  bool Run(const char* method, vtkDataArray* points, int columns, vtkDoubleArray* values,
    vtkDoubleArray* attributes, vtkIntArray* errors);
  // Run's checks of its arguments and the object (each failure a vtkErrorMacro naming `method`).
  bool CanRun(const char* method, vtkDataArray* points, int columns, vtkDoubleArray* values);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
