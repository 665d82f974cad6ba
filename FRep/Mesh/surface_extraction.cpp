// extract_surface: interval-culled boxes, batch sampling of the boxes that may hold the
// surface, marching cubes with per-face decisions (Mesh/detail/cube_topology.h) and caps on the
// box.
#include "Mesh/detail/cube_topology.h"
#include "Mesh/detail/extraction_common.h"
#include "Mesh/surface.h"

#include <algorithm>
#include <cmath>

namespace frep::mesh
{
namespace
{

using detail::CellBox;
using detail::GridFrame;
using detail::Piece;

// Keeps crossings off the grid vertices: a value exactly at the iso level would otherwise put
// several crossings at one position and make zero-area triangles.
constexpr double crossing_margin = 1e-3;

double crossing_parameter(double g0, double g1)
{
  const double t = g0 / (g0 - g1);
  if (!std::isfinite(t))
  {
    return 0.5; // one end failed (NaN): no better guess
  }
  return std::clamp(t, crossing_margin, 1.0 - crossing_margin);
}

/// Decision on an ambiguous face: its inside corners are joined across it when the product of
/// their values exceeds the product of the outside ones (the asymptotic decider: the bilinear
/// interpolant's saddle is inside). Depends only on the face's four values, so both cells of the
/// face decide alike; ties and NaN separate.
bool joined(double in0, double in1, double out0, double out1)
{
  return in0 * in1 > out0 * out1;
}

class SurfaceWalker final : public detail::BoxWalker
{
public:
  using BoxWalker::BoxWalker;

private:
  std::array<double, 3> vertex_position(std::int64_t i, std::int64_t j, std::int64_t k) const
  {
    return { frame_.coord(0, i), frame_.coord(1, j), frame_.coord(2, k) };
  }

  // Faces of cell (i, j, k) on the boundary of the grid, as a bit per face.
  std::uint8_t boundary_faces(std::int64_t i, std::int64_t j, std::int64_t k) const
  {
    const std::array<std::int64_t, 3> c{ i, j, k };
    std::uint8_t faces = 0;
    for (int a = 0; a < 3; ++a)
    {
      faces |= static_cast<std::uint8_t>((c[a] == 0 ? 1u : 0u) << (2 * a));
      faces |= static_cast<std::uint8_t>((c[a] == frame_.cells(a) - 1 ? 1u : 0u) << (2 * a + 1));
    }
    return faces;
  }

  void leaf(const CellBox& box) override
  {
    const std::vector<double>& samples = values();
    const std::int64_t n0 = box.c1[0] - box.c0[0] + 1;
    const std::int64_t n1 = box.c1[1] - box.c0[1] + 1;
    const std::array<std::int64_t, 8> corner_offset_index{ 0, 1, n0, n0 + 1, n0 * n1,
      n0 * n1 + 1, n0 * n1 + n0, n0 * n1 + n0 + 1 };
    std::array<double, 8> g{};
    for (std::int64_t k = box.c0[2]; k < box.c1[2]; ++k)
    {
      for (std::int64_t j = box.c0[1]; j < box.c1[1]; ++j)
      {
        const std::int64_t row = n0 * ((j - box.c0[1]) + n1 * (k - box.c0[2]));
        for (std::int64_t i = box.c0[0]; i < box.c1[0]; ++i)
        {
          const std::int64_t base = row + (i - box.c0[0]);
          std::uint8_t in = 0;
          for (int c = 0; c < 8; ++c)
          {
            g[c] = samples[static_cast<std::size_t>(base + corner_offset_index[c])];
            in |= static_cast<std::uint8_t>((g[c] >= 0.0 ? 1u : 0u) << c);
          }
          if (in == 0)
          {
            continue;
          }
          const std::uint8_t caps = options_.cap_boundary ? boundary_faces(i, j, k) : 0;
          if (in == 255 && caps == 0)
          {
            continue;
          }
          polygonise_cell(i, j, k, in, g, caps);
        }
      }
    }
  }

  std::uint8_t decide_faces(std::uint8_t in, const std::array<double, 8>& g) const
  {
    std::uint8_t connected = 0;
    const std::uint8_t ambiguous = ambiguous_faces(in);
    for (int f = 0; f < 6; ++f)
    {
      if ((ambiguous >> f) & 1)
      {
        const int q0 = face_corner(f, 0);
        const int q1 = face_corner(f, 1);
        const int q2 = face_corner(f, 2);
        const int q3 = face_corner(f, 3);
        const bool q0_inside = (in >> q0) & 1;
        const bool join = q0_inside ? joined(g[q0], g[q2], g[q1], g[q3])
                                    : joined(g[q1], g[q3], g[q0], g[q2]);
        connected |= static_cast<std::uint8_t>((join ? 1u : 0u) << f);
      }
    }
    return connected;
  }

  std::uint32_t crossing(std::int64_t i, std::int64_t j, std::int64_t k, int edge,
    const std::array<double, 8>& g)
  {
    const int start = edge_start(edge);
    const int axis = edge_axis(edge);
    const std::int64_t vi = i + corner_offset(start, 0);
    const std::int64_t vj = j + corner_offset(start, 1);
    const std::int64_t vk = k + corner_offset(start, 2);
    return builder_.point(frame_.key(vi, vj, vk, axis),
      [&]
      {
        std::array<std::int64_t, 3> v{ vi, vj, vk };
        std::array<double, 3> p = vertex_position(vi, vj, vk);
        const double t = crossing_parameter(g[start], g[edge_end(edge)]);
        const double a = frame_.coord(axis, v[axis]);
        const double b = frame_.coord(axis, v[axis] + 1);
        p[axis] = a + t * (b - a);
        return p;
      });
  }

