/**
 * @class   vtkFRepSlice
 * @brief   fixes coordinates of an n-D FRep object: a lower-dimensional cross-section
 *
 * vtkFRepSlice takes a vtkFRepObject and produces a vtkFRepObject in which some of the input's
 * free coordinates are fixed to values, and/or the remaining free coordinates are put in a
 * chosen order. The output shares the input's compiled model (ShallowCopy); its GetTape() is
 * the model specialised to the fixed values, a smaller tape over the remaining coordinates
 * (see frep::Model::specialise). Nothing is evaluated here: slicing costs microseconds.
 *
 * Coordinates are the MODEL's coordinates, 0-based (coordinate 3 is x[4]), as in
 * vtkFRepObject, whatever the input has fixed already. The requests:
 * - SetFixedValue(coordinate, value) fixes a coordinate; a NaN value releases it, so that one
 *   value per coordinate (NaN = free) can drive the filter, e.g. one slider per coordinate.
 * - SetFixedValueByName(name, value) does the same by coordinate name (as the input names its
 *   coordinates, default "x1".."xn"; exact, case-sensitive). Names are resolved when the
 *   filter executes.
 * - ReleaseCoordinate(), ReleaseCoordinateByName(), ReleaseAllCoordinates() undo them.
 * - FreeCoordinateOrder, e.g. "x3,x1,x2": the names of the coordinates that stay free, in the
 *   order they become the output's axes (and its tape's inputs). Empty (the default): the
 *   remaining free coordinates keep the input's order.
 *
 * A fixed value outside the coordinate's interval is allowed without a warning: the interval
 * is only the default sampling box of that coordinate, the model is defined everywhere (a
 * slider may well go beyond it). Non-finite values (infinities) are refused.
 *
 * ERRORS: the requests are checked when the filter executes, against its input. A coordinate
 * the model does not have, a name that names no coordinate (or several), a coordinate already
 * fixed by the input (upstream slices are not undone here), a coordinate fixed twice to
 * different values (by index and by name), an infinite value, an order that names a fixed or
 * unknown coordinate, names one twice or leaves out a coordinate that is not fixed: all of them
 * are reported together in one vtkErrorMacro, and the output is empty (an initialised
 * vtkFRepObject without a model). The filter still returns success, so VTK adds no second,
 * position-less "returned failure" error, and downstream FRep filters pass the empty object on
 * silently.
 *
 * An empty input (for example a vtkHyperFunSource with a parse error, which has reported it
 * already) gives an empty output without any further message (vtkDebugMacro only).
 *
 * PIPELINE: RequestInformation resolves the requests against the input's vtkFRepInformation
 * keys and publishes the output's (the fixed coordinates leave the free ones, the order is
 * FreeCoordinateOrder's), without executing anything upstream; requests that do not resolve
 * publish no object there and are reported by RequestData. Every rank of a parallel run builds
 * the whole object (CAN_HANDLE_PIECE_REQUEST, see vtkFRepObjectAlgorithm): an FRep object cannot
 * be split into pieces.
 *
 * @sa vtkFRepObject vtkFRepObjectAlgorithm vtkFRepInformation vtkHyperFunSource vtkFRepSampler
 */
#ifndef vtkFRepSlice_h
#define vtkFRepSlice_h

#include "FRepKitFiltersModule.h" // for export macro
#include "vtkFRepInformation.h" // for vtkFRepInformation::Metadata
#include "vtkFRepObjectAlgorithm.h"

#include <map>    // for std::map
#include <string> // for std::string
#include <vector> // for std::vector

class vtkFRepObject;

class FREPKITFILTERS_EXPORT vtkFRepSlice : public vtkFRepObjectAlgorithm
{
public:
  static vtkFRepSlice* New();
  vtkTypeMacro(vtkFRepSlice, vtkFRepObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Fixes model coordinate `coordinate` (0-based) to `value`; NaN releases it (default: no
   * coordinate fixed). GetFixedValue is NaN for a coordinate this filter does not fix by index.
   * Checked when the filter executes (see ERRORS in the class description).
   */
  void SetFixedValue(int coordinate, double value);
  double GetFixedValue(int coordinate) const;
  bool IsCoordinateFixed(int coordinate) const;
  void ReleaseCoordinate(int coordinate);
  ///@}

  ///@{
  /**
   * The same by coordinate name (default: none). A null or empty name is kept as a request and
   * reported when the filter executes (no coordinate has that name). NaN releases.
   */
  void SetFixedValueByName(const char* name, double value);
  double GetFixedValueByName(const char* name) const;
  void ReleaseCoordinateByName(const char* name);
  ///@}

  /**
   * Releases every coordinate fixed by index or by name.
   */
  void ReleaseAllCoordinates();

  /**
   * Number of fixing requests, by index plus by name.
   */
  int GetNumberOfFixedValues() const;

  ///@{
  /**
   * Names of the coordinates that stay free, comma-separated, in output axis order (white space
   * around the names is ignored); default none = the remaining free coordinates in the input's
   * order.
   */
  vtkSetStringMacro(FreeCoordinateOrder);
  vtkGetStringMacro(FreeCoordinateOrder);
  ///@}

protected:
  /**
   * Defaults: nothing fixed, no FreeCoordinateOrder; one input port and one output port, both
   * vtkFRepObject.
   */
  vtkFRepSlice();
  ~vtkFRepSlice() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::map<int, double> FixedValues;               // by model coordinate
  std::map<std::string, double> FixedValuesByName; // by name, resolved on execution
  char* FreeCoordinateOrder = nullptr;

private:
  vtkFRepSlice(const vtkFRepSlice&) = delete;
  void operator=(const vtkFRepSlice&) = delete;

#ifndef __VTK_WRAP__
  // Resolves the requests against the input's metadata: the coordinates to fix and the new
  // order of the free ones (empty = unchanged). Returns the problems found (empty = valid).
  std::vector<std::string> Resolve(const vtkFRepInformation::Metadata& input,
    std::map<int, double>& fixed,
    std::vector<int>& order) const;
  // The output's metadata: `input` with `fixed` and `order` (from Resolve) applied.
  static vtkFRepInformation::Metadata Apply(const vtkFRepInformation::Metadata& input,
    const std::map<int, double>& fixed,
    const std::vector<int>& order);
#endif
};

#endif
