#include "Mapping/path.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace frep::mapping
{
namespace
{

using Point = std::vector<double>;

double distance(const Point& a, const Point& b)
{
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    d += (a[i] - b[i]) * (a[i] - b[i]);
  }
  return std::sqrt(d);
}

Point lerp(const Point& a, const Point& b, double wa, double wb)
{
  Point p(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    p[i] = wa * a[i] + wb * b[i];
  }
  return p;
}

// 2 p - q: the mirror image of q through p, the neighbour an end of an open path lacks.
Point reflect(const Point& p, const Point& q)
{
  return lerp(p, q, 2.0, -1.0);
}

// Centripetal Catmull-Rom (alpha 0.5) on p1 -> p2 by the Barry-Goldman pyramid: no cusps or
// self-intersections within a segment, unlike the uniform variant on uneven spacing.
Point catmull_rom(const Point& p0, const Point& p1, const Point& p2, const Point& p3, double u)
{
  const double t0 = 0.0;
  const double t1 = t0 + std::sqrt(distance(p0, p1));
  const double t2 = t1 + std::sqrt(distance(p1, p2));
  const double t3 = t2 + std::sqrt(distance(p2, p3));
  const double t = t1 + u * (t2 - t1);
  const Point a1 = lerp(p0, p1, (t1 - t) / (t1 - t0), (t - t0) / (t1 - t0));
  const Point a2 = lerp(p1, p2, (t2 - t) / (t2 - t1), (t - t1) / (t2 - t1));
  const Point a3 = lerp(p2, p3, (t3 - t) / (t3 - t2), (t - t2) / (t3 - t2));
  const Point b1 = lerp(a1, a2, (t2 - t) / (t2 - t0), (t - t0) / (t2 - t0));
  const Point b2 = lerp(a2, a3, (t3 - t) / (t3 - t1), (t - t1) / (t3 - t1));
  return lerp(b1, b2, (t2 - t) / (t2 - t1), (t - t1) / (t2 - t1));
}

} // namespace

SampledPath::Result SampledPath::make(const Path& path, int steps_per_segment)
{
  Result result;
  auto error = [&](std::string place, std::string message) {
    result.errors.push_back({ std::move(place), std::move(message) });
  };

  const std::size_t n = path.points.size();
  if (n < 2)
  {
    error("points", "at least 2 points are needed, found " + std::to_string(n));
    return result;
  }
  const std::size_t dimension =
    path.coordinates.empty() ? path.points.front().size() : path.coordinates.size();
  if (dimension == 0)
  {
    error("points", "the points have no values");
    return result;
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::string place = "points[" + std::to_string(k) + "]";
    if (path.points[k].size() != dimension)
    {
      error(place,
        std::to_string(path.points[k].size()) + " values, expected " + std::to_string(dimension) +
          (path.coordinates.empty() ? "" : " (one per path coordinate)"));
    }
    else if (!std::all_of(path.points[k].begin(),
               path.points[k].end(),
               [](double v) { return std::isfinite(v); }))
    {
      error(place, "the values must be finite numbers");
    }
  }
  if (!result.ok())
  {
    return result;
  }
  if (std::all_of(path.points.begin(),
        path.points.end(),
        [&](const Point& p) { return p == path.points.front(); }))
  {
    error("points", "every point is the same: the path has zero length");
    return result;
  }
  const std::size_t segments = path.closed ? n : n - 1;
  if (path.timing == Path::Timing::Keys)
  {
    const std::size_t expected = segments + 1;
    if (path.key_times.size() != expected)
    {
      error("key_times",
        std::to_string(path.key_times.size()) + " key times, expected " + std::to_string(expected) +
          (path.closed ? " (one per point, plus the return to the first point)"
                       : " (one per point)"));
    }
    else
    {
      for (std::size_t k = 0; k < expected; ++k)
      {
        if (!std::isfinite(path.key_times[k]) ||
            (k > 0 && !(path.key_times[k] > path.key_times[k - 1])))
        {
          error("key_times[" + std::to_string(k) + "]", "key times must increase strictly");
          break;
        }
      }
    }
  }
  else if (!path.key_times.empty())
  {
    error("key_times", "key times apply only with timing \"keys\"");
  }
  if (steps_per_segment < 1)
  {
    error("", "at least one sub-step per segment is needed");
  }
  if (!result.ok())
  {
    return result;
  }

  SampledPath& p = result.path;
  p.spec_ = path;
  p.dimension_ = dimension;
  p.segments_ = segments;
  p.steps_ = steps_per_segment;
  p.cumulative_.reserve(segments * steps_per_segment + 1);
  p.cumulative_.push_back(0.0);
  p.segment_start_.push_back(0.0);
  Point previous = p.segment_point(0, 0.0);
  for (std::size_t j = 0; j < segments; ++j)
  {
    for (int i = 1; i <= steps_per_segment; ++i)
    {
      const Point q = p.segment_point(j, static_cast<double>(i) / steps_per_segment);
      p.cumulative_.push_back(p.cumulative_.back() + distance(previous, q));
      previous = q;
    }
    p.segment_start_.push_back(p.cumulative_.back());
  }
  return result;
}

