// Test helpers: meshes built in code, and pictures for a human to look at.
#pragma once

#include "Imaging/image.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

namespace frep::render::test
{

struct TestMesh
{
  std::vector<double> points;
  std::vector<std::uint32_t> triangles;
  std::vector<float> normals;
  std::vector<float> colours;
};

/// A UV sphere, triangles wound counter-clockwise seen from outside; `bump` > 0 ripples the
/// radius (a more interesting picture; then no analytic normals are given).
inline TestMesh uv_sphere(int slices,
  int stacks,
  double radius = 1.0,
  double cx = 0.0,
  double cy = 0.0,
  double cz = 0.0,
  double bump = 0.0,
  bool normals = true)
{
  TestMesh m;
  const auto index = [&](int i, int j) { return static_cast<std::uint32_t>(i * (slices + 1) + j); };
  for (int i = 0; i <= stacks; ++i)
  {
    const double phi = std::numbers::pi * i / stacks;
    for (int j = 0; j <= slices; ++j)
    {
      const double theta = 2.0 * std::numbers::pi * j / slices;
      const double n[3] = {
        std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi)
      };
      const double r = radius * (1.0 + bump * std::sin(6.0 * theta) * std::sin(5.0 * phi));
      m.points.insert(m.points.end(), { cx + r * n[0], cy + r * n[1], cz + r * n[2] });
      if (normals && bump == 0.0)
      {
        m.normals.insert(m.normals.end(),
          { static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]) });
      }
      // A colour ramp over height, for pictures.
      const float t = static_cast<float>(0.5 * (1.0 + n[2]));
      m.colours.insert(
        m.colours.end(), { 0.85F * t + 0.05F, 0.25F + 0.35F * (1 - t), 0.9F - 0.7F * t });
    }
  }
  for (int i = 0; i < stacks; ++i)
  {
    for (int j = 0; j < slices; ++j)
    {
      const std::uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1),
                          d = index(i, j + 1);
      if (i != stacks - 1)
      {
        m.triangles.insert(m.triangles.end(), { a, b, c }); // not at the south pole (degenerate)
      }
      if (i != 0)
      {
        m.triangles.insert(m.triangles.end(), { a, c, d }); // not at the north pole
      }
    }
  }
  return m;
}

/// An axis-aligned square in the plane y = y0 (facing -y), centre (x, z), half size h.
inline TestMesh square_y(double y0, double x, double z, double h)
{
  TestMesh m;
  m.points = { x - h, y0, z - h, x + h, y0, z - h, x + h, y0, z + h, x - h, y0, z + h };
  m.triangles = { 0, 1, 2, 0, 2, 3 };
  return m;
}

/// When FREPKIT_RENDER_CHECK_DIR is set, the picture goes there as <name>.ppm (convert with
/// oiiotool to look at it). Returns the error of writing, empty when not asked or written.
inline std::string save_picture(const imaging::Image& image,
  const std::string& name,
  imaging::Rgba background = { 1, 1, 1, 1 })
{
  const char* dir = std::getenv("FREPKIT_RENDER_CHECK_DIR");
  if (!dir || !*dir)
  {
    return {};
  }
  return imaging::write_ppm(image, std::string(dir) + "/" + name + ".ppm", background);
}

} // namespace frep::render::test
