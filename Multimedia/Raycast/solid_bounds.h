// Internal: a box around the solid tighter than the model box, from the interval evaluator: the
// model box is split as an octree; cells where F < 0 for sure are dropped, and the bounding box
// of the rest encloses every point where F >= 0 (or may fail). Rays clip to it, and the shadow
// map frames it, so the work follows the shape's size, not the box's.
#pragma once

#include "Compiler/tape.h"
#include "Eval/interval.h"

#include <array>
#include <cstddef>
#include <memory>

namespace frep::raycast::detail
{

struct SolidBounds
{
  std::array<Interval, 3> box{}; ///< valid when !empty
  bool empty = true;             ///< F < 0 everywhere in the model box
  std::size_t interval_evaluations = 0;
};

/// The bounds of {F >= 0} in `box` to within 1 / 2^depth of the box on each axis.
SolidBounds solid_bounds(const std::shared_ptr<const Tape>& tape,
  const std::array<Interval, 3>& box,
  int depth = 5);

} // namespace frep::raycast::detail
