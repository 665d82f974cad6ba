// The normalised map of one channel: x in range -> u in [0, 1] -> v = curve(u) in [0, 1] ->
// y in target, and back. Expression curves are HyperFun expressions of `t`, compiled once by
// the engine and shared (immutable) between copies and threads.
#pragma once

#include "Mapping/mapping_spec.h"

#include <memory>
#include <string>

namespace frep
{
struct Tape;
class PointEvaluator;
} // namespace frep

namespace frep::mapping
{

/// A curve ready to evaluate. Cheap to copy (an expression's compiled tape is shared) and safe
/// to evaluate from several threads at once (each evaluation uses its own evaluator state).
class UnitCurve
{
public:
  /// The linear curve v = u.
  UnitCurve() = default;

  struct Result;
  /// Checks the curve and compiles an expression. Errors (a parse error with its column, an
  /// exponent <= 0, a table whose u do not rise from 0 to 1, ...) come back in Result::error.
  static Result make(const Curve& curve);

  /// v = curve(u) for u clamped to [0, 1]. The value is clamped to [0, 1] too: a table or an
  /// expression may overshoot, and a channel must stay inside its target. An expression that
  /// fails at run time (sqrt of a negative, ...) gives 0.
  double operator()(double u) const;

  /// Non-decreasing or non-increasing over [0, 1]. Linear, ease-in-out and power curves are;
  /// tables and expressions are checked at 1025 evenly spaced points.
  bool is_monotone() const { return monotone_; }

  /// u in [0, 1] with curve(u) = v (clamped to the curve's values). Analytic for linear and
  /// power curves, bisection to 1e-12 otherwise. Meaningful only where is_monotone(); on a
  /// flat stretch it returns one of the u of that stretch.
  double inverse(double v) const;

  const Curve& curve() const { return curve_; }

private:
  /// The clamped value; `evaluator` (expression curves) is the caller's scratch.
  double evaluate(double u, PointEvaluator* evaluator) const;

  Curve curve_;
  std::shared_ptr<const Tape> tape_; ///< expression curves only
  bool monotone_ = true;
};

struct UnitCurve::Result
{
  UnitCurve curve;
  std::string error; ///< empty = success
  bool ok() const { return error.empty(); }
};

/// curve(u) in [0, 1] (see UnitCurve::operator()). Compiles an expression curve on every call:
/// evaluate many points through a UnitCurve or ChannelMap instead. NaN for an invalid curve.
double evaluate_curve(const Curve& curve, double u);

/// One channel's map: range (geometric coordinate) -> target (multimedia coordinate). Cheap to
/// copy, thread-safe to evaluate.
class ChannelMap
{
public:
  /// [0, 1] -> linear -> [0, 1].
  ChannelMap() = default;

  struct Result;
  /// Fails for a range of zero width, non-finite bounds or an invalid curve. Reversed
  /// intervals (hi < lo, e.g. an opacity target 1 -> 0.3) are fine; the mapping file insists on
  /// lo < hi for ranges only to catch typos.
  static Result make(Interval range, const Curve& curve, Interval target);

  /// (x - lo) / (hi - lo), clamped to [0, 1]: outside its range a channel saturates.
  double to_unit(double x) const;
  /// x -> target.lo + curve(to_unit(x)) * (target.hi - target.lo).
  double forward(double x) const;
  /// The x in range with forward(x) = y (y is clamped to the target). Requires is_monotone();
  /// a target of zero width gives range.lo.
  double inverse(double y) const;
  bool is_monotone() const { return curve_.is_monotone(); }

  Interval range() const { return range_; }
  Interval target() const { return target_; }
  const UnitCurve& curve() const { return curve_; }

private:
  Interval range_;
  UnitCurve curve_;
  Interval target_;
};

struct ChannelMap::Result
{
  ChannelMap map;
  std::string error; ///< empty = success
  bool ok() const { return error.empty(); }
};

} // namespace frep::mapping
