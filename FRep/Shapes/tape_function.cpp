#include "Shapes/tape_function.h"

#include "Eval/detail/object_pool.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"

#include <cmath>
#include <vector>

namespace frep::shapes
{
namespace
{

// Evaluators keep per-thread scratch; the user function's forms may run on any thread.
template<class Evaluator>
std::shared_ptr<eval::ObjectPool<Evaluator>> evaluator_pool(std::shared_ptr<const Tape> tape)
{
  return std::make_shared<eval::ObjectPool<Evaluator>>(
    [tape] { return std::make_unique<Evaluator>(tape); });
}

} // namespace

UserFunction array_function(const std::string& name, int k, ArrayForms forms)
{
  UserFunction f;
  f.name = name;
  f.kinds = { ArgKind::Array };
  f.array_sizes = { k };
  const auto items = [k](const UserArgument& a)
  { return std::span<const double>(a.values, static_cast<std::size_t>(k)); };
  if (forms.point)
    f.point = [point = std::move(forms.point), items](std::span<const UserArgument> args, double& v)
    {
      v = point(items(args[0]));
      return !std::isnan(v);
    };
  if (forms.interval)
    f.interval = [interval = std::move(forms.interval), k](std::span<const UserIntervalArgument> args,
                   double& lo, double& hi, bool& may_fail)
    {
      std::vector<Interval> box(static_cast<std::size_t>(k));
      for (int i = 0; i < k; ++i)
        box[static_cast<std::size_t>(i)] = Interval{ args[0].lo[i], args[0].hi[i] };
      const IntervalResult r = interval(box);
      lo = r.value.lo;
      hi = r.value.hi;
      may_fail = r.may_fail;
      return true;
    };
  if (forms.gradient)
    f.gradient = [gradient = std::move(forms.gradient), items, k](std::span<const UserArgument> args,
                   double& v, std::span<double> g)
    {
      v = gradient(items(args[0]), g.first(static_cast<std::size_t>(k)));
      return !std::isnan(v);
    };
  return f;
}

UserFunction tape_function(const std::string& name, std::shared_ptr<const Tape> tape)
{
  if (!tape)
  {
    UserFunction f;
    f.name = name;
    return f; // no point form: the registry refuses it
  }
  auto points = evaluator_pool<PointEvaluator>(tape);
  auto intervals = evaluator_pool<IntervalEvaluator>(tape);
  auto gradients = evaluator_pool<GradientEvaluator>(tape);
  ArrayForms forms;
  forms.point = [points](std::span<const double> x)
  { return points->with([&](PointEvaluator& e) { return e.value(x); }); };
  forms.interval = [intervals](std::span<const Interval> box)
  { return intervals->with([&](IntervalEvaluator& e) { return e.evaluate(box); }); };
  forms.gradient = [gradients](std::span<const double> x, std::span<double> g)
  { return gradients->with([&](GradientEvaluator& e) { return e.evaluate(x, g); }); };
  return array_function(name, static_cast<int>(tape->input_count), std::move(forms));
}

} // namespace frep::shapes
