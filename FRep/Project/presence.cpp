#include "Project/detail/space_time_checks.h"
#include "Project/space_time.h"

#include "Eval/region_walker.h"

#include <cmath>

namespace frep::project
{
namespace
{

// Subdivision of t, depth first with the region walker: a piece whose enclosure is >= 0 is
// inside, one whose enclosure is < 0 outside; an undecided piece no longer than the tolerance
// takes its centre's side.
struct PresenceWalk
{
  RegionWalker walker;
  double tolerance;
  std::vector<Interval> inside;

  void add(const Interval& piece)
  {
    if (!inside.empty() && inside.back().hi == piece.lo)
      inside.back().hi = piece.hi;
    else
      inside.push_back(piece);
  }

  void visit(const RegionWalker::Region& region, const Interval& t)
  {
    const Interval box[1] = { t };
    const IntervalResult r = walker.enclose(region, box);
    if (r.value.lo >= 0.0 && !r.may_fail)
      return add(t);
    if (r.value.hi < 0.0)
      return;
    const double middle = t.lo + 0.5 * (t.hi - t.lo);
    const RegionWalker::Region inner = walker.descend(region);
    if (t.hi - t.lo <= tolerance || middle <= t.lo || middle >= t.hi)
    {
      double value = 0.0;
      const double* column[1] = { &middle };
      walker.evaluate(inner, column, 1, &value);
      if (value >= 0.0) // NaN (a failing point) is outside
        add(t);
      return;
    }
    visit(inner, Interval{ t.lo, middle });
    visit(inner, Interval{ middle, t.hi });
  }
};

} // namespace

Presence presence(const Model& model, const CoordinateRange& time, std::vector<double> at,
  const SpaceTimeOptions& options)
{
  Presence result;
  result.error = detail::check_time(model, time);
  if (result.error.empty() && static_cast<int>(at.size()) != model.x_dim())
    result.error = "the point has " + std::to_string(at.size()) + " coordinates, " +
                   model.name() + " has x[" + std::to_string(model.x_dim()) + "]";
  for (std::size_t i = 0; result.error.empty() && i < at.size(); ++i)
    if (!std::isfinite(at[i]) && static_cast<int>(i) != time.coordinate - 1) // time's is unread
      result.error = "the point's coordinates must be finite";
  if (result.error.empty())
    result.error = detail::check_tolerances(options);
  if (!result.error.empty())
    return result;
  Specialisation s;
  s.parameters = options.parameters;
  s.fixed.assign(at.begin(), at.end());
  s.fixed[static_cast<std::size_t>(time.coordinate - 1)] = std::nullopt;
  PresenceWalk walk{ RegionWalker(model.specialise(s)), options.time_tolerance, {} };
  walk.visit(walk.walker.root(), Interval{ time.lo, time.hi });
  result.inside = std::move(walk.inside);
  return result;
}

} // namespace frep::project
