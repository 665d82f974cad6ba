/**
 * @class   vtkImageDataToFRep
 * @brief   a scalar volume (vtkImageData) as a 3-D vtkFRepObject: trilinear value minus IsoValue
 *
 * F(p) = trilinear(scalars)(p) - IsoValue inside the image (F >= 0 where the field is at least
 * the iso value), and outside it the border's value minus the distance to the image, so the
 * object is bounded (FRep/Shapes/volume_field.h). Enclosures over boxes come from the min/max
 * of bricks of 8^3 cells: meshing culls. Reads the active point scalars (else the first point
 * array), component 0; a 3-D image of at least 2 samples per axis. An image without point
 * scalars, with non-finite values or flat on an axis is refused with a message.
 *
 * @sa vtkFRepShapeAlgorithm vtkPolyDataToFRep
 */
#ifndef vtkImageDataToFRep_h
#define vtkImageDataToFRep_h

#include "FRepKitSourcesModule.h" // for export macro
#include "vtkFRepShapeAlgorithm.h"

class FREPKITSOURCES_EXPORT vtkImageDataToFRep : public vtkFRepShapeAlgorithm
{
public:
  static vtkImageDataToFRep* New();
  vtkTypeMacro(vtkImageDataToFRep, vtkFRepShapeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The iso value: F = value - IsoValue. Default 0. */
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

protected:
  vtkImageDataToFRep();
  ~vtkImageDataToFRep() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
#ifndef __VTK_WRAP__
  bool MakeFunction(vtkInformationVector** inputVector, frep::UserFunction& function,
    double dataBounds[6], bool& haveBounds) override;
  bool InformationBounds(vtkInformationVector** inputVector, double dataBounds[6]) override;
#endif

  double IsoValue = 0;

private:
  vtkImageDataToFRep(const vtkImageDataToFRep&) = delete;
  void operator=(const vtkImageDataToFRep&) = delete;
};

#endif
