#include "Project/path_pieces.h"

#include <cmath>

namespace frep::project
{
namespace
{

// Point k of the path (wrapped when closed, mirrored beyond an open path's ends), coordinate a.
double control(const std::vector<std::vector<double>>& p, bool closed, long k, std::size_t a)
{
  const long n = static_cast<long>(p.size());
  if (closed)
    return p[static_cast<std::size_t>((k % n + n) % n)][a];
  if (k < 0)
    return 2 * p[0][a] - p[1][a];
  if (k >= n)
    return 2 * p[static_cast<std::size_t>(n - 1)][a] - p[static_cast<std::size_t>(n - 2)][a];
  return p[static_cast<std::size_t>(k)][a];
}

std::vector<PathPiece> pieces(
  const std::vector<std::vector<double>>& points, bool closed, bool cubic)
{
  std::vector<PathPiece> out;
  if (points.size() < (closed ? 3u : 2u))
    return out;
  const std::size_t count = closed ? points.size() : points.size() - 1;
  for (std::size_t i = 0; i < count; ++i)
  {
    PathPiece piece(points[0].size());
    const long k = static_cast<long>(i);
    for (std::size_t a = 0; a < piece.size(); ++a)
    {
      const double q0 = control(points, closed, k - 1, a), q1 = control(points, closed, k, a);
      const double q2 = control(points, closed, k + 1, a), q3 = control(points, closed, k + 2, a);
      if (!cubic)
        piece[a] = { q1, q2 - q1, 0.0, 0.0 };
      else
        piece[a] = { q1, 0.5 * (q2 - q0), 0.5 * (2 * q0 - 5 * q1 + 4 * q2 - q3),
          0.5 * (-q0 + 3 * q1 - 3 * q2 + q3) };
    }
    out.push_back(std::move(piece));
  }
  return out;
}

} // namespace

std::vector<PathPiece> polyline_pieces(const std::vector<std::vector<double>>& points, bool closed)
{
  return pieces(points, closed, false);
}

std::vector<PathPiece> catmull_rom_pieces(
  const std::vector<std::vector<double>>& points, bool closed)
{
  return pieces(points, closed, true);
}

std::string path_pieces_error(const std::vector<PathPiece>& pieces, std::size_t coordinates)
{
  if (pieces.empty())
    return "a path needs at least one piece";
  for (std::size_t i = 0; i < pieces.size(); ++i)
  {
    if (pieces[i].size() != coordinates)
      return "path piece " + std::to_string(i + 1) + " has " + std::to_string(pieces[i].size()) +
             " coordinates, the path " + std::to_string(coordinates);
    for (const std::array<double, 4>& c : pieces[i])
      for (const double v : c)
        if (!std::isfinite(v))
          return "path piece " + std::to_string(i + 1) + " is not finite";
  }
  return {};
}

double piece_value(const std::array<double, 4>& c, double u)
{
  return c[0] + u * (c[1] + u * (c[2] + u * c[3]));
}

double piece_slope(const std::array<double, 4>& c, double u)
{
  return c[1] + u * (2 * c[2] + u * 3 * c[3]);
}

} // namespace frep::project
