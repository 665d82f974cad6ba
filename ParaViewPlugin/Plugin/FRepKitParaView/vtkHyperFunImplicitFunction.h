/**
 * @class   vtkHyperFunImplicitFunction
 * @brief   vtkFRepImplicitFunction over a HyperFun object given by text or file
 *
 * vtkHyperFunImplicitFunction is the FRep shape of ParaView's implicit-function list (Clip,
 * Slice, ... "FRep Shape"): a vtkFRepImplicitFunction that makes its object itself, from a .hf
 * file (FileName, which wins) or HyperFun text (ModelText), with ObjectName chosen as in
 * vtkHyperFunSource. x1, x2, x3 are x, y, z; the extra coordinates x4..x8 are fixed to
 * ExtraCoordinates (default 0 each), any further one to the midpoint of its interval
 * ([-10, 10], i.e. 0).
 *
 * The object is (re)built lazily, at the first GetMTime() or evaluation after a change of
 * FileName, ModelText, ObjectName or ExtraCoordinates (parse and compile: milliseconds), so a
 * filter that asks for the function's MTime before executing (every VTK pipeline does) sees a
 * stable function. Reload() reads the file again (after it was edited). Parse errors are
 * reported by the internal vtkHyperFunSource with file:line:col; the function is then without
 * an object and evaluates to ErrorValue (outside), as vtkFRepImplicitFunction does. The sign
 * convention is vtkFRepImplicitFunction's: -F, negative inside.
 *
 * Thread safety: evaluation may run on many threads (see vtkFRepImplicitFunction); a rebuild is
 * guarded by a mutex and happens once. Do not change properties while evaluating.
 *
 * @sa vtkFRepImplicitFunction vtkHyperFunSource
 */

#ifndef vtkHyperFunImplicitFunction_h
#define vtkHyperFunImplicitFunction_h

#include "FRepKitParaViewModule.h" // for export macro
#include "vtkFRepImplicitFunction.h"
#include "vtkNew.h" // for vtkNew

#include <atomic> // for std::atomic
#include <mutex>  // for std::mutex
#include <string> // for std::string

class vtkHyperFunSource;

class FREPKITPARAVIEW_EXPORT vtkHyperFunImplicitFunction : public vtkFRepImplicitFunction
{
public:
  static vtkHyperFunImplicitFunction* New();
  vtkTypeMacro(vtkHyperFunImplicitFunction, vtkFRepImplicitFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Extra coordinates with a value of their own: x4..x8. */
  static constexpr int NumberOfExtraCoordinates = 5;

  ///@{
  /**
   * A .hf file (default none); wins over ModelText.
   */
  void SetFileName(const char* name);
  const char* GetFileName() const { return this->FileName.c_str(); }
  ///@}

  ///@{
  /**
   * HyperFun program text (default none).
   */
  void SetModelText(const char* text);
  const char* GetModelText() const { return this->ModelText.c_str(); }
  ///@}

  ///@{
  /**
   * The object, case-insensitive (default none: my_model, else the first object). Named as
   * in vtkHyperFunSource; like there, it hides vtkObjectBase's debugging label of that name.
   */
  void SetObjectName(const char* name);
  const char* GetObjectName() { return this->HyperFunObject.c_str(); }
  ///@}

  ///@{
  /**
   * Value of x[4 + i] (i = 0..4; default 0 each). Out of range: an error.
   */
  void SetExtraCoordinate(int i, double value);
  double GetExtraCoordinate(int i) const;
  ///@}

  /**
   * Reads the file (or text) again at the next use, e.g. after the file was edited.
   */
  void Reload();

  ///@{
  /**
   * Build the object first if a property changed.
   */
  using vtkFRepImplicitFunction::EvaluateFunction;
  double EvaluateFunction(double x[3]) override;
  void EvaluateFunction(vtkDataArray* input, vtkDataArray* output) override;
  void EvaluateGradient(double x[3], double g[3]) override;
  vtkMTimeType GetMTime() override;
  ///@}

protected:
  /**
   * Defaults: no FileName, ModelText or ObjectName, ExtraCoordinates 0.
   */
  vtkHyperFunImplicitFunction();
  ~vtkHyperFunImplicitFunction() override;

private:
  vtkHyperFunImplicitFunction(const vtkHyperFunImplicitFunction&) = delete;
  void operator=(const vtkHyperFunImplicitFunction&) = delete;

  // Builds the object if the request changed since the last build.
  void Prepare();
  void RequestChanged();

  std::string FileName;
  std::string ModelText;
  std::string HyperFunObject;
  double ExtraCoordinates[NumberOfExtraCoordinates] = {};
  vtkNew<vtkHyperFunSource> Source;
  std::mutex BuildMutex;
  std::atomic<unsigned long> Requested{ 1 }; // counts changes of the request
  std::atomic<unsigned long> Built{ 0 };     // the request the object was built for
};

#endif
