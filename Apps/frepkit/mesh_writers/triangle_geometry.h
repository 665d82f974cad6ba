// Small geometry on the surface's triangles, shared by the writers.
#pragma once

#include "Mesh/surface.h"

#include <array>
#include <cmath>
#include <cstddef>

namespace frepkit
{

/// Corner `corner` (0..2) of triangle `t` as x, y, z.
inline std::array<double, 3> triangle_corner(const frep::mesh::Surface& surface,
  std::size_t t,
  int corner)
{
  const std::size_t p = surface.cells[3 * t + static_cast<std::size_t>(corner)];
  return { surface.points[3 * p], surface.points[3 * p + 1], surface.points[3 * p + 2] };
}

/// The unit normal of triangle t from its winding (counter-clockwise seen from outside), zero for
/// a degenerate triangle. STL wants facet normals; the points' normals are the model's gradient.
inline std::array<double, 3> facet_normal(const frep::mesh::Surface& surface, std::size_t t)
{
  const auto a = triangle_corner(surface, t, 0);
  const auto b = triangle_corner(surface, t, 1);
  const auto c = triangle_corner(surface, t, 2);
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  std::array<double, 3> n{
    u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]
  };
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (length > 0)
  {
    for (double& component : n)
    {
      component /= length;
    }
  }
  return n;
}

} // namespace frepkit
