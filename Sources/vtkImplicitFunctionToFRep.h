/**
 * @class   vtkImplicitFunctionToFRep
 * @brief   any vtkImplicitFunction as a 3-D vtkFRepObject (F = -f: FRep is >= 0 inside)
 *
 * VTK's implicit functions are negative inside, FRep's objects positive: F(p) =
 * -FunctionValue(p), with the function's Transform applied as VTK's own filters do (ParaView's
 * Box is a vtkBox moved by its Transform). No enclosure is known for an arbitrary function, so meshing samples
 * every box (the whole line, never wrong); gradients by differences. Evaluation is serialised
 * by a lock (SerializeEvaluation, default on) because many vtkImplicitFunction subclasses are
 * not thread-safe (vtkImplicitPolyDataDistance's locator); turn it off for thread-safe ones
 * (vtkSphere, vtkPlane, vtkBox...) to let the evaluators run in parallel. The coordinate
 * ranges are Bounds when set, else [-10, 10]. No function: an error, and an empty output.
 *
 * @sa vtkFRepShapeAlgorithm vtkFRepImplicitFunction (the other way round)
 */
#ifndef vtkImplicitFunctionToFRep_h
#define vtkImplicitFunctionToFRep_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkFRepShapeAlgorithm.h"

class vtkImplicitFunction;

class FREPKITSOURCES_EXPORT vtkImplicitFunctionToFRep : public vtkFRepShapeAlgorithm
{
public:
  static vtkImplicitFunctionToFRep* New();
  vtkTypeMacro(vtkImplicitFunctionToFRep, vtkFRepShapeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The function (its MTime is part of this filter's). */
  virtual void SetImplicitFunction(vtkImplicitFunction* function);
  vtkGetObjectMacro(ImplicitFunction, vtkImplicitFunction);
  ///@}

  ///@{
  /** One evaluation at a time (default on; see the class description). */
  vtkSetMacro(SerializeEvaluation, bool);
  vtkGetMacro(SerializeEvaluation, bool);
  vtkBooleanMacro(SerializeEvaluation, bool);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkImplicitFunctionToFRep();
  ~vtkImplicitFunctionToFRep() override;
#ifndef __VTK_WRAP__
  bool MakeFunction(vtkInformationVector** inputVector, frep::UserFunction& function,
    double dataBounds[6], bool& haveBounds) override;
#endif

  vtkImplicitFunction* ImplicitFunction = nullptr;
  bool SerializeEvaluation = true;

private:
  vtkImplicitFunctionToFRep(const vtkImplicitFunctionToFRep&) = delete;
  void operator=(const vtkImplicitFunctionToFRep&) = delete;
};

#endif
