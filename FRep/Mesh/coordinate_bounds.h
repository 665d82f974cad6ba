// The default interval of every coordinate of an n-D model, from the solid's own bounds: what
// vtkHyperFunSource (and so ParaView and Python's frepkit.load) and FRepStudio give the
// coordinates a user did not range. frepkit's subcommands bound the section they draw instead
// (find_solid_bounds on the tape with x4.. fixed); this is for tools that publish the whole n-D
// object before anything is fixed.
#pragma once

#include "Compiler/model.h"
#include "Eval/interval.h"
#include "Mesh/solid_bounds.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace frep::mesh
{

struct CoordinateBounds
{
  enum class Rule
  {
    None,     ///< nothing could be bounded: every unranged coordinate keeps the fallback
    Whole,    ///< the n-D solid is bounded: every coordinate's interval covers every section
    Sections, ///< x1..x3 cover the sections at the centre and corners of x4..'s intervals
  };
  Rule rule = Rule::None;
  /// One interval per coordinate: the given one, the bounds found (with the search's margin,
  /// rounded outwards by readable()), or the fallback.
  std::vector<Interval> ranges;
  /// Per coordinate: the interval comes from the bounds found.
  std::vector<bool> found;
  /// Why rule 1 did not apply (Rule::Sections, Rule::None), one sentence; empty for Rule::Whole
  /// and when every coordinate has an interval given.
  std::string note;
};

/// Intervals for the coordinates of `model` (a[] = `parameters`): `given[i]`, when set, is
/// coordinate i's own interval and is kept; the others get the solid's bounds by this rule:
///  1. the n-D solid, every coordinate free (find_solid_bounds): when Bounded, each unranged
///     coordinate gets its bounds, which hold for every section;
///  2. else, for n > 3: x4.. are fixed at the centre of their intervals (given, or `fallback`)
///     and at the corners of the given ones (up to 4 of them; the fallback's corners would be
///     extrapolations nobody asked for), and x1..x3 get the union of those sections' bounds (an
///     empty section adds nothing, a corner's unbounded one is left out). That encloses every
///     section of a convex blend of key shapes at the corners (Meta5D over [0, 1]^2) but, in
///     general, only the sections searched. x4.. without an interval keep `fallback`;
///  3. else (the centre's section unbounded, every section empty, or n <= 3 and unbounded) every
///     unranged coordinate keeps `fallback`.
/// `note` says why rule 1 (and 2) did not apply.
/// Throws std::invalid_argument for a bad `fallback` or `options`.
CoordinateBounds find_coordinate_bounds(const Model& model,
  std::span<const double> parameters,
  std::span<const std::optional<Interval>> given,
  Interval fallback,
  const SolidBoundsOptions& options = {});

/// `axis` widened outwards to about three significant digits of its extent, so that it prints
/// short and can be typed back (-7.57205 .. 7.79378, extent 15.4 -> -7.6 .. 7.8).
Interval readable(Interval axis);

} // namespace frep::mesh
