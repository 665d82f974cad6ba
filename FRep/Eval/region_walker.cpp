// RegionWalker: one level (tape, interval evaluator, choices, kernel, throttle) per depth,
// rebound from region to region, and one freeze per depth.
#include "Eval/region_walker.h"

#include "Eval/detail/block_runner.h"
#include "Eval/detail/jit_kernel.h"
#include "Eval/tape_simplifier.h"

#include <deque>
#include <optional>
#include <stdexcept>
#include <vector>

namespace frep
{

/// A box's freeze for the boxes inside it, made when one of them first asks (walks decide many
/// boxes inside without an interval: marched, sampled), and only kept where it skips something
/// (evaluating with a freeze costs a check per instruction): else the enclosing box's.
class RegionWalker::LazyFreeze
{
public:
  /// `evaluator` evaluated the box last with `outer` and recorded into `inner`.
  LazyFreeze(IntervalEvaluator& evaluator, const IntervalFreeze* outer, IntervalFreeze& inner)
    : evaluator_(&evaluator)
    , outer_(outer)
    , inner_(&inner)
  {
  }
  /// The freeze to evaluate a box inside with (null: none).
  const IntervalFreeze* get()
  {
    if (!tried_)
    {
      tried_ = true;
      made_ = evaluator_->make_freeze(outer_, *inner_) && inner_->skipped > 0 ? inner_ : outer_;
    }
    return made_;
  }

private:
  IntervalEvaluator* evaluator_;
  const IntervalFreeze* outer_;
  IntervalFreeze* inner_;
  const IntervalFreeze* made_ = nullptr;
  bool tried_ = false;
};

namespace
{

/// Whether a walk should keep trying to simplify a tape for its boxes: after 16 attempts, only
/// while at least one in 8 paid (a tape whose boxes never simplify, such as an R-function blend,
/// stops paying for a copy of itself per box). One per tape a walk holds; reset with the tape.
struct SimplifyThrottle
{
  int attempts = 0;
  int successes = 0;
  bool worth_trying() const { return attempts < 16 || successes * 8 >= attempts; }
  void record(bool paid)
  {
    ++attempts;
    successes += paid ? 1 : 0;
  }
};

} // namespace

/// A tape and what evaluates it: the walker's tape at the root, a simplified one below a region
/// that decided some of its instructions.
struct RegionWalker::Level
{
  std::shared_ptr<const Tape> tape;
  bool trusted = false; // a tape the engine made (simplified): not checked again
  IntervalEvaluator interval;
  std::vector<Choice> choices;
  bool simplifiable = false;  // may_simplify(*tape)
  SimplifyThrottle throttle;  // a blend whose regions never simplify stops trying
  eval::LazyKernel kernel;    // the tape compiled, once its samples pay for it

  Level(std::shared_ptr<const Tape> t, bool trusted_tape)
    : tape(std::move(t))
    , trusted(trusted_tape)
    , interval(tape)
    , choices(tape->code.size())
    , simplifiable(may_simplify(*tape))
  {
  }

  void rebind(std::shared_ptr<const Tape> t)
  {
    if (t == tape)
    {
      return;
    }
    tape = std::move(t);
    trusted = true;
    interval.rebind(tape, true);
    choices.resize(tape->code.size());
    simplifiable = may_simplify(*tape);
    kernel.reset();
    throttle = {};
  }
};

struct RegionWalker::Walk
{
  /// What the last enclose() at one depth left for descend().
  struct DepthState
  {
    IntervalFreeze inner;          // the box's enclosures, recorded for its freeze
    std::optional<LazyFreeze> own; // the freeze handed to the regions inside
    bool enclosed = false;         // enclose() ran and descend() has not consumed it
    bool recorded = false;         // ... and recorded choices
  };

  RegionWalkerOptions options;
  Level root;
  std::unique_ptr<Level> entry;              // root(tape) for another tape
  std::vector<std::unique_ptr<Level>> below; // [d]: the level below a region at depth d
  std::deque<DepthState> depths;             // [d] (stable addresses: freezes point into it)
  TapeSimplifier simplifier;
  eval::BlockRunner runner;

  Walk(std::shared_ptr<const Tape> tape, const RegionWalkerOptions& o)
    : options(o)
    , root(std::move(tape), false)
    , runner(o.block)
  {
  }

