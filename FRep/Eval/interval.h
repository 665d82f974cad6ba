// A closed interval of doubles, possibly unbounded; the whole real line means "unknown".
#pragma once

#include <limits>

namespace frep
{

struct Interval
{
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();

  static Interval point(double v) { return {v, v}; }
  static Interval everything() { return {}; }
  bool contains(double v) const { return lo <= v && v <= hi; }
};

} // namespace frep
