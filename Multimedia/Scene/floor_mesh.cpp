#include "Scene/floor_mesh.h"

#include <cmath>

namespace frep::mapping
{
namespace
{

void add_quad(OwnedMesh& m, const std::array<std::array<double, 3>, 4>& corners,
  const std::array<float, 3>& colour)
{
  const auto base = static_cast<std::uint32_t>(m.points.size() / 3);
  for (const auto& c : corners)
  {
    m.points.insert(m.points.end(), c.begin(), c.end());
    m.normals.insert(m.normals.end(), { 0.0F, 0.0F, 1.0F });
    m.colours.insert(m.colours.end(), colour.begin(), colour.end());
  }
  m.triangles.insert(m.triangles.end(), { base, base + 1, base + 2, base, base + 2, base + 3 });
}

} // namespace

render::MeshInput OwnedMesh::input(const std::array<float, 3>& colour, double opacity) const
{
  render::MeshInput in;
  in.points = points;
  in.triangles = triangles;
  in.normals = normals;
  in.colours = colours;
  in.colour = colour;
  in.opacity = opacity;
  return in;
}

OwnedMesh floor_board(const raycast::Floor& f)
{
  OwnedMesh m;
  const double z = f.height;
  for (int j = 0; j < f.rows; ++j)
  {
    for (int i = 0; i < f.columns; ++i)
    {
      const double x0 = f.origin[0] + i * f.square, y0 = f.origin[1] + j * f.square;
      const double x1 = x0 + f.square, y1 = y0 + f.square;
      add_quad(m, { { { x0, y0, z }, { x1, y0, z }, { x1, y1, z }, { x0, y1, z } } },
        (i + j) % 2 == 0 ? f.dark : f.light);
    }
  }
  // The path: one quad per segment, half its width to each side, raised so it wins the depth
  // test against the board without visibly floating.
  const double lift = 1e-3 * f.square, r = 0.5 * f.path_width;
  for (std::size_t p = 0; p + 3 < f.path.size(); p += 2)
  {
    const double ax = f.path[p], ay = f.path[p + 1], bx = f.path[p + 2], by = f.path[p + 3];
    const double dx = bx - ax, dy = by - ay, len = std::hypot(dx, dy);
    if (!(len > 0.0))
    {
      continue;
    }
    // Extended by r at both ends, so that consecutive segments overlap at the joints.
    const double ux = dx / len * r, uy = dy / len * r, nx = -uy, ny = ux;
    add_quad(m,
      { { { ax - ux + nx, ay - uy + ny, z + lift },
        { ax - ux - nx, ay - uy - ny, z + lift },
        { bx + ux - nx, by + uy - ny, z + lift },
        { bx + ux + nx, by + uy + ny, z + lift } } },
      f.path_colour);
  }
  return m;
}

OwnedMesh floor_shadow(const raycast::Floor& f,
  const mesh::Surface& surface,
  const imaging::Camera& camera,
  const imaging::RenderStyle& style)
{
  OwnedMesh m;
  if (style.lights.empty() || surface.dimension != 3)
  {
    return m;
  }
  // The key light in world space (camera coordinates: x right, y up, z towards the camera).
  const imaging::CameraFrame frame = imaging::camera_frame(camera);
  const auto& d = style.lights.front().direction;
  std::array<double, 3> l;
  for (int k = 0; k < 3; ++k)
  {
    l[k] = d[0] * frame.right[k] + d[1] * frame.up[k] - d[2] * frame.forward[k];
  }
  if (!(l[2] > 1e-6))
  {
    return m;
  }
  // Each triangle flattened, then clipped to the board (Sutherland-Hodgman on its four edges),
  // so the shadow falls on the board only, as the ray caster's does.
  const double z = f.height + 2e-3 * f.square;
  const double bx0 = f.origin[0], bx1 = f.origin[0] + f.columns * f.square;
  const double by0 = f.origin[1], by1 = f.origin[1] + f.rows * f.square;
  using P2 = std::array<double, 2>;
  const auto flat = [&](std::uint32_t i) -> P2
  {
    const double* p = surface.points.data() + 3 * static_cast<std::size_t>(i);
    const double t = (p[2] - z) / l[2];
    return { p[0] - t * l[0], p[1] - t * l[1] };
  };
  std::vector<P2> poly, next;
  for (std::size_t t = 0; t + 2 < surface.cells.size(); t += 3)
  {
    poly = { flat(surface.cells[t]), flat(surface.cells[t + 1]), flat(surface.cells[t + 2]) };
    for (int edge = 0; edge < 4 && !poly.empty(); ++edge)
    {
      const int axis = edge / 2;
      const double bound = edge == 0 ? bx0 : edge == 1 ? bx1 : edge == 2 ? by0 : by1;
      const double sign = edge % 2 ? -1.0 : 1.0; // inside: sign * (p - bound) >= 0
      next.clear();
      for (std::size_t i = 0; i < poly.size(); ++i)
      {
        const P2& a = poly[i];
        const P2& b = poly[(i + 1) % poly.size()];
        const double da = sign * (a[axis] - bound), db = sign * (b[axis] - bound);
        if (da >= 0.0)
        {
          next.push_back(a);
        }
        if ((da >= 0.0) != (db >= 0.0))
        {
          const double w = da / (da - db);
          next.push_back({ a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]) });
        }
      }
      poly.swap(next);
    }
    if (poly.size() < 3)
    {
      continue;
    }
    const auto base = static_cast<std::uint32_t>(m.points.size() / 3);
    for (const P2& p : poly)
    {
      m.points.insert(m.points.end(), { p[0], p[1], z });
      m.normals.insert(m.normals.end(), { 0.0F, 0.0F, 1.0F });
    }
    for (std::uint32_t k = 1; k + 1 < poly.size(); ++k)
    {
      m.triangles.insert(m.triangles.end(), { base, base + k, base + k + 1 });
    }
  }
  return m;
}

} // namespace frep::mapping
