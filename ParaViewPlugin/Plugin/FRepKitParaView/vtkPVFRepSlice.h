/**
 * @class   vtkPVFRepSlice
 * @brief   vtkFRepSlice driven by one value per coordinate, for sliders in ParaView
 *
 * vtkPVFRepSlice is the vtkFRepSlice behind ParaView's "FRep Slice". Instead of a list of
 * fixing requests it has one value per model coordinate x1..x8 (X1..X8, default 0; ParaView
 * starts each at the midpoint of the coordinate's interval) and a choice of the coordinates
 * that stay free:
 *
 * - FreeCoordinateOrder (inherited; ParaView's "FreeCoordinates"), e.g. "x1,x3,x4": exactly
 *   these stay free, in this order (as in vtkFRepSlice);
 * - empty (the default): the first OutputDimension (default 3) free coordinates of the input
 *   stay free, in the input's order.
 *
 * Every other free coordinate of the input is fixed: coordinate i < 8 to the value Xi+1, any
 * coordinate beyond x8 to the midpoint of its interval. Requests made through vtkFRepSlice's
 * own API (SetFixedValue, SetFixedValueByName) still apply and win over the automatic ones.
 * Coordinates fixed upstream stay fixed (their slider has no effect). A 4-D object with the
 * defaults gives the 3-D cross-section x4 = X4; a 5-D one x4 = X4, x5 = X5.
 *
 * For the sliders' ranges, RequestInformation reads the input's vtkFRepInformation keys (nothing
 * upstream is executed) and GetXiRange() then gives the interval of model coordinate xi ([0, 0]
 * for a coordinate the input does not have), GetCoordinateSliders() which of X1..X8 act on the
 * input (ParaView shows only those sliders); the output's keys are those of the cross-section
 * RequestData will make. Errors are vtkFRepSlice's: one message listing every
 * problem (e.g. an unknown name in FreeCoordinateOrder) and an empty output.
 *
 * @sa vtkFRepSlice vtkFRepObject
 */

#ifndef vtkPVFRepSlice_h
#define vtkPVFRepSlice_h

#include "FRepKitParaViewModule.h" // for export macro
#include "vtkFRepSlice.h"

#include <functional> // for std::function
#include <map>        // for std::map

class FREPKITPARAVIEW_EXPORT vtkPVFRepSlice : public vtkFRepSlice
{
public:
  static vtkPVFRepSlice* New();
  vtkTypeMacro(vtkPVFRepSlice, vtkFRepSlice);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Coordinates with a value of their own (X1..X8). */
  static constexpr int NumberOfValues = 8;

  ///@{
  /**
   * The value of model coordinate xi when it is fixed (default 0 each).
   */
  vtkSetMacro(X1, double);
  vtkGetMacro(X1, double);
  vtkSetMacro(X2, double);
  vtkGetMacro(X2, double);
  vtkSetMacro(X3, double);
  vtkGetMacro(X3, double);
  vtkSetMacro(X4, double);
  vtkGetMacro(X4, double);
  vtkSetMacro(X5, double);
  vtkGetMacro(X5, double);
  vtkSetMacro(X6, double);
  vtkGetMacro(X6, double);
  vtkSetMacro(X7, double);
  vtkGetMacro(X7, double);
  vtkSetMacro(X8, double);
  vtkGetMacro(X8, double);
  ///@}

  /** Value of coordinate `coordinate` (0-based, < NumberOfValues), NaN beyond. */
  double GetValue(int coordinate) const;

  ///@{
  /**
   * Free coordinates kept when FreeCoordinateOrder is empty (default 3; 1..3).
   */
  vtkSetClampMacro(OutputDimension, int, 1, 3);
  vtkGetMacro(OutputDimension, int);
  ///@}

  ///@{
  /**
   * Interval of model coordinate xi in the input, after RequestInformation ([0, 0] when the
   * input has no such coordinate or no model).
   */
  double* GetX1Range() VTK_SIZEHINT(2) { return this->Ranges[0]; }
  double* GetX2Range() VTK_SIZEHINT(2) { return this->Ranges[1]; }
  double* GetX3Range() VTK_SIZEHINT(2) { return this->Ranges[2]; }
  double* GetX4Range() VTK_SIZEHINT(2) { return this->Ranges[3]; }
  double* GetX5Range() VTK_SIZEHINT(2) { return this->Ranges[4]; }
  double* GetX6Range() VTK_SIZEHINT(2) { return this->Ranges[5]; }
  double* GetX7Range() VTK_SIZEHINT(2) { return this->Ranges[6]; }
  double* GetX8Range() VTK_SIZEHINT(2) { return this->Ranges[7]; }
  ///@}

  /**
   * Which sliders X1..X8 act on the input, after RequestInformation: element i is 1 when the
   * input's model has coordinate x(i+1) and it is free in the input (so fixing it means
   * something), else 0 (no such coordinate, fixed upstream, or no input). ParaView shows the
   * slider Xi only where this is 1.
   */
  int* GetCoordinateSliders() VTK_SIZEHINT(8) { return this->Sliders; }

protected:
  /**
   * Defaults: X1..X8 0, OutputDimension 3, no FreeCoordinateOrder.
   */
  vtkPVFRepSlice();
  ~vtkPVFRepSlice() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double X1 = 0.0;
  double X2 = 0.0;
  double X3 = 0.0;
  double X4 = 0.0;
  double X5 = 0.0;
  double X6 = 0.0;
  double X7 = 0.0;
  double X8 = 0.0;
  int OutputDimension = 3;
  double Ranges[NumberOfValues][2] = {};
  int Sliders[NumberOfValues] = {};

private:
  vtkPVFRepSlice(const vtkPVFRepSlice&) = delete;
  void operator=(const vtkPVFRepSlice&) = delete;

#ifndef __VTK_WRAP__
  // The values of the free coordinates that neither stay free nor are requested explicitly.
  std::map<int, double> AutomaticValues(const vtkFRepInformation::Metadata& input) const;
  // Runs `pass` (a superclass pass) with AutomaticValues(input) added to FixedValues.
  int WithAutomaticValues(
    const vtkFRepInformation::Metadata& input, const std::function<int()>& pass);
#endif
};

#endif
