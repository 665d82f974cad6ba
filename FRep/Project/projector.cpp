#include "Project/projector.h"

#include "Eval/gradient_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Project/detail/box_split.h"
#include "Project/detail/tape_split.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace frep::project
{
namespace
{

// Points of T evaluated before the search: per axis 9 (one range), 3 (two), 2 (more; at most
// kMaxSeeds in all, the rest of the axes at their centres).
constexpr std::size_t kMaxSeeds = 32;

// A box of T is not split below this fraction of its range on every axis: an enclosure that
// has not shrunk to the tolerance by then will not (opaque calls, NaN).
constexpr double kMinRelativeWidth = 0x1p-30;

using detail::centre;

// A point's search walks the suffix without simplifying it per box: a search visits tens of
// boxes of T, too few to pay for the shorter tapes. Measured on 2026-12-07 (frepkit mesh
// --project x4=0:1 -j1, the benchmark's cases and two more): the turning blade at 64^3 8.25 s ->
// 6.7 s, Meta5D along x4 at 48^3 1.11 -> 0.97 s, a union of 50 moving spheres at 64^3 76.6 ->
// 71.1 s, the capsule at 96^3 1.09 -> 1.05 s, Meta5D's ghost (a point's search) 72 -> 28 us.
RegionWalkerOptions suffix_walk()
{
  RegionWalkerOptions options;
  options.simplify = false;
  return options;
}

} // namespace

// Per thread: the walkers, the evaluators and the scratch of one search.
struct Projector::Search
{
  // A point's search walks the suffix (the part of F that reads t), after the prefix (the part
  // that reads x' alone) has been evaluated once at the point; an enclosure over a box of x'
  // walks the whole tape.
  std::optional<PointEvaluator> prefix;
  std::optional<IntervalEvaluator> prefix_intervals;
  std::vector<double> prefix_values;
  RegionWalker point_walker;
  RegionWalker box_walker;
  RegionWalker* walker = nullptr; // the one the current walk uses
  GradientEvaluator gradients;
  std::vector<Interval> box;                 // kept inputs, then the eliminated ones
  std::vector<std::vector<double>> columns;  // two points' inputs, one column per input
  std::vector<const double*> pointers;
  double best = 0.0;                         // the search's lower bound: F at best_at
  std::vector<double> best_at;
  std::vector<double> gradient_inputs, gradient_outputs; // gradient()'s scratch
  std::size_t boxes = 0;
  bool resolved = true;
  // The question asked: stop once best reaches stop_at, and skip the boxes whose enclosure is
  // below prune_below (the band's, or maximise(kept, threshold)'s).
  double stop_at = 0.0;
  double prune_below = 0.0;

  // The walks' context, set by maximise() / enclose().
  std::span<const Interval> ranges;
  std::size_t kept = 0;
  const ProjectorOptions* options = nullptr;
  double lo = 0.0, hi = 0.0; // the enclosure walk's P >= lo, and the uncovered boxes' max hi
  bool may_fail = false;

  void seed(const RegionWalker::Region& root);
  bool enclose_prefix(std::span<const Interval> kept);
  void evaluate_centres(const RegionWalker::Region& region, int axis, const Interval (&halves)[2],
    double (&values)[2]);
  void visit_maximum(const RegionWalker::Region& region);
  void visit_enclosure(const RegionWalker::Region& region);

  Search(const std::shared_ptr<const Tape>& tape, const detail::SplitTape& split)
    : point_walker(split.suffix, suffix_walk())
    , box_walker(tape)
    , gradients(tape)
  {
    if (split.prefix)
    {
      prefix.emplace(split.prefix);
      prefix_intervals.emplace(split.prefix);
      prefix_values.resize(split.prefix->outputs.size());
    }
    columns.assign(std::max(tape->input_count, split.suffix->input_count),
      std::vector<double>(kMaxSeeds));
    for (const std::vector<double>& column : columns)
      pointers.push_back(column.data());
  }
};

Projector::Projector(std::shared_ptr<const Tape> tape, std::vector<Interval> ranges,
  const ProjectorOptions& options)
  : tape_(std::move(tape))
  , ranges_(std::move(ranges))
  , options_(options)
{
  if (!tape_ || ranges_.empty() || ranges_.size() > tape_->input_count)
    throw std::invalid_argument("Projector: the eliminated inputs do not fit the tape");
  for (const Interval& r : ranges_)
    if (!std::isfinite(r.lo) || !std::isfinite(r.hi) || r.lo > r.hi)
      throw std::invalid_argument("Projector: an eliminated range is not a finite lo <= hi");
  if (!(options_.tolerance > 0.0) || options_.max_boxes < 1 || options_.enclosure_boxes < 1)
    throw std::invalid_argument("Projector: tolerance <= 0 or no boxes");
  kept_ = tape_->input_count - ranges_.size();
  search_ = std::make_unique<Search>(tape_, detail::split_tape(*tape_, kept_));
  search_->ranges = ranges_;
  search_->options = &options_;
}

Projector::~Projector() = default;

void Projector::set_ranges(std::span<const Interval> ranges)
{
  if (ranges.size() != ranges_.size())
    throw std::invalid_argument("Projector::set_ranges: wrong number of ranges");
  for (const Interval& r : ranges)
    if (!std::isfinite(r.lo) || !std::isfinite(r.hi) || r.lo > r.hi)
      throw std::invalid_argument("Projector: an eliminated range is not a finite lo <= hi");
  ranges_.assign(ranges.begin(), ranges.end());
  search_->ranges = ranges_;
}

namespace
{

// The eliminated axis to split (an index into the eliminated inputs), or -1.
int split_axis(std::span<const Interval> box, std::span<const Interval> ranges, std::size_t kept)
{
  return detail::widest_axis(box.subspan(kept), ranges, kMinRelativeWidth);
}

} // namespace

void Projector::Search::seed(const RegionWalker::Region& root)
{
  const std::size_t k = ranges.size();
  const std::size_t per_axis = k == 1 ? 9 : (k == 2 ? 3 : 2);
  std::size_t count = 1, seeded_axes = 0;
  while (seeded_axes < k && count * per_axis <= kMaxSeeds)
  {
    count *= per_axis;
    ++seeded_axes;
  }
  // (Not the previous search's maximiser, though neighbouring points have theirs close: a value
  // must not depend on which point a thread evaluated before, or pictures would change with the
  // number of threads.)
  for (std::size_t i = 0; i < box.size(); ++i)
    std::fill_n(columns[i].begin(), count, centre(box[i]));
  for (std::size_t p = 0; p < count; ++p)
  {
    std::size_t rest = p;
    for (std::size_t e = 0; e < seeded_axes; ++e)
    {
      const Interval& r = ranges[e];
      const double f = static_cast<double>(rest % per_axis) / static_cast<double>(per_axis - 1);
      columns[kept + e][p] = f == 0.0 ? r.lo : (f == 1.0 ? r.hi : r.lo + f * (r.hi - r.lo));
      rest /= per_axis;
    }
  }
  double values[kMaxSeeds];
  std::uint32_t errors[kMaxSeeds] = {};
  walker->evaluate(root, pointers, count, values, errors);
  for (std::size_t p = 0; p < count; ++p)
    if (errors[p] == 0 && values[p] > best) // NaN is never better
    {
      best = values[p];
      for (std::size_t e = 0; e < ranges.size(); ++e)
        best_at[e] = columns[kept + e][p];
    }
}

// Branch and bound, depth first: each box's children's centres are evaluated together, the
// better child searched first, and a box culled once its enclosure cannot beat the best value
// by more than the tolerance.

// F at the centres of the two halves of the box along `axis`, with the region's tape; the better
// one becomes the best.
void Projector::Search::evaluate_centres(const RegionWalker::Region& region, int axis,
  const Interval (&halves)[2], double (&values)[2])
{
  for (std::size_t i = 0; i < box.size(); ++i)
    columns[i][0] = columns[i][1] = centre(box[i]);
  const std::size_t a = kept + static_cast<std::size_t>(axis);
  for (std::size_t c = 0; c < 2; ++c)
    columns[a][c] = centre(halves[c]);
  std::uint32_t errors[2] = { 0, 0 };
  walker->evaluate(region, pointers, 2, values, errors);
  for (std::size_t c = 0; c < 2; ++c)
  {
    if (errors[c] != 0 || std::isnan(values[c]))
      values[c] = -std::numeric_limits<double>::infinity();
    if (values[c] > best)
    {
      best = values[c];
      for (std::size_t e = 0; e < ranges.size(); ++e)
        best_at[e] = columns[kept + e][c];
    }
  }
}

void Projector::Search::visit_maximum(const RegionWalker::Region& region)
{
  if (boxes >= options->max_boxes)
  {
    resolved = false;
    return;
  }
  if (best >= stop_at)
    return; // the question asked is answered
  const IntervalResult r = walker->enclose(region, box);
  ++boxes;
  if (!(r.value.hi > best + options->tolerance) || r.value.hi < prune_below)
    return;
  const int axis = split_axis(box, ranges, kept);
  if (axis < 0)
  {
    resolved = false; // as small as boxes get, and still not within the tolerance
    return;
  }
  const RegionWalker::Region inner = walker->descend(region);
  Interval& b = box[kept + static_cast<std::size_t>(axis)];
  const Interval whole = b;
  const double middle = centre(whole);
  const Interval halves[2] = { { whole.lo, middle }, { middle, whole.hi } };
  double values[2];
  evaluate_centres(inner, axis, halves, values);
  const int first = values[1] > values[0] ? 1 : 0;
  for (const int c : { first, 1 - first })
  {
    b = halves[c];
    visit_maximum(inner);
  }
  b = whole;
}

Maximum Projector::maximise(std::span<const double> kept)
{
  search_->stop_at = options_.band;
  search_->prune_below = -options_.band;
  return run_search(kept);
}

Maximum Projector::maximise(std::span<const double> kept, double threshold)
{
  search_->stop_at = threshold;
  search_->prune_below = threshold;
  return run_search(kept);
}

Maximum Projector::run_search(std::span<const double> kept)
{
  if (kept.size() != kept_)
    throw std::invalid_argument("Projector::maximise: wrong number of kept inputs");
  Search& s = *search_;
  s.best = -std::numeric_limits<double>::infinity();
  s.best_at.assign(ranges_.size(), 0.0);
  for (std::size_t e = 0; e < ranges_.size(); ++e)
    s.best_at[e] = centre(ranges_[e]);
  s.boxes = 0;
  s.resolved = true;
  // The part of F that reads x' alone, once: a point where it fails fails for every t.
  std::span<const double> inputs; // the suffix's inputs before t: none without a prefix
  if (s.prefix)
  {
    if (s.prefix->evaluate(kept, s.prefix_values) != 0)
      return Maximum{ std::numeric_limits<double>::quiet_NaN(), s.best_at, true, 0 };
    inputs = s.prefix_values;
  }
  s.box.clear();
  for (const double x : inputs)
    s.box.push_back(Interval::point(x));
  s.box.insert(s.box.end(), ranges_.begin(), ranges_.end());
  s.kept = inputs.size();
  s.walker = &s.point_walker;

  // A lattice of T first (its centre and corners, 9 points of a single range): a lower bound
  // before any box is enclosed, in one evaluation.
  // Each point's search starts from a walker that has learnt nothing from the last point's (a
  // value must not depend on which points a thread searched before).
  s.walker->restart();
  const RegionWalker::Region root = s.walker->root();
  s.seed(root);

  s.visit_maximum(root);

  Maximum m;
  m.value = std::isinf(s.best) && s.best < 0 ? std::numeric_limits<double>::quiet_NaN() : s.best;
  m.at = s.best_at;
  m.resolved = s.resolved;
  m.boxes = s.boxes;
  return m;
}

// The prefix's enclosures over a box of x' as the suffix's first inputs (the suffix is then walked
// over the boxes of T, the prefix evaluated once: the composition of the two tapes' interval
// rules is the whole tape's); false where a prefix value may be NaN.
bool Projector::Search::enclose_prefix(std::span<const Interval> kept_box)
{
  box.clear();
  if (prefix_intervals)
  {
    may_fail = prefix_intervals->evaluate(kept_box).may_fail;
    for (std::size_t i = 0; i < prefix_values.size(); ++i)
    {
      Interval v;
      if (!prefix_intervals->output(i, v))
        return false;
      box.push_back(v);
    }
  }
  kept = box.size();
  walker = &point_walker;
  return true;
}

// The enclosure of P over a box of x': the boxes of T split while the budget lasts; P is at
// least every box's lower end (each t of it is a candidate), at most the largest upper end of the
// boxes that cover T (a box whose upper end is below the lower bound found adds nothing).
void Projector::Search::visit_enclosure(const RegionWalker::Region& region)
{
  const IntervalResult r = walker->enclose(region, box);
  ++boxes;
  may_fail = may_fail || r.may_fail;
  lo = std::max(lo, r.value.lo);
  if (r.value.hi <= lo)
    return;
  const int axis = split_axis(box, ranges, kept);
  if (axis < 0 || boxes + 2 > options->enclosure_boxes)
  {
    hi = std::max(hi, r.value.hi);
    return;
  }
  const RegionWalker::Region inner = walker->descend(region);
  Interval& b = box[kept + static_cast<std::size_t>(axis)];
  const Interval whole = b;
  const double middle = centre(whole);
  for (const Interval half : { Interval{ whole.lo, middle }, Interval{ middle, whole.hi } })
  {
    b = half;
    visit_enclosure(inner);
  }
  b = whole;
}

IntervalResult Projector::enclose(std::span<const Interval> kept)
{
  if (kept.size() != kept_)
    throw std::invalid_argument("Projector::enclose: wrong number of kept inputs");
  Search& s = *search_;
  s.boxes = 0;
  s.lo = s.hi = -std::numeric_limits<double>::infinity();
  s.may_fail = false;
  if (!s.enclose_prefix(kept))
  {
    // The whole tape over the box (the prefix may be NaN in it: the suffix cannot say).
    s.box.assign(kept.begin(), kept.end());
    s.kept = kept_;
    s.walker = &s.box_walker;
  }
  s.box.insert(s.box.end(), ranges_.begin(), ranges_.end());
  s.walker->restart();
  s.visit_enclosure(s.walker->root());
  IntervalResult result;
  // P >= lo everywhere, so a point value (>= P - tolerance, or >= band) is at least the lower
  // of lo - tolerance and the band.
  result.value = Interval{ std::min(s.lo - options_.tolerance, options_.band), std::max(s.hi, s.lo) };
  result.may_fail = s.may_fail;
  if (std::isnan(result.value.lo) || std::isnan(result.value.hi))
    result.value = Interval::everything();
  return result;
}

double Projector::gradient(std::span<const double> kept, std::span<double> gradient)
{
  const Maximum m = maximise(kept);
  // The search's scratch (no allocation per point: the mesher asks this for every normal).
  std::vector<double>& inputs = search_->gradient_inputs;
  std::vector<double>& full = search_->gradient_outputs;
  inputs.assign(kept.begin(), kept.end());
  inputs.insert(inputs.end(), m.at.begin(), m.at.end());
  full.resize(inputs.size());
  search_->gradients.evaluate(inputs, full);
  std::copy_n(full.begin(), std::min(gradient.size(), kept_), gradient.begin());
  return m.value;
}

} // namespace frep::project
