#include "Mapping/unit_map.h"

#include "Compiler/load_model.h"
#include "Eval/point_evaluator.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace frep::mapping
{
namespace
{

// The expression sits alone from line 5 on, so the engine's line:col map back onto it.
constexpr int expression_first_line = 5;

std::string wrap_expression(const std::string& expression)
{
  return "curve(x[1], a[1])\n{\nt = x[1];\ncurve =\n" + expression + "\n;\n}\n";
}

int line_count(const std::string& text)
{
  return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

// "column 3: ..." on a one-line expression, "line 2, column 3: ..." on a longer one; a problem
// found on the closing lines of the wrapper is one at the end of the expression.
std::string describe(const Diagnostic& d, const std::string& expression)
{
  const int lines = line_count(expression);
  const int line = d.location.line - expression_first_line + 1;
  if (!d.location.valid() || line < 1)
  {
    return d.message;
  }
  if (line > lines)
  {
    return "at the end of the expression: " + d.message;
  }
  const std::string column = "column " + std::to_string(d.location.column);
  return (lines == 1 ? column : "line " + std::to_string(line) + ", " + column) + ": " + d.message;
}

std::string check_curve(const Curve& curve)
{
  switch (curve.kind)
  {
    case Curve::Kind::Power:
      if (!std::isfinite(curve.exponent) || curve.exponent <= 0)
      {
        return "power curve: the exponent must be > 0";
      }
      break;
    case Curve::Kind::Table:
    {
      const auto& t = curve.table;
      if (t.size() < 2)
      {
        return "table curve: at least 2 points are needed";
      }
      for (const auto& p : t)
      {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
        {
          return "table curve: the points must be finite numbers";
        }
      }
      if (t.front()[0] != 0.0 || t.back()[0] != 1.0)
      {
        return "table curve: u must run from 0 (first point) to 1 (last point)";
      }
      for (std::size_t k = 1; k < t.size(); ++k)
      {
        if (!(t[k][0] > t[k - 1][0]))
        {
          return "table curve: u must increase (point " + std::to_string(k) + ")";
        }
      }
      break;
    }
    case Curve::Kind::Expression:
      if (curve.expression.find_first_not_of(" \t\r\n") == std::string::npos)
      {
        return "expression curve: the expression is empty";
      }
      break;
    case Curve::Kind::Linear:
    case Curve::Kind::EaseInOut:
      break;
  }
  return {};
}

double table_value(const std::vector<std::array<double, 2>>& table, double u)
{
  // First point whose u is >= the argument; the table is validated (u from 0 to 1, rising).
  const auto it = std::lower_bound(table.begin(),
    table.end(),
    u,
    [](const std::array<double, 2>& p, double value) { return p[0] < value; });
  if (it == table.begin())
  {
    return table.front()[1];
  }
  if (it == table.end())
  {
    return table.back()[1];
  }
  const auto& b = *it;
  const auto& a = *(it - 1);
  const double f = (u - a[0]) / (b[0] - a[0]);
  return a[1] + f * (b[1] - a[1]);
}

double clamp_unit(double v)
{
  if (std::isnan(v))
  {
    return 0.0;
  }
  return std::clamp(v, 0.0, 1.0);
}

} // namespace

UnitCurve::Result UnitCurve::make(const Curve& curve)
{
  Result result;
  result.error = check_curve(curve);
  if (!result.ok())
  {
    return result;
  }
  UnitCurve& c = result.curve;
  c.curve_ = curve;
  if (curve.kind == Curve::Kind::Expression)
  {
    const LoadedProgram parsed =
      load_program(ModelSource::from_text(wrap_expression(curve.expression), "<curve>"));
    if (!parsed.ok())
    {
      result.error =
        "expression \"" + curve.expression + "\": " +
        (parsed.diagnostics.empty() ? std::string("does not parse")
                                    : describe(parsed.diagnostics.front(), curve.expression));
      return result;
    }
    if (parsed.program->objects.size() != 1)
    {
      result.error = "expression \"" + curve.expression + "\": not a single expression";
      return result;
    }
    const LoadedModel compiled = compile_object(parsed);
    if (!compiled.ok())
    {
      result.error =
        "expression \"" + curve.expression + "\": " +
        (compiled.diagnostics.empty() ? std::string("does not compile")
                                      : describe(compiled.diagnostics.front(), curve.expression));
      return result;
    }
    c.tape_ = compiled.model->tape();
  }
  if (curve.kind == Curve::Kind::Table || curve.kind == Curve::Kind::Expression)
  {
    // Sampled, not proven: enough for tables (exact at their points when they fall on the
    // samples, linear between) and for the smooth expressions curves are made of.
    constexpr int n = 1025;
    std::unique_ptr<PointEvaluator> evaluator;
    if (c.tape_)
    {
      evaluator = std::make_unique<PointEvaluator>(c.tape_);
    }
    bool rising = true;
    bool falling = true;
    double previous = c.evaluate(0.0, evaluator.get());
    for (int k = 1; k < n; ++k)
    {
      const double v = c.evaluate(static_cast<double>(k) / (n - 1), evaluator.get());
      rising = rising && v >= previous;
      falling = falling && v <= previous;
      previous = v;
    }
    c.monotone_ = rising || falling;
  }
  return result;
}

double UnitCurve::evaluate(double u, PointEvaluator* evaluator) const
{
  u = clamp_unit(u);
  switch (curve_.kind)
  {
    case Curve::Kind::Linear:
      return u;
    case Curve::Kind::Power:
      return clamp_unit(std::pow(u, curve_.exponent));
    case Curve::Kind::EaseInOut:
      return clamp_unit(u * u * (3.0 - 2.0 * u));
    case Curve::Kind::Table:
      return clamp_unit(table_value(curve_.table, u));
    case Curve::Kind::Expression:
    {
      if (!tape_)
      {
        return 0.0; // a default-constructed Curve of kind Expression that was never compiled
      }
      std::unique_ptr<PointEvaluator> own;
      if (!evaluator)
      {
        own = std::make_unique<PointEvaluator>(tape_);
        evaluator = own.get();
      }
      const std::vector<double> inputs(tape_->input_count, u);
      return clamp_unit(evaluator->value(inputs));
    }
  }
  return u;
}

double UnitCurve::operator()(double u) const
{
  return evaluate(u, nullptr);
}

double UnitCurve::inverse(double v) const
{
  v = clamp_unit(v);
  switch (curve_.kind)
  {
    case Curve::Kind::Linear:
      return v;
    case Curve::Kind::Power:
      return clamp_unit(std::pow(v, 1.0 / curve_.exponent));
    default:
      break;
  }
  std::unique_ptr<PointEvaluator> evaluator;
  if (tape_)
  {
    evaluator = std::make_unique<PointEvaluator>(tape_);
  }
  const double f0 = evaluate(0.0, evaluator.get());
  const double f1 = evaluate(1.0, evaluator.get());
  const bool rising = f1 >= f0;
  // Work on a rising function g; clamp v to its values so the bisection has a root.
  const double sign = rising ? 1.0 : -1.0;
  const double target =
    std::clamp(sign * v, std::min(sign * f0, sign * f1), std::max(sign * f0, sign * f1));
  // The ends exactly: a steep end (sqrt(t) at 0) would otherwise leave a visible error.
  if (target == sign * f0)
  {
    return 0.0;
  }
  if (target == sign * f1)
  {
    return 1.0;
  }
  double lo = 0.0;
  double hi = 1.0;
  while (hi - lo > 1e-12)
  {
    const double mid = 0.5 * (lo + hi);
    if (sign * evaluate(mid, evaluator.get()) < target)
    {
      lo = mid;
    }
    else
    {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

double evaluate_curve(const Curve& curve, double u)
{
  const UnitCurve::Result r = UnitCurve::make(curve);
  return r.ok() ? r.curve(u) : std::nan("");
}

ChannelMap::Result ChannelMap::make(Interval range, const Curve& curve, Interval target)
{
  Result result;
  if (!std::isfinite(range.lo) || !std::isfinite(range.hi) || !std::isfinite(target.lo) ||
      !std::isfinite(target.hi))
  {
    result.error = "the range and target must be finite";
    return result;
  }
  if (range.lo == range.hi)
  {
    result.error = "the range has zero width";
    return result;
  }
  UnitCurve::Result c = UnitCurve::make(curve);
  if (!c.ok())
  {
    result.error = c.error;
    return result;
  }
  result.map.range_ = range;
  result.map.curve_ = std::move(c.curve);
  result.map.target_ = target;
  return result;
}

double ChannelMap::to_unit(double x) const
{
  return clamp_unit((x - range_.lo) / (range_.hi - range_.lo));
}

double ChannelMap::forward(double x) const
{
  return target_.lo + curve_(to_unit(x)) * (target_.hi - target_.lo);
}

double ChannelMap::inverse(double y) const
{
  if (target_.hi == target_.lo)
  {
    return range_.lo;
  }
  const double v = clamp_unit((y - target_.lo) / (target_.hi - target_.lo));
  return range_.lo + curve_.inverse(v) * (range_.hi - range_.lo);
}

} // namespace frep::mapping
