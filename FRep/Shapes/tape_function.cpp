#include "Shapes/tape_function.h"

#include "Eval/gradient_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"

#include <cmath>
#include <mutex>
#include <vector>

namespace frep::shapes
{
namespace
{

// Evaluators keep per-thread scratch; the user function's forms may run on any thread. A
// small pool hands each call an evaluator of its own (made on demand, kept for the next call).
template<class Evaluator>
class Pool
{
public:
  explicit Pool(std::shared_ptr<const Tape> tape)
    : tape_(std::move(tape))
  {
  }
  template<class F>
  auto with(F&& f)
  {
    std::unique_ptr<Evaluator> e;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!free_.empty())
      {
        e = std::move(free_.back());
        free_.pop_back();
      }
    }
    if (!e)
    {
      e = std::make_unique<Evaluator>(tape_);
    }
    auto result = f(*e);
    std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(std::move(e));
    return result;
  }

private:
  std::shared_ptr<const Tape> tape_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<Evaluator>> free_;
};

} // namespace

UserFunction tape_function(const std::string& name, std::shared_ptr<const Tape> tape)
{
  UserFunction f;
  f.name = name;
  if (!tape)
  {
    return f; // no point form: the registry refuses it
  }
  const int k = static_cast<int>(tape->input_count);
  f.kinds = { ArgKind::Array };
  f.array_sizes = { k };
  auto points = std::make_shared<Pool<PointEvaluator>>(tape);
  auto intervals = std::make_shared<Pool<IntervalEvaluator>>(tape);
  auto gradients = std::make_shared<Pool<GradientEvaluator>>(tape);
  f.point = [points, k](std::span<const UserArgument> args, double& v)
  {
    v = points->with([&](PointEvaluator& e)
      { return e.value(std::span<const double>(args[0].values, static_cast<std::size_t>(k))); });
    return !std::isnan(v);
  };
  f.interval = [intervals, k](std::span<const UserIntervalArgument> args, double& lo, double& hi,
                 bool& fails)
  {
    std::vector<Interval> box(static_cast<std::size_t>(k));
    for (int i = 0; i < k; ++i)
    {
      box[static_cast<std::size_t>(i)] = Interval{ args[0].lo[i], args[0].hi[i] };
    }
    const IntervalResult r = intervals->with([&](IntervalEvaluator& e) { return e.evaluate(box); });
    lo = r.value.lo;
    hi = r.value.hi;
    fails = r.may_fail;
    return true;
  };
  f.gradient = [gradients, k](std::span<const UserArgument> args, double& v, std::span<double> g)
  {
    v = gradients->with([&](GradientEvaluator& e)
      {
        return e.evaluate(std::span<const double>(args[0].values, static_cast<std::size_t>(k)),
          g.first(static_cast<std::size_t>(k)));
      });
    return !std::isnan(v);
  };
  return f;
}

} // namespace frep::shapes
