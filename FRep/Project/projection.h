// A model projected along some of its coordinates (projector.h says what P is and how exact):
// an object like any other, loaded through load_model from a one-line HyperFun wrapper that
// calls the projection as a user function with its point, interval and gradient forms, so every
// tool (slice, sample, mesh, ray cast, the mapping, set operations) takes it as it is.
#pragma once

#include "Compiler/load_model.h"
#include "Project/projector.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace frep::project
{

/// A coordinate and a range of it: one eliminated over [lo, hi], a query's time.
struct CoordinateRange
{
  int coordinate = 0; ///< 1-based: x[coordinate]
  double lo = 0.0;
  double hi = 0.0;
};

struct ProjectionOptions : ProjectorOptions
{
  std::vector<double> parameters; ///< the source's a[] (missing: 0)
  /// The result keeps the source's coordinates (x_dim the same; the eliminated ones are read
  /// by nothing), so a tool's axes and sliders keep their numbering. Off: the result's
  /// coordinates are the kept ones, in increasing order (x_dim - k of them).
  bool keep_coordinates = false;
};

/// Why the request is refused ("" when it is not): no coordinate, one the model lacks or given
/// twice, a range that is not finite lo <= hi, a tolerance <= 0, no boxes, every coordinate.
std::string check_projection(const Model& model, const std::vector<CoordinateRange>& axes,
  const ProjectionOptions& options);

/// "x4=0:1" or "x4=0:1,x5=-1:1" (also "4=0:1"): the coordinates and their ranges, or the
/// reason in `error` (empty result).
std::vector<CoordinateRange> parse_eliminated(std::string_view text, std::string& error);

/// "x4=0:1,x5=-1:1".
std::string eliminated_text(const std::vector<CoordinateRange>& axes);

/// The projection as a user function `name(x)` over the kept inputs (an array of
/// tape.input_count - ranges.size() items) of a tape whose last inputs are eliminated: point,
/// interval and gradient forms, safe from any thread (one Projector per thread, pooled). A
/// search cut short by max_boxes still returns its best value.
UserFunction projection_function(const std::string& name, std::shared_ptr<const Tape> tape,
  std::vector<Interval> ranges, const ProjectorOptions& options = {});

/// The model projected: its object is named `<source>_projection` (`projection` for a composed
/// model), with s[1] and a[1] (the source's a[] are in the options). Errors (check_projection's)
/// come back as one diagnostic without a position.
LoadedModel project(std::shared_ptr<const Model> model, const std::vector<CoordinateRange>& axes,
  const ProjectionOptions& options = {});

} // namespace frep::project
