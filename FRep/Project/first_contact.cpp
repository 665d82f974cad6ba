#include "Project/detail/box_split.h"
#include "Project/detail/space_time_checks.h"
#include "Project/space_time.h"

#include "Compiler/combine.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace frep::project
{
namespace
{

// A box of (t, space) waiting, the earliest first. Best-first, not the region walker: the queue
// holds boxes of many branches at once, and the walker's regions are valid only depth first.
struct Pending
{
  double t_lo = 0.0;
  std::vector<Interval> box; // t, then space
  bool operator<(const Pending& other) const { return t_lo > other.t_lo; } // min-heap on t_lo
};

// Boxes smaller than this fraction of the search's range on every axis are not split.
constexpr double kSmallest = 0x1p-24;

// The axis to split among [first, box.size()), as an index of the whole box; -1 when every one
// is as small as boxes get.
int widest_axis(const std::vector<Interval>& box, const std::vector<Interval>& whole,
  std::size_t first)
{
  const int axis = detail::widest_axis(std::span<const Interval>(box).subspan(first),
    std::span<const Interval>(whole).subspan(first), kSmallest);
  return axis < 0 ? -1 : axis + static_cast<int>(first);
}

using detail::centre;

// The search over I = A & B (t first): a box is dropped when I's enclosure is below 0. A box
// thinner in t than the tolerance is decided at once by the projector (a depth-first search of
// the whole box with the region walker): a point where I >= -value_tolerance is a contact, an
// enclosure below it everywhere rules the box out; only a search cut short splits its space.
struct ContactSearch
{
  IntervalEvaluator boxes;
  PointEvaluator points;
  Projector witness; // I maximised over a thin box (every input eliminated)
  std::vector<Interval> whole;
  const SpaceTimeOptions& options;
  std::priority_queue<Pending> queue;
  Contact result;
  double unsearched = std::numeric_limits<double>::infinity(); // earliest t not ruled out

  void found(double time, std::vector<double> where)
  {
    if (!result.found || time < result.time)
    {
      result.found = true;
      result.time = time;
      result.where = std::move(where);
    }
  }

  // A thin box decided by one depth-first search of all of it (the projector with every input
  // eliminated, asked only whether I reaches -value_tolerance): true when it holds a contact
  // (then found) or none (I < 0 all over it); false when the search was cut short.
  bool thin_decided(const Pending& p)
  {
    witness.set_ranges(p.box);
    const Maximum m = witness.maximise({}, -options.value_tolerance);
    result.boxes += m.boxes;
    if (m.value >= -options.value_tolerance)
    {
      found(m.at[0], m.at);
      unsearched = std::min(unsearched, p.t_lo);
      return true;
    }
    return m.resolved;
  }

  void split(Pending p, int axis)
  {
    const double middle = centre(p.box[static_cast<std::size_t>(axis)]);
    Pending low = p;
    low.box[static_cast<std::size_t>(axis)].hi = middle;
    p.box[static_cast<std::size_t>(axis)].lo = middle;
    p.t_lo = p.box[0].lo;
    queue.push(std::move(low));
    queue.push(std::move(p));
  }

  void visit(Pending p, std::vector<double>& at)
  {
    ++result.boxes;
    if (boxes.evaluate(p.box).value.hi < 0.0)
      return;
    for (std::size_t i = 0; i < p.box.size(); ++i)
      at[i] = centre(p.box[i]);
    if (points.value(at) >= 0.0)
    {
      found(at[0], at);
      // The box's earlier part may hold an earlier contact (its later part cannot).
      if (p.box[0].hi - p.box[0].lo > options.time_tolerance)
      {
        p.box[0].hi = at[0];
        queue.push(std::move(p));
      }
      else
        unsearched = std::min(unsearched, p.t_lo);
      return;
    }
    const bool thin = p.box[0].hi - p.box[0].lo <= options.time_tolerance;
    if (thin && thin_decided(p))
      return;
    const int axis = widest_axis(p.box, whole, thin ? 1 : 0);
    if (axis >= 0)
      split(std::move(p), axis);
    else
      unsearched = std::min(unsearched, p.t_lo); // undecided at the smallest size
  }

  void run()
  {
    queue.push({ whole[0].lo, whole });
    std::vector<double> at(whole.size());
    while (!queue.empty())
    {
      if (result.found && queue.top().t_lo >= result.time - options.time_tolerance)
        break;
      if (result.boxes >= options.max_boxes)
      {
        result.error = "no answer within " + std::to_string(options.max_boxes) +
                       " boxes (raise the time tolerance or narrow the box)";
        return;
      }
      Pending p = queue.top();
      queue.pop();
      visit(std::move(p), at);
    }
    // Every box left starts no earlier than the answer's time minus the tolerance.
    if (result.found)
      result.time_lo = std::min(
        { result.time, unsearched, queue.empty() ? result.time : queue.top().t_lo });
  }
};

} // namespace

Contact first_contact(std::shared_ptr<const Model> a, std::shared_ptr<const Model> b,
  const CoordinateRange& time, const std::vector<Interval>& space, const SpaceTimeOptions& options)
{
  Contact refused;
  if (!a || !b)
    refused.error = "contact needs two models";
  else if (a->x_dim() != b->x_dim())
    refused.error = a->name() + " has x[" + std::to_string(a->x_dim()) + "], " + b->name() +
                    " has x[" + std::to_string(b->x_dim()) + "]: contact needs the same space-time";
  for (const std::string& why : { refused.error, a ? detail::check_time(*a, time) : std::string(),
         a ? detail::check_space(*a, space) : std::string(), detail::check_tolerances(options) })
    if (!why.empty())
    {
      refused.error = why;
      return refused;
    }
  Specialisation order;
  order.parameters = options.parameters;
  order.input_order = detail::time_first_order(a->x_dim(), time.coordinate);
  const CombineResult both =
    combine(Operation::Intersection, Operand{ a, order }, Operand{ b, order });
  if (!both.ok())
  {
    refused.error = both.error;
    return refused;
  }
  const std::shared_ptr<const Tape> tape = both.model->tape();
  std::vector<Interval> whole{ Interval{ time.lo, time.hi } };
  whole.insert(whole.end(), space.begin(), space.end());
  ProjectorOptions witness;
  witness.tolerance = std::max(options.value_tolerance, 1e-12);
  witness.max_boxes = 20000;
  ContactSearch search{ IntervalEvaluator(tape), PointEvaluator(tape),
    Projector(tape, whole, witness), whole, options,
    {}, {} };
  search.run();
  Contact& r = search.result;
  // `where` in the models' own coordinate order (time where it belongs).
  if (r.found)
  {
    std::vector<double> where(r.where.begin() + 1, r.where.end());
    where.insert(where.begin() + (time.coordinate - 1), r.where[0]);
    r.where = std::move(where);
  }
  return r;
}

} // namespace frep::project
