/**
 * @class   vtkPolyDataToFRep
 * @brief   a closed, oriented triangle mesh as a 3-D vtkFRepObject (signed distance)
 *
 * F(p) = +distance inside, -distance outside (F >= 0 inside, FRep's convention), from a
 * bounding-volume hierarchy over the triangles (FRep/Shapes/mesh_distance.h: O(log n) per point,
 * the sign from angle-weighted pseudonormals, enclosures over boxes so that meshing culls).
 * Polygons are fanned into triangles; lines, vertices and strips are refused. The mesh must be
 * closed and consistently oriented: otherwise the error names the open, non-manifold and
 * misoriented edge counts, unless UnsignedDistance is on (F = -distance: use it through
 * vtkHyperFunSource, e.g. `0.05 + name(x)` for a shell). An inward mesh is flipped.
 *
 * @sa vtkFRepShapeAlgorithm vtkImageDataToFRep vtkImplicitFunctionToFRep
 */
#ifndef vtkPolyDataToFRep_h
#define vtkPolyDataToFRep_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkFRepShapeAlgorithm.h"

class FREPKITSOURCES_EXPORT vtkPolyDataToFRep : public vtkFRepShapeAlgorithm
{
public:
  static vtkPolyDataToFRep* New();
  vtkTypeMacro(vtkPolyDataToFRep, vtkFRepShapeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Accept any triangles (open, non-manifold): F = -unsigned distance. Default off. */
  vtkSetMacro(UnsignedDistance, bool);
  vtkGetMacro(UnsignedDistance, bool);
  vtkBooleanMacro(UnsignedDistance, bool);
  ///@}

protected:
  vtkPolyDataToFRep();
  ~vtkPolyDataToFRep() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
#ifndef __VTK_WRAP__
  bool MakeFunction(vtkInformationVector** inputVector, frep::UserFunction& function,
    double dataBounds[6], bool& haveBounds) override;
  bool InformationBounds(vtkInformationVector** inputVector, double dataBounds[6]) override;
#endif

  bool UnsignedDistance = false;

private:
  vtkPolyDataToFRep(const vtkPolyDataToFRep&) = delete;
  void operator=(const vtkPolyDataToFRep&) = delete;
};

#endif
