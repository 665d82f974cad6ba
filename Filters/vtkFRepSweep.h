/**
 * @class   vtkFRepSweep
 * @brief   the volume a 3-D FRep object sweeps moving along a path
 *
 * vtkFRepSweep takes a vtkFRepObject with three free coordinates (the profile: any FRep
 * producer's object, a HyperFun model, a mesh's or a volume's distance, a slice, a projection)
 * and produces the 3-D vtkFRepObject of every point the profile covers as it moves along a path
 * of points (frep::project::sweep_model, then frep::project::project along the path's
 * parameter; Documentation/projection.md). The profile's origin follows the path; with
 * Orientation Tangent its own z axis follows the path's tangent.
 *
 * The path: AddPathPoint(x, y, z) in the profile's coordinates (RemoveAllPathPoints clears
 * them), joined by straight segments (Curve Polyline, the default) or by a uniform Catmull-Rom
 * spline (CatmullRom); Closed returns to the first point.
 *
 * The output's coordinates are the input's free ones (their names), each over the range that
 * holds the sweep: the input's ranges moved over the path's extent (frep::project::sweep_bounds).
 * Its values are within Tolerance below the maximum over the path; beyond +-Band only the sign is
 * kept (as vtkFRepProjection's).
 *
 * ERRORS (one vtkErrorMacro when the filter executes; the output is then empty and the filter
 * still returns success, as vtkFRepProjection does): an input without three free coordinates, a
 * path of too few points (2, or 3 when closed), a point that is not finite, two consecutive
 * points alike, a Tolerance <= 0 or a Band <= Tolerance. An empty input gives an empty output
 * quietly.
 *
 * PIPELINE: RequestInformation publishes the output's keys from the input's and the path
 * (nothing upstream is executed). The sweep is built in RequestData, in milliseconds: the work
 * is done point by point downstream (a sampler or polygoniser), with UpdateProgress there.
 *
 * @sa vtkFRepProjection vtkFRepObject vtkFRepPolygonizer
 */
#ifndef vtkFRepSweep_h
#define vtkFRepSweep_h

#include "FRepKitFiltersModule.h" // for export macro
#include "vtkFRepObjectAlgorithm.h"

#include <array>  // for std::array
#include <string> // for std::string
#include <vector> // for std::vector

class FREPKITFILTERS_EXPORT vtkFRepSweep : public vtkFRepObjectAlgorithm
{
public:
  static vtkFRepSweep* New();
  vtkTypeMacro(vtkFRepSweep, vtkFRepObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum CurveType
  {
    POLYLINE = 0,
    CATMULL_ROM = 1
  };
  enum OrientationType
  {
    FIXED = 0,
    TANGENT = 1
  };

  ///@{
  /**
   * The path's points, in order (default none).
   */
  void AddPathPoint(double x, double y, double z);
  void RemoveAllPathPoints();
  int GetNumberOfPathPoints() const { return static_cast<int>(this->PathPoints.size()); }
  void GetPathPoint(int i, double point[3]) const;
  ///@}

  ///@{
  /**
   * How the points are joined (default POLYLINE).
   */
  vtkSetClampMacro(Curve, int, POLYLINE, CATMULL_ROM);
  vtkGetMacro(Curve, int);
  void SetCurveToPolyline() { this->SetCurve(POLYLINE); }
  void SetCurveToCatmullRom() { this->SetCurve(CATMULL_ROM); }
  ///@}

  ///@{
  /**
   * The path returns to its first point (default off).
   */
  vtkSetMacro(Closed, vtkTypeBool);
  vtkGetMacro(Closed, vtkTypeBool);
  vtkBooleanMacro(Closed, vtkTypeBool);
  ///@}

  ///@{
  /**
   * FIXED: the profile moves as it stands (default); TANGENT: its z axis follows the tangent.
   */
  vtkSetClampMacro(Orientation, int, FIXED, TANGENT);
  vtkGetMacro(Orientation, int);
  void SetOrientationToFixed() { this->SetOrientation(FIXED); }
  void SetOrientationToTangent() { this->SetOrientation(TANGENT); }
  ///@}

  ///@{
  /**
   * The values are within Tolerance below the maximum (default 1e-4, > 0).
   */
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Beyond +-Band only the sign is kept (default 0.1, > Tolerance).
   */
  vtkSetMacro(Band, double);
  vtkGetMacro(Band, double);
  ///@}

protected:
  /**
   * Defaults: no path, POLYLINE, open, FIXED, Tolerance 1e-4, Band 0.1; one input and one
   * output port, both vtkFRepObject.
   */
  vtkFRepSweep();
  ~vtkFRepSweep() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::vector<std::array<double, 3>> PathPoints;
  int Curve = POLYLINE;
  vtkTypeBool Closed = false;
  int Orientation = FIXED;
  double Tolerance = 1e-4;
  double Band = 0.1;

private:
  vtkFRepSweep(const vtkFRepSweep&) = delete;
  void operator=(const vtkFRepSweep&) = delete;

#ifndef __VTK_WRAP__
  // What is wrong with the request for an input of `free` free coordinates ("" when nothing).
  std::string Problems(int free) const;
#endif
};

#endif
