#include "Mesh/solid_bounds.h"

#include "Eval/region_walker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace frep::mesh
{
namespace
{

// One pass: cells are halved along axis (level % n) until each axis has `depth` levels.
struct Walk
{
  RegionWalker walker; // a shorter tape where a cell decides min/max (the same enclosures)
  std::size_t n;
  int max_level;
  std::size_t budget; // 0: none
  bool found = false;
  bool gave_up = false;
  std::vector<Interval> box;
  std::size_t evaluations = 0;

  void include(const std::vector<Interval>& cell)
  {
    if (!found)
    {
      box = cell;
      found = true;
      return;
    }
    for (std::size_t k = 0; k < n; ++k)
    {
      box[k].lo = std::min(box[k].lo, cell[k].lo);
      box[k].hi = std::max(box[k].hi, cell[k].hi);
    }
  }

  // True when the cell is already inside the bounds found: nothing to learn from it.
  bool covered(const std::vector<Interval>& cell) const
  {
    if (!found)
    {
      return false;
    }
    for (std::size_t k = 0; k < n; ++k)
    {
      if (cell[k].lo < box[k].lo || cell[k].hi > box[k].hi)
      {
        return false;
      }
    }
    return true;
  }

  void visit(std::vector<Interval>& cell, int level, const RegionWalker::Region& region)
  {
    if (gave_up || covered(cell))
    {
      return;
    }
    if (budget > 0 && evaluations >= budget)
    {
      gave_up = true;
      return;
    }
    ++evaluations;
    const IntervalResult r = walker.enclose(region, cell);
    // Points that raise a run-time error are outside (NaN is not >= 0): F < 0 wherever no
    // error occurs is enough to drop the cell. A NaN bound compares false: kept, split.
    if (r.value.hi < 0.0)
    {
      return;
    }
    if (level == max_level || (r.value.lo >= 0.0 && !r.may_fail))
    {
      include(cell);
      return;
    }
    const RegionWalker::Region inner = walker.descend(region);
    const std::size_t k = static_cast<std::size_t>(level) % n;
    const Interval whole = cell[k];
    const double mid = 0.5 * (whole.lo + whole.hi);
    cell[k] = { whole.lo, mid };
    visit(cell, level + 1, inner);
    cell[k] = { mid, whole.hi };
    visit(cell, level + 1, inner);
    cell[k] = whole;
  }
};

bool reaches_edge(const std::vector<Interval>& found, double search)
{
  return std::any_of(found.begin(), found.end(),
    [search](const Interval& i) { return i.lo <= -search || i.hi >= search; });
}

double volume_ratio(const std::vector<Interval>& inner, const std::vector<Interval>& outer)
{
  double ratio = 1.0;
  for (std::size_t k = 0; k < inner.size(); ++k)
  {
    ratio *= (inner[k].hi - inner[k].lo) / (outer[k].hi - outer[k].lo);
  }
  return ratio;
}

} // namespace

SolidBounds solid_bounds_in(const std::shared_ptr<const Tape>& tape,
  std::span<const Interval> box,
  int depth,
  std::size_t budget)
{
  if (!tape || tape->input_count == 0 || box.size() != tape->input_count || depth < 0 ||
      depth > 30)
  {
    throw std::invalid_argument(
      "solid bounds: the box needs one interval per tape input and a depth of 0..30");
  }
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = box.size();
  Walk walk{ RegionWalker(tape), n, depth * static_cast<int>(n), budget, false, false, {}, 0 };
  std::vector<Interval> cell(box.begin(), box.end());
  walk.visit(cell, 0, walk.walker.root());
  SolidBounds result;
  result.status = walk.gave_up ? SolidBounds::Status::Unbounded
                : walk.found   ? SolidBounds::Status::Bounded
                               : SolidBounds::Status::Empty;
  result.box = std::move(walk.box);
  result.interval_evaluations = walk.evaluations;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

SolidBounds find_solid_bounds(const std::shared_ptr<const Tape>& tape,
  const SolidBoundsOptions& options)
{
  if (!(options.search > 0.0) || !std::isfinite(options.search) || !(options.margin >= 0.0) ||
      options.depth < 1 || options.max_passes < 1)
  {
    throw std::invalid_argument("solid bounds: bad search options");
  }
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = tape ? tape->input_count : 0;
  std::vector<Interval> search(n, Interval{ -options.search, options.search });
  SolidBounds result = solid_bounds_in(tape, search, options.depth, options.budget);
  std::size_t evaluations = result.interval_evaluations;
  if (result.bounded() && reaches_edge(result.box, options.search))
  {
    result.status = SolidBounds::Status::Unbounded;
  }
  // Each pass searches the box the last one found (it encloses the solid) at a finer step.
  for (int pass = 1; pass < options.max_passes && result.bounded(); ++pass)
  {
    SolidBounds next = solid_bounds_in(tape, result.box, options.depth, options.budget);
    evaluations += next.interval_evaluations;
    if (!next.bounded())
    {
      break; // cannot happen for a sound enclosure; keep the looser box
    }
    const double shrink = volume_ratio(next.box, result.box);
    result.box = std::move(next.box);
    if (shrink > 0.95)
    {
      break;
    }
  }
  if (result.bounded())
  {
    for (Interval& i : result.box)
    {
      const double pad = options.margin * (i.hi - i.lo);
      i = { i.lo - pad, i.hi + pad };
    }
  }
  result.interval_evaluations = evaluations;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace frep::mesh
