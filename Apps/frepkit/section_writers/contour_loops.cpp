#include "contour_loops.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace frepkit
{
namespace
{

using Point = std::array<double, 2>;

struct Chain
{
  std::vector<Point> points;
  bool closed = false;
};

/// Follows unused segments from point `start` as long as there is one.
std::vector<Point> follow(std::uint32_t start,
  const frep::mesh::Surface& contour,
  std::vector<std::vector<std::uint32_t>>& outgoing,
  std::uint32_t& end)
{
  std::vector<Point> points;
  std::uint32_t p = start;
  points.push_back({ contour.points[3 * p], contour.points[3 * p + 1] });
  while (!outgoing[p].empty())
  {
    const std::uint32_t segment = outgoing[p].back();
    outgoing[p].pop_back();
    p = contour.cells[2 * segment + 1];
    points.push_back({ contour.points[3 * p], contour.points[3 * p + 1] });
  }
  end = p;
  return points;
}

double signed_area(const std::vector<Point>& loop)
{
  double twice = 0;
  for (std::size_t i = 0; i + 1 < loop.size(); ++i)
  {
    twice += loop[i][0] * loop[i + 1][1] - loop[i + 1][0] * loop[i][1];
  }
  return 0.5 * twice;
}

/// Position on the box perimeter, counter-clockwise from (xmin, ymin): [0, 4), one unit per
/// side; NaN when the point is not on the boundary.
double perimeter_position(const Point& p, const Point& lo, const Point& hi)
{
  const double w = hi[0] - lo[0];
  const double h = hi[1] - lo[1];
  const double tolerance = 1e-9 * std::max(w, h);
  const double d[4] = {
    std::abs(p[1] - lo[1]), std::abs(p[0] - hi[0]), std::abs(p[1] - hi[1]), std::abs(p[0] - lo[0])
  };
  const int side = static_cast<int>(std::min_element(d, d + 4) - d);
  if (d[side] > tolerance)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  switch (side)
  {
    case 0:
      return std::clamp((p[0] - lo[0]) / w, 0.0, 1.0);
    case 1:
      return 1.0 + std::clamp((p[1] - lo[1]) / h, 0.0, 1.0);
    case 2:
      return 2.0 + std::clamp((hi[0] - p[0]) / w, 0.0, 1.0);
    default:
      return std::fmod(3.0 + std::clamp((hi[1] - p[1]) / h, 0.0, 1.0), 4.0);
  }
}

} // namespace

std::vector<ContourLoop> close_contour_loops(const frep::mesh::Surface& contour,
  std::array<double, 2> lo,
  std::array<double, 2> hi,
  bool box_inside)
{
  const std::size_t point_count = contour.point_count();
  const std::size_t segment_count = contour.cell_count();
  std::vector<std::vector<std::uint32_t>> outgoing(point_count);
  std::vector<int> balance(point_count, 0); // outgoing - incoming
  for (std::uint32_t s = 0; s < segment_count; ++s)
  {
    const std::uint32_t a = contour.cells[2 * s];
    const std::uint32_t b = contour.cells[2 * s + 1];
    outgoing[a].push_back(s);
    ++balance[a];
    --balance[b];
  }

  // Open chains start where more segments leave than arrive (on the box boundary).
  std::vector<Chain> open;
  std::vector<ContourLoop> loops;
  for (std::uint32_t p = 0; p < point_count; ++p)
  {
    while (balance[p] > 0 && !outgoing[p].empty())
    {
      std::uint32_t end = 0;
      Chain chain;
      chain.points = follow(p, contour, outgoing, end);
      --balance[p];
      ++balance[end];
      open.push_back(std::move(chain));
    }
  }
  // What remains are closed loops.
  for (std::uint32_t p = 0; p < point_count; ++p)
  {
    while (!outgoing[p].empty())
    {
      std::uint32_t end = 0;
      ContourLoop loop;
      loop.points = follow(p, contour, outgoing, end);
      if (loop.points.front() != loop.points.back())
      {
        loop.points.push_back(loop.points.front());
      }
      loop.signed_area = signed_area(loop.points);
      loops.push_back(std::move(loop));
    }
  }

  // Close the open chains along the box, counter-clockwise from each end to the nearest start.
  const Point corners[4] = {
    { lo[0], lo[1] }, { hi[0], lo[1] }, { hi[0], hi[1] }, { lo[0], hi[1] }
  };
  std::vector<double> start_at(open.size());
  std::vector<double> end_at(open.size());
  for (std::size_t c = 0; c < open.size(); ++c)
  {
    start_at[c] = perimeter_position(open[c].points.front(), lo, hi);
    end_at[c] = perimeter_position(open[c].points.back(), lo, hi);
  }
  std::vector<bool> used(open.size(), false);
  for (std::size_t first = 0; first < open.size(); ++first)
  {
    if (used[first])
    {
      continue;
    }
    ContourLoop loop;
    std::size_t current = first;
    used[first] = true;
    loop.points = open[first].points;
    for (std::size_t guard = 0; guard <= open.size(); ++guard)
    {
      const double from = end_at[current];
      if (std::isnan(from))
      {
        break; // not on the boundary (should not happen): close straight back
      }
      // The next start counter-clockwise from here (the first chain itself included).
      std::size_t next = first;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t c = 0; c < open.size(); ++c)
      {
        if ((used[c] && c != first) || std::isnan(start_at[c]))
        {
          continue;
        }
        const double distance = std::fmod(start_at[c] - from + 4.0, 4.0);
        if (distance < best)
        {
          best = distance;
          next = c;
        }
      }
      if (std::isinf(best))
      {
        break;
      }
      // Box corners passed on the way.
      for (int k = 1; k <= 4; ++k)
      {
        const double corner_at = std::floor(from) + k;
        if (corner_at - from > 0 && corner_at - from < best)
        {
          loop.points.push_back(corners[static_cast<int>(corner_at) % 4]);
        }
      }
      if (next == first)
      {
        break;
      }
      used[next] = true;
      loop.points.insert(loop.points.end(), open[next].points.begin(), open[next].points.end());
      current = next;
    }
    loop.points.push_back(loop.points.front());
    loop.signed_area = signed_area(loop.points);
    loops.push_back(std::move(loop));
  }

  if (open.empty() && box_inside)
  {
    ContourLoop box;
    box.points = { corners[0], corners[1], corners[2], corners[3], corners[0] };
    box.signed_area = signed_area(box.points);
    loops.push_back(std::move(box));
  }
  return loops;
}

} // namespace frepkit
