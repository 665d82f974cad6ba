/**
 * @class   vtkFRepProjection
 * @brief   projects an n-D FRep object along some of its coordinates: what it covers over a range
 *
 * vtkFRepProjection takes a vtkFRepObject and produces the vtkFRepObject P = max of F over the
 * projected coordinates' ranges (frep::project, Documentation/projection.md): inside wherever
 * some value of them puts the point inside. Projecting a moving solid F(x, t) along t gives the
 * volume it sweeps. The output is a model like any other (slice it, sample it, polygonise it,
 * ray-cast it, combine it), whose values are F at the best point found, within Tolerance below
 * the maximum (beyond +-Band only the sign is kept: see frep::project::ProjectorOptions).
 *
 * The requests, on MODEL coordinates (0-based, coordinate 3 is x[4], as in vtkFRepObject):
 * - ProjectedCoordinate over ProjectedRange (default: coordinate 3, x4, over [0, 1]; -1: none);
 * - AddProjection(coordinate, lo, hi) for further coordinates (RemoveAllProjections clears
 *   them).
 * The output keeps the input's model coordinates, their names and intervals, and what the input
 * fixed; each projected coordinate is marked fixed at the start of its range (its value is read
 * by nothing), so it leaves the free coordinates: a 4-D object projected along x4 is 3-D.
 *
 * ERRORS (reported together in one vtkErrorMacro when the filter executes; the output is then
 * empty and the filter still returns success, as vtkFRepSlice does): no coordinate to project, a
 * coordinate the model lacks, one the input fixed already, one requested twice, a range that is
 * not finite lo <= hi, a Tolerance <= 0 or a Band <= Tolerance, every free coordinate projected.
 * An empty input gives an empty output quietly.
 *
 * PIPELINE: RequestInformation publishes the output's keys from the input's and the requests
 * (nothing upstream is executed). The projection is built in RequestData, in microseconds: the
 * work is done point by point downstream (a sampler or polygoniser), with UpdateProgress there.
 *
 * @sa vtkFRepSlice vtkFRepObject vtkFRepPolygonizer
 */
#ifndef vtkFRepProjection_h
#define vtkFRepProjection_h

#include "FRepKitFiltersModule.h" // for export macro
#include "vtkFRepObjectAlgorithm.h"

#include <array>  // for std::array
#include <map>    // for std::map
#include <string> // for std::string
#include <vector> // for std::vector

class FREPKITFILTERS_EXPORT vtkFRepProjection : public vtkFRepObjectAlgorithm
{
public:
  static vtkFRepProjection* New();
  vtkTypeMacro(vtkFRepProjection, vtkFRepObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The model coordinate projected (0-based; default 3, x4; -1: none besides AddProjection's).
   */
  vtkSetMacro(ProjectedCoordinate, int);
  vtkGetMacro(ProjectedCoordinate, int);
  ///@}

  ///@{
  /**
   * Its range, lo <= hi (default 0, 1).
   */
  vtkSetVector2Macro(ProjectedRange, double);
  vtkGetVector2Macro(ProjectedRange, double);
  ///@}

  ///@{
  /**
   * Further coordinates projected over their ranges (default none); a coordinate added again
   * gets the new range.
   */
  void AddProjection(int coordinate, double lo, double hi);
  void RemoveAllProjections();
  int GetNumberOfAddedProjections() const { return static_cast<int>(this->Added.size()); }
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
   * Beyond +-Band only the sign is kept (default 0.1, > Tolerance; VTK_DOUBLE_MAX: the value
   * within Tolerance everywhere, slower).
   */
  vtkSetMacro(Band, double);
  vtkGetMacro(Band, double);
  ///@}

protected:
  /**
   * Defaults: x4 over [0, 1], Tolerance 1e-4, Band 0.1; one input and one output port, both
   * vtkFRepObject.
   */
  vtkFRepProjection();
  ~vtkFRepProjection() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int ProjectedCoordinate = 3;
  double ProjectedRange[2] = { 0.0, 1.0 };
  double Tolerance = 1e-4;
  double Band = 0.1;
  std::map<int, std::array<double, 2>> Added;

private:
  vtkFRepProjection(const vtkFRepProjection&) = delete;
  void operator=(const vtkFRepProjection&) = delete;

#ifndef __VTK_WRAP__
  // Every coordinate requested with its range, in coordinate order, and the problems found
  // against the input's coordinates (`fixed`: NaN where free) and its free coordinates.
  std::map<int, std::array<double, 2>> Requests(const std::vector<double>& fixed,
    int freeCount, std::vector<std::string>& problems) const;
#endif
};

#endif
