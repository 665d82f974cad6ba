#include "Raycast/solid_bounds.h"

#include "Eval/interval_evaluator.h"

#include <algorithm>

namespace frep::raycast::detail
{
namespace
{

struct Walk
{
  IntervalEvaluator interval;
  SolidBounds result;
  int depth;

  void include(const std::array<Interval, 3>& cell)
  {
    if (result.empty)
    {
      result.box = cell;
      result.empty = false;
      return;
    }
    for (int k = 0; k < 3; ++k)
    {
      result.box[k].lo = std::min(result.box[k].lo, cell[k].lo);
      result.box[k].hi = std::max(result.box[k].hi, cell[k].hi);
    }
  }

  // True when the cell is already inside the bounds found: nothing to learn from it.
  bool covered(const std::array<Interval, 3>& cell) const
  {
    if (result.empty)
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (cell[k].lo < result.box[k].lo || cell[k].hi > result.box[k].hi)
      {
        return false;
      }
    }
    return true;
  }

  void visit(const std::array<Interval, 3>& cell, int level)
  {
    if (covered(cell))
    {
      return;
    }
    ++result.interval_evaluations;
    const IntervalResult r = interval.evaluate(cell);
    // Points that raise a run-time error are outside (NaN is not >= 0): F < 0 wherever no
    // error occurs is enough to drop the cell.
    if (r.value.hi < 0.0)
    {
      return;
    }
    if (level == depth || (r.value.lo >= 0.0 && !r.may_fail))
    {
      include(cell);
      return;
    }
    for (int c = 0; c < 8; ++c)
    {
      std::array<Interval, 3> child;
      for (int k = 0; k < 3; ++k)
      {
        const double mid = 0.5 * (cell[k].lo + cell[k].hi);
        child[k] = (c >> k) & 1 ? Interval{ mid, cell[k].hi } : Interval{ cell[k].lo, mid };
      }
      visit(child, level + 1);
    }
  }
};

} // namespace

SolidBounds solid_bounds(const std::shared_ptr<const Tape>& tape,
  const std::array<Interval, 3>& box,
  int depth)
{
  Walk walk{ IntervalEvaluator(tape), {}, depth };
  walk.visit(box, 0);
  return walk.result;
}

} // namespace frep::raycast::detail