  std::uint32_t corner_point(std::int64_t i, std::int64_t j, std::int64_t k)
  {
    return builder_.point(frame_.key(i, j, k, 3), [&] { return vertex_position(i, j, k); });
  }

  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
  {
    auto& cells = builder_.piece().cells;
    cells.push_back(a);
    cells.push_back(b);
    cells.push_back(c);
  }

  void polygonise_cell(std::int64_t i, std::int64_t j, std::int64_t k, std::uint8_t in,
    const std::array<double, 8>& g, std::uint8_t caps)
  {
    const std::uint8_t connected = decide_faces(in, g);
    if (in != 255)
    {
      const CellPolygons& polygons = cell_polygons(in, connected);
      std::size_t first = 0;
      for (int l = 0; l < polygons.loop_count; ++l)
      {
        const int n = polygons.loop_size[static_cast<std::size_t>(l)];
        std::array<std::uint32_t, 12> ids{};
        for (int q = 0; q < n; ++q)
        {
          ids[static_cast<std::size_t>(q)] =
            crossing(i, j, k, polygons.edges[first + static_cast<std::size_t>(q)], g);
        }
        first += static_cast<std::size_t>(n);
        if ((polygons.centre_loops >> l) & 1)
        {
          std::array<double, 3> centre{};
          const auto& points = builder_.piece().points;
          for (int q = 0; q < n; ++q)
          {
            for (int a = 0; a < 3; ++a)
            {
              centre[a] += points[3 * ids[static_cast<std::size_t>(q)] + static_cast<std::size_t>(a)];
            }
          }
          for (double& c : centre)
          {
            c /= n;
          }
          const std::uint32_t middle = builder_.unshared_point(centre);
          for (int q = 0; q < n; ++q)
          {
            triangle(ids[static_cast<std::size_t>(q)], ids[static_cast<std::size_t>((q + 1) % n)], middle);
          }
        }
        else
        {
          for (int q = 1; q + 1 < n; ++q)
          {
            triangle(ids[0], ids[static_cast<std::size_t>(q)], ids[static_cast<std::size_t>(q + 1)]);
          }
        }
      }
    }
    for (int f = 0; f < 6; ++f)
    {
      if ((caps >> f) & 1)
      {
        cap_face(i, j, k, f, face_cap(f, in, (connected >> f) & 1), g);
      }
    }
  }

  void cap_face(std::int64_t i, std::int64_t j, std::int64_t k, int /*face*/,
    const FacePolygons& cap, const std::array<double, 8>& g)
  {
    std::size_t first = 0;
    for (int p = 0; p < cap.polygon_count; ++p)
    {
      const int n = cap.polygon_size[static_cast<std::size_t>(p)];
      std::array<std::uint32_t, 8> ids{};
      for (int q = 0; q < n; ++q)
      {
        const int item = cap.items[first + static_cast<std::size_t>(q)];
        ids[static_cast<std::size_t>(q)] = item < 8
          ? corner_point(i + corner_offset(item, 0), j + corner_offset(item, 1),
              k + corner_offset(item, 2))
          : crossing(i, j, k, item - 8, g);
      }
      first += static_cast<std::size_t>(n);
      // Cap polygons are convex (their points lie on the cell face's boundary, in order).
      for (int q = 1; q + 1 < n; ++q)
      {
        triangle(ids[0], ids[static_cast<std::size_t>(q)], ids[static_cast<std::size_t>(q + 1)]);
      }
    }
  }

  // A box proven inside: the parts of its faces on the grid's boundary are caps of whole cells.
  void inside_box(const CellBox& box) override
  {
    for (int f = 0; f < 6; ++f)
    {
      const int axis = f / 2;
      const bool high = f % 2 == 1;
      const std::int64_t at = high ? frame_.cells(axis) - 1 : 0;
      if ((high && box.c1[axis] != frame_.cells(axis)) || (!high && box.c0[axis] != 0))
      {
        continue;
      }
      CellBox face = box;
      face.c0[axis] = at;
      face.c1[axis] = at + 1;
      const FacePolygons& cap = face_cap(f, 255, false);
      const std::array<double, 8> g{}; // unused: a full cap has no crossings
      for (std::int64_t k = face.c0[2]; k < face.c1[2]; ++k)
      {
        for (std::int64_t j = face.c0[1]; j < face.c1[1]; ++j)
        {
          for (std::int64_t i = face.c0[0]; i < face.c1[0]; ++i)
          {
            cap_face(i, j, k, f, cap, g);
          }
        }
      }
    }
  }

};

} // namespace

ExtractResult extract_surface(std::shared_ptr<const Tape> tape,
  const GridSpec& grid,
  const ExtractOptions& options)
{
  return detail::run_extraction(tape, grid, 3, options,
    [&](const GridFrame& frame)
    { return std::make_unique<SurfaceWalker>(tape, frame, options); });
}

} // namespace frep::mesh
