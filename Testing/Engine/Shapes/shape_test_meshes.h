// Small meshes for the shape tests: a cube and a UV sphere, closed and outward.
#pragma once

#include "Shapes/triangle_mesh.h"

#include <cmath>
#include <numbers>

namespace frep::shapes::testing
{

inline TriangleMesh cube_mesh(double h)
{
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
  {
    m.points.insert(m.points.end(), { (i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h });
  }
  // Outward: counter-clockwise seen from outside.
  m.triangles = { 0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2,
    2, 4, 6, 1, 3, 5, 3, 7, 5 };
  return m;
}

inline TriangleMesh sphere_mesh(double r, int rings, int segments)
{
  TriangleMesh m;
  // push_back, not insert of a list: GCC 12 warns falsely (-Wstringop-overflow) on the latter.
  m.points.push_back(0);
  m.points.push_back(0);
  m.points.push_back(r);
  for (int i = 1; i < rings; ++i)
  {
    const double theta = std::numbers::pi * i / rings;
    for (int j = 0; j < segments; ++j)
    {
      const double phi = 2 * std::numbers::pi * j / segments;
      m.points.insert(m.points.end(),
        { r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta) });
    }
  }
  m.points.insert(m.points.end(), { 0, 0, -r });
  const auto id = [&](int ring, int j) { return static_cast<std::uint32_t>(1 + (ring - 1) * segments + (j % segments)); };
  const std::uint32_t south = static_cast<std::uint32_t>(m.point_count() - 1);
  for (int j = 0; j < segments; ++j)
  {
    m.triangles.insert(m.triangles.end(), { 0, id(1, j), id(1, j + 1) });
    for (int i = 1; i + 1 < rings; ++i)
    {
      m.triangles.insert(m.triangles.end(), { id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      m.triangles.insert(m.triangles.end(), { id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
    m.triangles.insert(m.triangles.end(), { id(rings - 1, j), south, id(rings - 1, j + 1) });
  }
  return m;
}

} // namespace frep::shapes::testing