std::vector<double> SampledPath::control(std::ptrdiff_t k) const
{
  const auto n = static_cast<std::ptrdiff_t>(spec_.points.size());
  return spec_.points[static_cast<std::size_t>(((k % n) + n) % n)];
}

std::vector<double> SampledPath::segment_point(std::size_t j, double t) const
{
  const auto k = static_cast<std::ptrdiff_t>(j);
  const Point p1 = control(k);
  const Point p2 = control(k + 1);
  // Ends exactly on the control points, whatever the rounding of the formulas.
  if (t <= 0.0)
  {
    return p1;
  }
  if (t >= 1.0)
  {
    return p2;
  }
  if (spec_.interpolation == Path::Interpolation::Polyline || p1 == p2)
  {
    return lerp(p1, p2, 1.0 - t, t);
  }
  const auto last = static_cast<std::ptrdiff_t>(spec_.points.size()) - 1;
  // An open path's ends, and a neighbour that repeats its point, get the mirrored neighbour:
  // the pyramid needs distinct consecutive points, and the mirror keeps the end tangent along
  // the segment.
  Point p0 = (!spec_.closed && k == 0) ? reflect(p1, p2) : control(k - 1);
  Point p3 = (!spec_.closed && k + 1 == last) ? reflect(p2, p1) : control(k + 2);
  if (p0 == p1)
  {
    p0 = reflect(p1, p2);
  }
  if (p3 == p2)
  {
    p3 = reflect(p2, p1);
  }
  return catmull_rom(p0, p1, p2, p3, t);
}

std::vector<project::PathPiece> SampledPath::pieces() const
{
  std::vector<project::PathPiece> out;
  for (std::size_t j = 0; j < segments_; ++j)
  {
    // The cubic through the segment's points at u = 0, 1/3, 2/3, 1 (Lagrange, in powers of u).
    const std::vector<double> f0 = segment_point(j, 0.0), f1 = segment_point(j, 1.0 / 3.0);
    const std::vector<double> f2 = segment_point(j, 2.0 / 3.0), f3 = segment_point(j, 1.0);
    project::PathPiece piece(dimension_);
    for (std::size_t a = 0; a < dimension_; ++a)
      piece[a] = { f0[a], 0.5 * (-11 * f0[a] + 18 * f1[a] - 9 * f2[a] + 2 * f3[a]),
        4.5 * (2 * f0[a] - 5 * f1[a] + 4 * f2[a] - f3[a]),
        4.5 * (-f0[a] + 3 * f1[a] - 3 * f2[a] + f3[a]) };
    out.push_back(std::move(piece));
  }
  return out;
}

std::vector<double> SampledPath::point_at(double s) const
{
  if (segments_ == 0)
  {
    return {};
  }
  s = std::isnan(s) ? 0.0 : std::clamp(s, 0.0, 1.0);
  const double target = s * length();
  // Sub-step whose arc-length interval holds the target, then the curve parameter inside it
  // in proportion (the sub-steps are short enough for the speed to be constant within one).
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
  std::size_t k =
    it == cumulative_.begin() ? 0 : static_cast<std::size_t>(it - cumulative_.begin()) - 1;
  k = std::min(k, cumulative_.size() - 2);
  const double width = cumulative_[k + 1] - cumulative_[k];
  const double f = width > 0 ? std::clamp((target - cumulative_[k]) / width, 0.0, 1.0) : 0.0;
  const std::size_t j = k / static_cast<std::size_t>(steps_);
  const double i = static_cast<double>(k % static_cast<std::size_t>(steps_));
  return segment_point(j, (i + f) / steps_);
}

double SampledPath::fraction_at_time(double t) const
{
  if (segments_ == 0)
  {
    return 0.0;
  }
  if (spec_.timing == Path::Timing::ArcLength)
  {
    return std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  }
  const std::vector<double>& keys = spec_.key_times;
  if (std::isnan(t) || t <= keys.front())
  {
    return 0.0;
  }
  if (t >= keys.back())
  {
    return 1.0;
  }
  const auto it = std::upper_bound(keys.begin(), keys.end(), t);
  const std::size_t j = static_cast<std::size_t>(it - keys.begin()) - 1;
  const double f = (t - keys[j]) / (keys[j + 1] - keys[j]);
  const double at = segment_start_[j] + f * (segment_start_[j + 1] - segment_start_[j]);
  return at / length();
}

std::vector<std::vector<double>> SampledPath::polyline(int n) const
{
  n = std::max(n, 2);
  std::vector<std::vector<double>> points;
  if (segments_ == 0)
  {
    return points;
  }
  points.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
  {
    points.push_back(point_at(static_cast<double>(k) / (n - 1)));
  }
  return points;
}

} // namespace frep::mapping
