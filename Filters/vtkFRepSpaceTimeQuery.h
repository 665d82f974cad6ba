/**
 * @class   vtkFRepSpaceTimeQuery
 * @brief   asks a moving solid (an n-D FRep object with a time coordinate) a question: its
 * section's volume over time, when a point is inside, when two moving solids first touch, or
 * when the section's topology changes
 *
 * vtkFRepSpaceTimeQuery takes one vtkFRepObject (two for CONTACT: the second on port 1) whose
 * model coordinate TimeCoordinate is time, and answers with a vtkTable (frep::project's queries,
 * Documentation/projection.md, each exact within the tolerance it states):
 *
 * - VOLUME (default): the section's volume (3 coordinates of space) or area (2) at Steps times
 *   evenly over TimeRange, both ends included, from a watertight mesh of it on Samples points
 *   per axis of the object's intervals. Columns "time", "volume" (or "area"), "pieces",
 *   "genus" (0 for areas). A table ParaView plots in a Line Chart View.
 * - PRESENCE: the time intervals in TimeRange during which Point (the coordinates of space, in
 *   model order, the first 3 of them) is inside, each end within TimeTolerance. Columns
 *   "enter", "leave"; no row when it is never inside.
 * - CONTACT: the first time in TimeRange at which the object of port 0 and that of port 1 share
 *   a point of the box of port 0's intervals. One row: "found" (1 or 0), "time", "time_lo" (no
 *   contact starts before it), and the point, one column per model coordinate named as the
 *   object names it (time included); NaN where there is none.
 * - TOPOLOGY: where along TimeRange the section's pieces or genus change: sampled at Steps
 *   times (both ends), each change between two samples located by bisection to TimeTolerance
 *   (frep::project::topology_events; the section meshed as for VOLUME). One row per change, in
 *   time order: "before", "after" (the change lies between these times), "pieces_before",
 *   "pieces_after", "genus_before", "genus_after"; no row when the topology never changes
 *   (between the samples' probes: a change undone within one step is not seen).
 *
 * The questions are asked of the objects' whole models with their parameters: the coordinates
 * of space are the model's other coordinates over the object's intervals. A coordinate the object
 * fixes keeps its value (a degenerate interval for CONTACT, the point's value for PRESENCE);
 * VOLUME and TOPOLOGY need every coordinate of space free (2 or 3 of them).
 *
 * ERRORS (one vtkErrorMacro when the filter executes; the table is then empty and the filter
 * still returns success): no object, a time coordinate the model lacks or that the object fixes,
 * a range that is not finite lo <= hi, TimeTolerance <= 0, Steps < 1 (TOPOLOGY: < 2), Samples < 2, two objects of
 * different dimensions, no second object for CONTACT, and the engine's own refusals.
 *
 * PROGRESS: VOLUME and TOPOLOGY report after each time and stop at CheckAbort (an empty
 * table); CONTACT and PRESENCE are single searches (bounded by the box budget and
 * TimeTolerance).
 *
 * @sa vtkFRepProjection vtkFRepObject
 */
#ifndef vtkFRepSpaceTimeQuery_h
#define vtkFRepSpaceTimeQuery_h

#include "FRepKitFiltersModule.h" // for export macro
#include "vtkTableAlgorithm.h"

#include <string> // for std::string

class vtkFRepObject;
class vtkTable;

class FREPKITFILTERS_EXPORT vtkFRepSpaceTimeQuery : public vtkTableAlgorithm
{
public:
  static vtkFRepSpaceTimeQuery* New();
  vtkTypeMacro(vtkFRepSpaceTimeQuery, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum QueryType
  {
    VOLUME = 0,
    PRESENCE = 1,
    CONTACT = 2,
    TOPOLOGY = 3
  };

  ///@{
  /**
   * The question asked (default VOLUME).
   */
  vtkSetClampMacro(Query, int, VOLUME, TOPOLOGY);
  vtkGetMacro(Query, int);
  void SetQueryToVolume() { this->SetQuery(VOLUME); }
  void SetQueryToPresence() { this->SetQuery(PRESENCE); }
  void SetQueryToContact() { this->SetQuery(CONTACT); }
  void SetQueryToTopology() { this->SetQuery(TOPOLOGY); }
  ///@}

  ///@{
  /**
   * The model coordinate that is time (0-based, as in vtkFRepObject; default 3, x4).
   */
  vtkSetMacro(TimeCoordinate, int);
  vtkGetMacro(TimeCoordinate, int);
  ///@}

  ///@{
  /**
   * The times asked about, lo <= hi (default 0, 1).
   */
  vtkSetVector2Macro(TimeRange, double);
  vtkGetVector2Macro(TimeRange, double);
  ///@}

  ///@{
  /**
   * How exactly a time is located by PRESENCE, CONTACT and TOPOLOGY (default 1e-4, > 0).
   */
  vtkSetMacro(TimeTolerance, double);
  vtkGetMacro(TimeTolerance, double);
  ///@}

  ///@{
  /**
   * VOLUME and TOPOLOGY: the number of times (default 11, >= 1; TOPOLOGY >= 2) and the samples
   * per axis of the section's mesh (default 48, >= 2).
   */
  vtkSetMacro(Steps, int);
  vtkGetMacro(Steps, int);
  vtkSetMacro(Samples, int);
  vtkGetMacro(Samples, int);
  ///@}

  ///@{
  /**
   * PRESENCE: the point's coordinates of space, in model order without time (default 0, 0, 0;
   * a model with fewer uses the first ones; one with more takes the others from the object's
   * fixed values, else the middle of their intervals).
   */
  vtkSetVector3Macro(Point, double);
  vtkGetVector3Macro(Point, double);
  ///@}

  /**
   * CONTACT's second moving solid (port 1), as a connection.
   */
  void SetSecondObjectConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(1, output);
  }

protected:
  /**
   * Defaults: VOLUME, time x4 over [0, 1], TimeTolerance 1e-4, 11 steps of 48 samples, the
   * point (0, 0, 0); port 0 a vtkFRepObject, port 1 an optional one; a vtkTable out.
   */
  vtkFRepSpaceTimeQuery();
  ~vtkFRepSpaceTimeQuery() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Query = VOLUME;
  int TimeCoordinate = 3;
  double TimeRange[2] = { 0.0, 1.0 };
  double TimeTolerance = 1e-4;
  int Steps = 11;
  int Samples = 48;
  double Point[3] = { 0.0, 0.0, 0.0 };

private:
  vtkFRepSpaceTimeQuery(const vtkFRepSpaceTimeQuery&) = delete;
  void operator=(const vtkFRepSpaceTimeQuery&) = delete;

#ifndef __VTK_WRAP__
  // Each question, filling `table`; "" or why there is no answer.
  std::string Volume(vtkFRepObject* object, vtkTable* table);
  std::string Presence(vtkFRepObject* object, vtkTable* table);
  std::string Contact(vtkFRepObject* a, vtkFRepObject* b, vtkTable* table);
  std::string Topology(vtkFRepObject* object, vtkTable* table);
  // "" when every coordinate of space is free (VOLUME and TOPOLOGY mesh the whole section).
  std::string SpaceIsFree(vtkFRepObject* object, const char* query);
#endif
};

#endif
