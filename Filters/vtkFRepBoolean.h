/**
 * @class   vtkFRepBoolean
 * @brief   a new n-D FRep object from two: set operations, blends, Cartesian product
 *
 * vtkFRepBoolean takes two vtkFRepObjects, A on input port 0 and B on port 1 (also
 * SetSourceConnection / SetSourceData), and produces the vtkFRepObject of a composed model
 * (frep::combine): each input is taken as it stands, with its own fixed coordinates, a[] and
 * order of free coordinates, and the output's coordinates are the inputs' FREE coordinates.
 *
 * Operation (values bit for bit as the HyperFun operators and library compute them):
 * - Union A | B, Intersection A & B, Difference A \ B (= A & -B): the R-functions of the
 *   language. Both inputs must have the same dimension k (number of free coordinates); output
 *   coordinate i is free coordinate (axis) i of both.
 * - BlendUnion hfBlendUni(A, B, a0, a1, a2), BlendIntersection hfBlendInt(A, B, a0, a1, a2), with
 *   a0 = BlendDisplacement and (a1, a2) = BlendParameters. Same dimension rule.
 * - CartesianProduct A(xA) & B(xB) (the language's `@`): kA + kB coordinates, A's then B's, e.g.
 *   a 2-D disc times a 1-D interval is a 3-D cylinder.
 *
 * The output has every coordinate free, in order, no a[] (the inputs' parameters are part of the
 * model). Its s[] are A's where F_A >= F_B, else B's (the colours of a union follow the visible
 * operand). Coordinate names and intervals come from the inputs:
 * - set operations and blends: A's names; each interval is the union hull of A's and B's
 *   intervals of that axis (the box that holds both operands' boxes);
 * - product: A's then B's names and intervals.
 * Names stay unique: a name that an earlier output coordinate already has (in a product both
 * inputs usually start with "x1") becomes the default name of its position, "x<i+1>" (primed
 * if that is taken too); a disc (x1, x2) times an interval (x1) has x1, x2, x3.
 * The object name is e.g. "union(ball, box)".
 *
 * Errors: an input without a model (e.g. a source that failed to parse) or inputs of different
 * dimensions for a set operation or blend are reported by vtkErrorMacro with both inputs'
 * dimensions and names, and the output is empty (an initialised vtkFRepObject without a model).
 * The filter still returns success, so that VTK adds no second, position-less error.
 *
 * PIPELINE: RequestInformation combines the operands' vtkFRepInformation keys into the output's
 * (dimension, names, intervals, the object name) without executing anything upstream; operands
 * it can tell do not fit (no object, different dimensions) publish no object there and are
 * reported by RequestData. Every rank of a parallel run builds the whole object
 * (CAN_HANDLE_PIECE_REQUEST, see vtkFRepObjectAlgorithm).
 *
 * @sa vtkFRepObject vtkFRepObjectAlgorithm vtkFRepInformation vtkHyperFunSource vtkFRepSlice
 */
#ifndef vtkFRepBoolean_h
#define vtkFRepBoolean_h

#include "FRepKitFiltersModule.h" // for export macro
#include "vtkFRepInformation.h" // for vtkFRepInformation::Metadata
#include "vtkFRepObjectAlgorithm.h"

class vtkAlgorithmOutput;
class vtkFRepObject;

class FREPKITFILTERS_EXPORT vtkFRepBoolean : public vtkFRepObjectAlgorithm
{
public:
  static vtkFRepBoolean* New();
  vtkTypeMacro(vtkFRepBoolean, vtkFRepObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum OperationType
  {
    VTK_UNION = 0,
    VTK_INTERSECTION,
    VTK_DIFFERENCE,
    VTK_BLEND_UNION,
    VTK_BLEND_INTERSECTION,
    VTK_CARTESIAN_PRODUCT
  };

  ///@{
  /**
   * The operation (default VTK_UNION).
   */
  vtkSetClampMacro(Operation, int, VTK_UNION, VTK_CARTESIAN_PRODUCT);
  vtkGetMacro(Operation, int);
  void SetOperationToUnion() { this->SetOperation(VTK_UNION); }
  void SetOperationToIntersection() { this->SetOperation(VTK_INTERSECTION); }
  void SetOperationToDifference() { this->SetOperation(VTK_DIFFERENCE); }
  void SetOperationToBlendUnion() { this->SetOperation(VTK_BLEND_UNION); }
  void SetOperationToBlendIntersection() { this->SetOperation(VTK_BLEND_INTERSECTION); }
  void SetOperationToCartesianProduct() { this->SetOperation(VTK_CARTESIAN_PRODUCT); }
  /**
   * "Union", "Intersection", "Difference", "BlendUnion", "BlendIntersection" or
   * "CartesianProduct".
   */
  const char* GetOperationAsString() const;
  ///@}

  ///@{
  /**
   * The blends' displacement a0 (default 1): how far the blend bulges out (union) or in
   * (intersection) where the operands meet. Used by BlendUnion and BlendIntersection only.
   */
  vtkSetMacro(BlendDisplacement, double);
  vtkGetMacro(BlendDisplacement, double);
  ///@}

  ///@{
  /**
   * The blends' a1 and a2 (default 1, 1): the extent of the blend along A's and along B's
   * values (hfBlendUni/hfBlendInt divide F_A by a1 and F_B by a2; 0 gives inf/NaN, as there).
   */
  vtkSetVector2Macro(BlendParameters, double);
  vtkGetVector2Macro(BlendParameters, double);
  ///@}

  ///@{
  /**
   * Operand A is input port 0: SetInputConnection(0, ...), SetInputData(a) or
   * SetInputData(0, a). Operand B is port 1: SetSourceConnection(...) / SetSourceData(b), the
   * same as SetInputConnection(1, ...) / SetInputData(1, b). The Data forms take an object
   * without a pipeline connection (e.g. a sliced copy).
   */
  void SetSourceConnection(vtkAlgorithmOutput* output);
  void SetSourceData(vtkDataObject* b);
  ///@}

protected:
  /**
   * Defaults: Operation VTK_UNION, BlendDisplacement 1, BlendParameters (1, 1); two input ports
   * (A, B) and one output port, all vtkFRepObject.
   */
  vtkFRepBoolean();
  ~vtkFRepBoolean() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Operation = VTK_UNION;
  double BlendDisplacement = 1.0;
  double BlendParameters[2] = { 1.0, 1.0 };

private:
  vtkFRepBoolean(const vtkFRepBoolean&) = delete;
  void operator=(const vtkFRepBoolean&) = delete;

#ifndef __VTK_WRAP__
  // Names and intervals of the output's coordinates (all free), from the operands' metadata
  // (see the class comment); used by RequestInformation and RequestData alike.
  void CombineCoordinates(const vtkFRepInformation::Metadata& a,
    const vtkFRepInformation::Metadata& b,
    vtkFRepInformation::Metadata& output) const;
#endif
};

#endif