  DepthState& at(std::size_t depth)
  {
    while (depths.size() <= depth)
    {
      depths.emplace_back();
    }
    return depths[depth];
  }
};

RegionWalker::RegionWalker(std::shared_ptr<const Tape> tape, const RegionWalkerOptions& options)
{
  if (!tape)
  {
    throw std::invalid_argument("RegionWalker: null tape");
  }
  if (options.block <= 0 || options.freeze_every <= 0)
  {
    throw std::invalid_argument("RegionWalker: block and freeze_every must be positive");
  }
  walk_ = std::make_unique<Walk>(std::move(tape), options);
}

RegionWalker::~RegionWalker() = default;

void RegionWalker::restart()
{
  walk_->root.throttle = {};
  if (walk_->entry)
    walk_->entry->throttle = {};
  for (const std::unique_ptr<Level>& level : walk_->below)
    if (level)
      level->throttle = {};
}

RegionWalker::Region RegionWalker::root()
{
  Region r;
  r.level_ = &walk_->root;
  return r;
}

RegionWalker::Region RegionWalker::root(std::shared_ptr<const Tape> tape)
{
  if (!tape || tape == walk_->root.tape)
  {
    return root();
  }
  if (!walk_->entry)
  {
    walk_->entry = std::make_unique<Level>(std::move(tape), true);
  }
  else
  {
    walk_->entry->rebind(std::move(tape));
  }
  Region r;
  r.level_ = walk_->entry.get();
  return r;
}

const std::shared_ptr<const Tape>& RegionWalker::tape(const Region& region) const
{
  return region.level_->tape;
}

RegionWalker::Level& RegionWalker::level_below(std::size_t depth, std::shared_ptr<const Tape> tape)
{
  std::vector<std::unique_ptr<Level>>& below = walk_->below;
  if (below.size() <= depth)
  {
    below.resize(depth + 1);
  }
  if (!below[depth])
  {
    below[depth] = std::make_unique<Level>(std::move(tape), true);
  }
  else
  {
    below[depth]->rebind(std::move(tape));
  }
  return *below[depth];
}

bool RegionWalker::would_simplify(const Region& region) const
{
  const Level& level = *region.level_;
  return walk_->options.simplify && level.simplifiable && level.throttle.worth_trying();
}

IntervalResult RegionWalker::enclose(const Region& region, std::span<const Interval> box,
  bool simplify)
{
  Level& level = *region.level_;
  Walk::DepthState& state = walk_->at(region.depth_);
  state.enclosed = true;
  state.recorded = simplify && would_simplify(region);
  ++statistics_.enclosures;
  const std::span<Choice> choices =
    state.recorded ? std::span<Choice>(level.choices) : std::span<Choice>();
  if (!walk_->options.freeze)
  {
    return level.interval.evaluate(box, choices, nullptr, nullptr);
  }
  const IntervalFreeze* outer = region.link_ ? region.link_->get() : nullptr;
  return level.interval.evaluate(box, choices, outer, &state.inner);
}

RegionWalker::Region RegionWalker::descend(const Region& region)
{
  Level& level = *region.level_;
  const std::size_t depth = region.depth_;
  Walk::DepthState& state = walk_->at(depth);
  const bool enclosed = state.enclosed;
  state.enclosed = false;
  Region inner;
  inner.level_ = &level;
  inner.depth_ = depth + 1;
  if (enclosed && state.recorded)
  {
    std::shared_ptr<const Tape> tape = walk_->simplifier.simplify(*level.tape, level.choices);
    const bool paid = tape && worth_switching(*tape, *level.tape);
    level.throttle.record(paid);
    ++statistics_.simplify_tries;
    if (paid)
    {
      ++statistics_.simplified;
      inner.level_ = &level_below(depth, std::move(tape));
      return inner; // another tape: the freeze of this one does not apply
    }
  }
  if (!enclosed || !walk_->options.freeze)
  {
    return inner;
  }
  // The same tape below: what this box dominates need not be evaluated again inside it. Every
  // freeze_every-th depth makes its own; the others pass their parent's on.
  if (region.link_ && depth % static_cast<std::size_t>(walk_->options.freeze_every) != 0)
  {
    inner.link_ = region.link_;
    return inner;
  }
  state.own.emplace(level.interval, region.link_ ? region.link_->get() : nullptr, state.inner);
  inner.link_ = &*state.own;
  return inner;
}

std::size_t RegionWalker::evaluate(const Region& region, std::span<const double* const> inputs,
  std::size_t count, double* values, std::uint32_t* errors, std::span<double* const> attributes)
{
  if (count == 0)
  {
    return 0;
  }
  Level& level = *region.level_;
  const RegionWalkerOptions& options = walk_->options;
  std::shared_ptr<const eval::JitKernel> kernel;
  if (options.jit)
  {
    const bool now = options.compile_root_now && &level == &walk_->root;
    kernel = level.kernel.get(*level.tape, now ? eval::LazyKernel::kWorthSamples : count);
  }
  walk_->runner.bind(level.tape, level.trusted, std::move(kernel));
  const std::size_t failed = walk_->runner.evaluate(inputs, count, values, errors, attributes);
  statistics_.points += count;
  statistics_.instructions += count * level.tape->code.size();
  statistics_.failed_points += failed;
  return failed;
}

} // namespace frep
