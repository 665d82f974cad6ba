// What the projector's and first contact's searches share about a box: its centre on an axis and
// the axis to split.
#pragma once

#include "Eval/interval.h"

#include <span>

namespace frep::project::detail
{

/// The middle of an interval; a degenerate interval's value itself, sign of zero included (-0 + 0
/// would be +0, and atan2 tells them apart).
inline double centre(const Interval& i)
{
  return i.lo == i.hi ? i.lo : i.lo + 0.5 * (i.hi - i.lo);
}

/// The axis of `box` widest relative to the same axis of `whole` (the search's ranges), or -1 when
/// every axis is at most `smallest` of its range (or its range is a point).
inline int widest_axis(std::span<const Interval> box, std::span<const Interval> whole,
  double smallest)
{
  int axis = -1;
  double widest = smallest;
  for (std::size_t i = 0; i < box.size() && i < whole.size(); ++i)
  {
    const double range = whole[i].hi - whole[i].lo;
    if (range > 0.0 && (box[i].hi - box[i].lo) / range > widest)
    {
      widest = (box[i].hi - box[i].lo) / range;
      axis = static_cast<int>(i);
    }
  }
  return axis;
}

} // namespace frep::project::detail
