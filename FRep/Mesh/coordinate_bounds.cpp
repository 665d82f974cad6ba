#include "Mesh/coordinate_bounds.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace frep::mesh
{
namespace
{

constexpr int kSpace = 3;         // x1..x3: what the sections are bounded in (rule 2)
constexpr int kMaxCornerAxes = 4; // beyond that, the centre only: 2^k + 1 searches

std::string search_box_text(const SolidBoundsOptions& options)
{
  const std::string s = std::to_string(static_cast<long long>(options.search));
  return "[-" + s + ", " + s + "]";
}

// Rule 2's points of x4..: the centre of their intervals, then each corner of the axes with
// `given` intervals (the others stay at the centre; an arbitrary fallback's corners are
// extrapolations nobody asked for), unless more than kMaxCornerAxes axes are given.
std::vector<std::vector<double>> section_points(const std::vector<Interval>& beyond,
  const std::vector<bool>& given)
{
  std::vector<double> centre;
  std::vector<std::size_t> axes;
  for (std::size_t k = 0; k < beyond.size(); ++k)
  {
    centre.push_back(0.5 * (beyond[k].lo + beyond[k].hi));
    if (given[k])
    {
      axes.push_back(k);
    }
  }
  std::vector<std::vector<double>> points{ centre };
  if (axes.empty() || axes.size() > kMaxCornerAxes)
  {
    return points;
  }
  for (std::size_t mask = 0; mask < (std::size_t{ 1 } << axes.size()); ++mask)
  {
    std::vector<double> corner = centre;
    for (std::size_t j = 0; j < axes.size(); ++j)
    {
      corner[axes[j]] = (mask >> j) & 1 ? beyond[axes[j]].hi : beyond[axes[j]].lo;
    }
    points.push_back(std::move(corner));
  }
  return points;
}

void widen(std::vector<Interval>& box, const std::vector<Interval>& more)
{
  if (box.empty())
  {
    box = more;
    return;
  }
  for (std::size_t k = 0; k < box.size(); ++k)
  {
    box[k] = { std::min(box[k].lo, more[k].lo), std::max(box[k].hi, more[k].hi) };
  }
}

// Rule 2: the union of the bounds of x1..x3 over the sections at `points` of x4.. (the centre
// first); empty when the centre's section is unbounded or every section is empty (`why` says
// which). A corner's unbounded section is left out and said in `why`.
std::vector<Interval> bound_sections(const Model& model,
  std::span<const double> parameters,
  const std::vector<std::vector<double>>& points,
  const SolidBoundsOptions& options,
  std::string& why)
{
  std::vector<Interval> box;
  std::size_t skipped = 0;
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    Specialisation section;
    section.parameters.assign(parameters.begin(), parameters.end());
    section.fixed.assign(kSpace, std::nullopt);
    section.fixed.insert(section.fixed.end(), points[p].begin(), points[p].end());
    const SolidBounds b = find_solid_bounds(model.specialise(section), options);
    if (b.status == SolidBounds::Status::Unbounded && p == 0)
    {
      why = "its section at the centre of x4..'s intervals reaches the edge of " +
            search_box_text(options);
      return {};
    }
    skipped += b.status == SolidBounds::Status::Unbounded ? 1 : 0;
    if (b.bounded())
    {
      widen(box, b.box);
    }
  }
  if (box.empty())
  {
    why = "every section of x1..x3 searched is empty";
  }
  else if (skipped > 0)
  {
    why = std::to_string(skipped) + " of the sections at the corners of x4..'s intervals " +
          "could not be bounded and were left out";
  }
  return box;
}

} // namespace

Interval readable(Interval axis)
{
  const double extent = axis.hi - axis.lo;
  if (!(extent > 0.0) || !std::isfinite(extent))
  {
    return axis;
  }
  // n / 10^d rather than n * 10^-d: the shortest decimal form of the result is then short.
  const double e = std::floor(std::log10(extent)) - 2.0;
  const double scale = std::pow(10.0, std::abs(e));
  const auto round = [e, scale](double v, bool up)
  {
    const double x = e < 0 ? v * scale : v / scale;
    const double n = up ? std::ceil(x) : std::floor(x);
    return e < 0 ? n / scale : n * scale;
  };
  return { round(axis.lo, false), round(axis.hi, true) };
}

CoordinateBounds find_coordinate_bounds(const Model& model,
  std::span<const double> parameters,
  std::span<const std::optional<Interval>> given,
  Interval fallback,
  const SolidBoundsOptions& options)
{
  if (!(fallback.lo < fallback.hi) || !std::isfinite(fallback.lo) || !std::isfinite(fallback.hi))
  {
    throw std::invalid_argument("coordinate bounds: the fallback must be finite with lo < hi");
  }
  const int n = model.x_dim();
  CoordinateBounds result;
  result.found.assign(n, false);
  for (int i = 0; i < n; ++i)
  {
    const bool has = static_cast<std::size_t>(i) < given.size() && given[i];
    result.ranges.push_back(has ? *given[i] : fallback);
  }
  const auto unranged = [&](int i)
  { return static_cast<std::size_t>(i) >= given.size() || !given[i]; };
  bool any_unranged = false;
  for (int i = 0; i < n; ++i)
  {
    any_unranged = any_unranged || unranged(i);
  }
  if (n == 0 || !any_unranged)
  {
    return result;
  }
  const auto take = [&](const std::vector<Interval>& box, int count)
  {
    for (int i = 0; i < count; ++i)
    {
      if (unranged(i))
      {
        result.ranges[i] = readable(box[i]);
        result.found[i] = true;
      }
    }
  };

  Specialisation whole;
  whole.parameters.assign(parameters.begin(), parameters.end());
  const SolidBounds all = find_solid_bounds(model.specialise(whole), options);
  if (all.bounded())
  {
    result.rule = CoordinateBounds::Rule::Whole;
    take(all.box, n);
    return result;
  }
  if (n <= kSpace)
  {
    result.note = all.status == SolidBounds::Status::Empty
                    ? "the solid is empty in " + search_box_text(options)
                    : "the solid reaches the edge of " + search_box_text(options) +
                        " (unbounded, or its intervals are too loose to tell)";
    return result;
  }
  const std::vector<Interval> beyond(result.ranges.begin() + kSpace, result.ranges.end());
  std::vector<bool> beyond_given;
  for (int i = kSpace; i < n; ++i)
  {
    beyond_given.push_back(!unranged(i));
  }
  std::string why;
  const std::vector<Interval> box =
    bound_sections(model, parameters, section_points(beyond, beyond_given), options, why);
  if (box.empty())
  {
    result.note = "the " + std::to_string(n) + "-D solid is not bounded in " +
                  search_box_text(options) + ", and " + why;
    return result;
  }
  result.rule = CoordinateBounds::Rule::Sections;
  take(box, kSpace);
  result.note = "the " + std::to_string(n) + "-D solid is not bounded in " +
                search_box_text(options) + ": x1..x3 bound its sections over x4..'s intervals" +
                (why.empty() ? "" : "; " + why);
  return result;
}

} // namespace frep::mesh
