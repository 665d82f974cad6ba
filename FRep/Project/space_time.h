// Questions asked of space-time (issue 28, item 3): models whose coordinate `time` is time, and
// the other coordinates space. Each answer is exact within the tolerances it states and says so
// when there is none.
//
//  - first_contact: the smallest t at which two moving solids A and B share a point of a box
//    (A & B >= 0), and that point. Best-first branch and bound over (t, space), the box with
//    the earliest t first: every box before the answer is proven empty by its enclosure, so no
//    contact starts earlier than `time_lo`, and at `time` the point `where` is inside both
//    (within value_tolerance: a box thinner in t than the tolerance is searched for its best
//    point by the projector).
//  - presence: the intervals of t during which a point is inside (F >= 0), each end located to
//    `time_tolerance` (subdivision of t with the region walker's enclosures).
//  - section_measures: the volume (3 free coordinates) or area (2) of the section at each of a
//    table of times, from a watertight mesh (contour) of it on a grid, and its pieces (genus);
//  - topology_events: where along time those pieces or the genus change, by bisection.
#pragma once

#include "Compiler/model.h"
#include "Eval/interval.h"
#include "Eval/run_control.h"
#include "Mesh/mesh_topology.h"
#include "Project/projection.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace frep::project
{

/// Tolerances of the queries. The run control (RunControl, the one settings struct of long
/// calls): topology_events reports progress after each sample and stops there when progress
/// returns false or `cancel` asks (not within a change's bisection); the other queries are
/// single searches and ignore it.
struct SpaceTimeOptions : RunControl
{
  double time_tolerance = 1e-4; ///< (> 0) how exactly a time is located
  /// (>= 0) first contact: a box of the smallest size whose enclosure still reaches 0 counts as a
  /// contact when F at its centre is at least -value_tolerance (the solids touch within it).
  double value_tolerance = 1e-6;
  std::size_t max_boxes = 2'000'000; ///< first contact: boxes enclosed before giving up
  std::vector<double> parameters;    ///< the models' a[] (missing: 0)
};

struct Contact
{
  std::string error;        ///< why there is no answer (bad request, box budget exhausted)
  bool found = false;       ///< the solids touch within the time range and box
  double time = 0.0;        ///< a time at which `where` is inside both
  double time_lo = 0.0;     ///< no contact before it: time - time_lo <= time_tolerance
  std::vector<double> where; ///< all coordinates (time included) of a common point
  std::size_t boxes = 0;     ///< boxes enclosed
  bool ok() const { return error.empty(); }
};

/// The first time in `time`'s range at which A and B (models of the same x_dim, their coordinate
/// `time.coordinate` is time) share a point of `space` (one interval per other coordinate, in
/// order).
Contact first_contact(std::shared_ptr<const Model> a, std::shared_ptr<const Model> b,
  const CoordinateRange& time, const std::vector<Interval>& space,
  const SpaceTimeOptions& options = {});

struct Presence
{
  std::string error;
  std::vector<Interval> inside; ///< disjoint, increasing; each end within time_tolerance
  bool ok() const { return error.empty(); }
};

/// When the point `at` (all coordinates; its time coordinate's value is ignored) is inside.
Presence presence(const Model& model, const CoordinateRange& time, std::vector<double> at,
  const SpaceTimeOptions& options = {});

struct SectionMeasure
{
  double time = 0.0;
  double measure = 0.0;       ///< volume (3-D section) or area (2-D)
  std::size_t components = 0; ///< connected pieces of its surface (contour loops in 2-D)
  long long genus = 0;        ///< 3-D: the surface's genus summed over its pieces (0 in 2-D)
};

struct SectionMeasures
{
  std::string error;
  int dimension = 0; ///< 3: volumes, 2: areas
  std::vector<SectionMeasure> table;
  bool ok() const { return error.empty(); }
};

/// The section's volume or area at `steps` times evenly over the range (both ends included),
/// the section meshed on `samples` points per axis of `space` (its 2 or 3 coordinates other
/// than time; further coordinates are not allowed). The mesh's error is that of marching cubes
/// (squares) at that grid.
SectionMeasures section_measures(const Model& model, const CoordinateRange& time,
  const std::vector<Interval>& space, int steps, int samples, const SpaceTimeOptions& options = {});

/// A change of the section's topology between two times `before` < `after`, at most the
/// resolution apart.
struct TopologyEvent
{
  double before = 0.0, after = 0.0;
  std::size_t components_before = 0, components_after = 0;
  long long genus_before = 0, genus_after = 0;
};

struct TopologySample
{
  double time = 0.0;
  std::size_t components = 0;
  long long genus = 0;
};

struct TopologyTrack
{
  std::string error;
  std::vector<TopologySample> samples; ///< at `steps` times, both ends included
  std::vector<TopologyEvent> events;   ///< in time order
  bool cancelled = false;              ///< stopped by the run control: nothing is reported
  bool ok() const { return error.empty() && !cancelled; }
};

/// Where the section's topology (pieces, and genus for 3-D sections) changes along time (issue
/// 29, item 5: a map of the topology): sampled at `steps` times, each change between two samples
/// located by bisection to `resolution`. The topology is the section's mesh's (contour's) on
/// `samples` points per axis of `space`, so a feature finer than the grid is not seen; a change
/// and its undoing between two samples is missed.
TopologyTrack topology_events(const Model& model, const CoordinateRange& time,
  const std::vector<Interval>& space, int steps, int samples, double resolution,
  const SpaceTimeOptions& options = {});

/// The topology of a family of shapes at a parameter (a mesh of the shape there, analysed).
using TopologyAt = std::function<mesh::ShapeTopology(double)>;

/// The changes of a family's topology from parameter a to b > a (whose shapes `at_a`, `at_b`
/// are known), each located by bisection to `resolution`, nearest to a first: a shape met in
/// between that is neither end's is a change of its own. What topology_events does between two
/// of its samples, and the mapping's topology map between two cells or two frames. A change and
/// its undoing between two of the probes is not seen; an error of shape_at's is its own to keep
/// (shape_at is called at most 2 + log2((b - a) / resolution) times per change).
std::vector<TopologyEvent> locate_topology_changes(double a, const mesh::ShapeTopology& at_a,
  double b, const mesh::ShapeTopology& at_b, double resolution, const TopologyAt& shape_at);

} // namespace frep::project
