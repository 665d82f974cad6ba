// A path through the dynamic coordinates, ready to follow: the curve through the control points
// (polyline or centripetal Catmull-Rom), sampled densely once so that positions can be looked up
// by arc length (constant speed) or by key times. Named SampledPath so as not to collide with
// the spec's `Path` (the description it is built from).
#pragma once

#include "Mapping/mapping_plan.h"
#include "Mapping/mapping_spec.h"

#include "Project/path_pieces.h"

#include <cstddef>
#include <vector>

namespace frep::mapping
{

class SampledPath
{
public:
  SampledPath() = default;

  struct Result;
  /// Checks and samples `path` (each segment at `steps_per_segment` sub-steps). Errors name
  /// their place relative to the path object ("points", "points[2]", "key_times"), so that the
  /// caller can prefix where the path lives ("animation.path."). Rules: at least 2 points, each
  /// with one finite value per path coordinate (when coordinates are named; else all of one
  /// size), not all the same point; with Timing::Keys one strictly increasing key time per
  /// control point, plus one for the return to the first point when closed.
  static Result make(const Path& path, int steps_per_segment = 64);

  std::size_t dimension() const { return dimension_; }
  std::size_t segment_count() const { return segments_; }
  /// Arc length in model units (of the sampled curve).
  double length() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }
  const Path& spec() const { return spec_; }

  /// The point at arc-length fraction s (clamped to [0, 1]): s = 0 is the first control point,
  /// s = 1 the last one (closed: the first one again), and equal steps of s are equal steps
  /// along the curve.
  std::vector<double> point_at(double s) const;

  /// Timing::Keys: the arc-length fraction reached at time t (seconds, clamped to the key
  /// times): control point k at key_times[k], constant speed within each segment. With
  /// Timing::ArcLength there are no key times and the answer is t itself clamped to [0, 1].
  double fraction_at_time(double t) const;

  /// n >= 2 points evenly spaced along the curve, both ends included (for drawing).
  std::vector<std::vector<double>> polyline(int n) const;

  /// The curve as polynomial pieces (FRep/Project/path_pieces.h), one per segment over the
  /// segment's own parameter (not arc length): the same points, for what depends only on where
  /// the path goes (the ghost: the union of every shape on it). Every segment is a cubic (the
  /// pyramid's three linear stages; a polyline's linear), fitted through 4 of its points.
  std::vector<project::PathPiece> pieces() const;

private:
  std::vector<double> control(std::ptrdiff_t k) const; ///< wraps when closed
  /// The curve on segment j (from control point j to the next) at local parameter t in [0, 1].
  std::vector<double> segment_point(std::size_t j, double t) const;

  Path spec_;
  std::size_t dimension_ = 0;
  std::size_t segments_ = 0;
  int steps_ = 64;
  std::vector<double> cumulative_;    ///< arc length at sub-step k (segments_ * steps_ + 1)
  std::vector<double> segment_start_; ///< arc length where segment j begins (segments_ + 1)
};

struct SampledPath::Result
{
  SampledPath path;
  std::vector<PlanError> errors; ///< empty = success
  bool ok() const { return errors.empty(); }
};

} // namespace frep::mapping
