// A profile moved along a path, written as one HyperFun object of x[4] (issue 28, item 2): at
// x4 = t in [0, 1] it is the profile (any 3-D HyperFun object: a model, a mesh or a volume through
// --shape) placed at the path's point c(t), either as it stands (Orientation::Fixed) or turned
// so that its own z axis follows the path's tangent (Orientation::Tangent). Projected along x4
// (projection.h) it is the volume the profile sweeps. The profile is called by name: load the
// written text with the profile's file as a library (LoadOptions::libraries).
//
// The path: points in space, joined by straight segments (Curve::Polyline) or by a uniform
// Catmull-Rom spline through them (the end segments' outer neighbours mirrored, or the points
// wrapped when closed); t = i / segments at point i. Tangent frames: z' = the tangent normalised,
// x' = up x z' normalised, y' = z' x x', with up = (0, 0, 1), or (0, 1, 0) when some tangent of
// the path is within 5 degrees of z (decided once for the path, so the frame never flips).
#pragma once

#include "Language/diagnostic.h"
#include "Project/path_pieces.h"

#include <array>
#include <string>
#include <vector>

namespace frep::project
{

struct SweepPath
{
  enum class Curve
  {
    Polyline,
    CatmullRom
  };
  enum class Orientation
  {
    Fixed,
    Tangent
  };
  std::vector<std::array<double, 3>> points; ///< at least 2 (3 when closed), finite
  Curve curve = Curve::Polyline;
  bool closed = false;
  Orientation orientation = Orientation::Fixed;
};

struct SweepText
{
  std::string text; ///< empty when diagnostics say why
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return diagnostics.empty(); }
};

/// `name(x[4], a[A])` calling `profile(y, a)`, A the profile's a[] size (>= 1). Refused: a
/// profile name or object name that is not an identifier (or is the same), fewer points than
/// the path needs, a point that is not finite, two consecutive points alike (no tangent).
SweepText write_sweep(const std::string& name, const std::string& profile, int profile_a_dim,
  const SweepPath& path);

/// A model driven along a path through some of its own coordinates, as HyperFun text that the
/// original reads (path_family.h makes the same model from a compiled one): `name(x[n + 1],
/// a[A])` is `source(y, a)` with y's `path_coordinates` (1-based, distinct) at the path's point
/// c(t), t = x[n + 1] in [0, 1], and its other coordinates x[1..n] as they are (the path ones
/// of x are read by nothing). Projected along x[n + 1] it is the union of every shape the path
/// passes: the animation's ghost. Refused: names that are not identifiers (or alike), a
/// coordinate outside 1..source_x_dim or given twice, none, pieces that do not fit.
SweepText write_path_family(const std::string& name, const std::string& source, int source_x_dim,
  int source_a_dim, const std::vector<int>& path_coordinates, const std::vector<PathPiece>& pieces);

/// Why `path` cannot be swept along ("" when it can): fewer points than it needs, a point that is
/// not finite, two consecutive points alike (no direction).
std::string sweep_path_error(const SweepPath& path);

/// The statements that set mp[1..3], the profile's point for x[1..3] at t = x[4] (the profile
/// moved back by the path's point, and turned back by its frame with Orientation::Tangent):
/// the body of write_sweep and of sweep_model's coordinates. `path` must pass sweep_path_error.
std::string moved_point_text(const SweepPath& path);

/// "polyline" / "catmull-rom", "fixed" / "tangent" (nullopt-like: false for another name).
bool sweep_curve_from_name(const std::string& text, SweepPath::Curve& curve);
bool sweep_orientation_from_name(const std::string& text, SweepPath::Orientation& orientation);

} // namespace frep::project
