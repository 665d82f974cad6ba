#include "Morph/timing.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace frep::morph
{

std::optional<Timing> timing_from_name(std::string_view name)
{
  if (name == "linear")
    return Timing{ TimingCurve::Linear, 0.0 };
  if (name == "ease")
    return Timing{ TimingCurve::Ease, 0.0 };
  if (name == "ease-in")
    return Timing{ TimingCurve::EaseIn, 0.0 };
  if (name == "ease-out")
    return Timing{ TimingCurve::EaseOut, 0.0 };
  if (name == "hold")
    return Timing{ TimingCurve::Hold, 0.5 };
  constexpr std::string_view prefix = "hold:";
  if (!name.starts_with(prefix))
    return std::nullopt;
  const std::string_view number = name.substr(prefix.size());
  double hold = -1.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), hold);
  if (error != std::errc() || end != number.data() + number.size() || !(hold >= 0.0) ||
      !(hold < 1.0))
    return std::nullopt;
  return Timing{ TimingCurve::Hold, hold };
}

std::string timing_name(const Timing& timing)
{
  switch (timing.curve)
  {
    case TimingCurve::Linear:
      return "linear";
    case TimingCurve::Ease:
      return "ease";
    case TimingCurve::EaseIn:
      return "ease-in";
    case TimingCurve::EaseOut:
      return "ease-out";
    case TimingCurve::Hold:
      break;
  }
  char text[32];
  std::snprintf(text, sizeof text, "hold:%g", timing.hold);
  return text;
}

// Each written as weight_text writes it, so the text and this agree operation for operation.
double timing_curve(const Timing& timing, double u)
{
  switch (timing.curve)
  {
    case TimingCurve::Linear:
      return u;
    case TimingCurve::Ease:
      return u * u * (3.0 - 2.0 * u);
    case TimingCurve::EaseIn:
      return u * u;
    case TimingCurve::EaseOut:
      return u * (2.0 - u);
    case TimingCurve::Hold:
      break;
  }
  return std::min(std::max((u - timing.hold / 2.0) / (1.0 - timing.hold), 0.0), 1.0);
}

double timed_parameter(const Timing& timing, int nodes, double t)
{
  if (timing.curve == TimingCurve::Linear || !(t > 0.0 && t < 1.0))
    return t;
  const double last = static_cast<double>(nodes - 1);
  const double s = t * last;
  const double i = std::min(std::floor(s), last - 1.0);
  return (i + timing_curve(timing, s - i)) / last;
}

} // namespace frep::morph
