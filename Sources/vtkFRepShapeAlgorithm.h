/**
 * @class   vtkFRepShapeAlgorithm
 * @brief   superclass of the filters that turn VTK data into a 3-D vtkFRepObject
 *
 * vtkImplicitFunctionToFRep, vtkPolyDataToFRep and vtkImageDataToFRep make a user function
 * `FunctionName(x)` (Documentation/user-functions.md) from their data and output the one-object
 * model `FunctionName_model(x[3], a[1]) { FunctionName_model = FunctionName(x); }` calling it:
 * a 3-D vtkFRepObject that every FRepKit filter takes (slice, boolean, sampler, polygoniser),
 * with the function's enclosures (meshing culls) and gradients. vtkHyperFunSource::AddShape
 * names such an object inside a HyperFun program.
 *
 * Coordinate ranges (the default box of samplers and polygonisers): Bounds when set, else the
 * data's bounds grown by Padding (a fraction of the diagonal) on every side; in
 * RequestInformation, before the data exist, [-10, 10] for a polydata input not yet executed
 * (set Bounds to plan downstream from it).
 *
 * @sa vtkFRepObjectAlgorithm vtkHyperFunSource
 */
#ifndef vtkFRepShapeAlgorithm_h
#define vtkFRepShapeAlgorithm_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkFRepObjectAlgorithm.h"

#ifndef __VTK_WRAP__
#include "Language/user_functions.h" // for frep::UserFunction
#include <memory>                    // for std::shared_ptr
#endif

class FREPKITSOURCES_EXPORT vtkFRepShapeAlgorithm : public vtkFRepObjectAlgorithm
{
public:
  /** The superclass alone makes no function (an error on update): use a subclass. */
  static vtkFRepShapeAlgorithm* New();
  vtkTypeMacro(vtkFRepShapeAlgorithm, vtkFRepObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The name the function (and the model, with "_model") gets: letters, digits and '_',
   * starting with a letter, not a library function's name. Default "shape".
   */
  vtkSetStringMacro(FunctionName);
  vtkGetStringMacro(FunctionName);
  ///@}

  ///@{
  /**
   * xmin, xmax, ymin, ymax, zmin, zmax of the output's coordinate ranges. Unset (the default,
   * xmin > xmax): from the data (see the class description).
   */
  vtkSetVector6Macro(Bounds, double);
  vtkGetVector6Macro(Bounds, double);
  ///@}

  ///@{
  /** Growth of the data's bounds on each side, as a fraction of their diagonal. Default 0.1. */
  vtkSetClampMacro(Padding, double, 0.0, 10.0);
  vtkGetMacro(Padding, double);
  ///@}

protected:
  vtkFRepShapeAlgorithm();
  ~vtkFRepShapeAlgorithm() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

#ifndef __VTK_WRAP__
  /**
   * The function from the inputs, and the data's bounds (xmin, xmax, ...; false when unknown).
   * Returns false after reporting an error (the output is then empty). The superclass's reports
   * that it makes none.
   */
  virtual bool MakeFunction(vtkInformationVector** inputVector, frep::UserFunction& function,
    double dataBounds[6], bool& haveBounds);
  /** The data's bounds from information alone (RequestInformation); false when unknown. */
  virtual bool InformationBounds(vtkInformationVector** inputVector, double dataBounds[6]);
#endif

  char* FunctionName = nullptr;
  double Bounds[6] = { 1, -1, 1, -1, 1, -1 };
  double Padding = 0.1;

private:
  void Ranges(const double dataBounds[6], bool haveBounds, double ranges[6]) const;
  vtkFRepShapeAlgorithm(const vtkFRepShapeAlgorithm&) = delete;
  void operator=(const vtkFRepShapeAlgorithm&) = delete;
};

#endif
