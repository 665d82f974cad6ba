// How a metamorphosis moves from one key to the next (issue 29, item 3: weight curves over the
// parameter). Between two neighbouring nodes of a lattice axis, at i/(n-1) and (i+1)/(n-1), the
// parameter's place u in [0, 1] is remapped by a curve before the scheme weighs the keys:
//
//   linear      u (the paper: the blend moves at a constant rate)
//   ease        u^2 (3 - 2u): starts and stops gently at every key (smoothstep)
//   ease-in     u^2: leaves each key slowly, arrives fast
//   ease-out    u (2 - u): leaves fast, arrives slowly
//   hold:H      min(max((u - H/2) / (1 - H), 0), 1), 0 <= H < 1: each key is shown alone for H/2
//               of the segment on either side of its node, then a linear blend
//
// The timed parameter is (i + curve(u)) / (n - 1). Every curve keeps 0 -> 0 and 1 -> 1, so the
// nodes (and the lattice's corners, exactly) are unchanged; only the speed between them is.
// Which key counts for how much, globally or at each point of space, is the keys' own weights
// (MorphSpec::key_weights), not a timing.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace frep::morph
{

enum class TimingCurve
{
  Linear,
  Ease,
  EaseIn,
  EaseOut,
  Hold
};

struct Timing
{
  TimingCurve curve = TimingCurve::Linear;
  double hold = 0.0; ///< Hold: the fraction of a segment each key is held, in [0, 1)
};

/// "linear", "ease", "ease-in", "ease-out", "hold:H" (0 <= H < 1, "hold" alone is hold:0.5);
/// nullopt for anything else.
std::optional<Timing> timing_from_name(std::string_view name);
/// The name timing_from_name reads back ("hold:0.3").
std::string timing_name(const Timing& timing);

/// The curve at u in [0, 1].
double timing_curve(const Timing& timing, double u);

/// The timed parameter of an axis of `nodes` nodes (>= 2) at t: t itself outside (0, 1), for
/// NaN and for Linear; else (i + curve(u)) / (nodes - 1) with t (nodes - 1) = i + u, i at most
/// nodes - 2. What the written text computes (weight_text.h), operation for operation.
double timed_parameter(const Timing& timing, int nodes, double t);

} // namespace frep::morph
