#include "Mesh/detail/cube_topology.h"

#include <stdexcept>
#include <vector>

namespace frep::mesh
{
namespace
{

struct Vec3
{
  double x, y, z;
};

Vec3 operator-(Vec3 a, Vec3 b)
{
  return { a.x - b.x, a.y - b.y, a.z - b.z };
}
Vec3 cross(Vec3 a, Vec3 b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
double dot(Vec3 a, Vec3 b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

Vec3 corner_position(int c)
{
  return { double(corner_offset(c, 0)), double(corner_offset(c, 1)), double(corner_offset(c, 2)) };
}

Vec3 edge_midpoint(int e)
{
  Vec3 p = corner_position(edge_start(e));
  const int axis = edge_axis(e);
  (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = 0.5;
  return p;
}

Vec3 face_normal(int face)
{
  const double sign = face % 2 == 0 ? -1.0 : 1.0;
  const int axis = face / 2;
  return { axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, axis == 2 ? sign : 0.0 };
}

int edge_between(int c0, int c1)
{
  const int diff = c0 ^ c1;
  const int axis = diff == 1 ? 0 : diff == 2 ? 1 : 2;
  const int start = c0 & c1;
  const int k = corner_offset(start, (axis + 1) % 3) | (corner_offset(start, (axis + 2) % 3) << 1);
  return axis * 4 + k;
}

bool inside(std::uint8_t inside_corners, int c)
{
  return (inside_corners >> c) & 1;
}

bool edges_share_face(int e0, int e1)
{
  for (int f = 0; f < 6; ++f)
  {
    bool has0 = false;
    bool has1 = false;
    for (int i = 0; i < 4; ++i)
    {
      has0 = has0 || face_edge(f, i) == e0;
      has1 = has1 || face_edge(f, i) == e1;
    }
    if (has0 && has1)
    {
      return true;
    }
  }
  return false;
}

// Orients the segment between the crossings on edges ea and eb of `face` so that corner q
// (a corner the segment cuts off, or any inside corner of the face) lies on the correct side:
// an inside corner on the right seen from outside along the face's normal, an outside corner on
// the left. Returns {from, to}.
std::array<int, 2> orient_segment(int face, int ea, int eb, int q, bool q_inside)
{
  const Vec3 a = edge_midpoint(ea);
  const Vec3 b = edge_midpoint(eb);
  const double side = dot(cross(b - a, corner_position(q) - a), face_normal(face));
  const bool keep = q_inside ? side < 0 : side > 0;
  return keep ? std::array<int, 2>{ ea, eb } : std::array<int, 2>{ eb, ea };
}

CellPolygons build_cell(std::uint8_t in, std::uint8_t connected)
{
  // Directed segments per crossing edge: next[from] = to.
  std::array<int, 12> next;
  next.fill(-1);
  for (int f = 0; f < 6; ++f)
  {
    std::array<int, 4> crossing_index{};
    int crossings = 0;
    for (int i = 0; i < 4; ++i)
    {
      if (inside(in, face_corner(f, i)) != inside(in, face_corner(f, (i + 1) % 4)))
      {
        crossing_index[static_cast<std::size_t>(crossings++)] = i;
      }
    }
    auto add = [&](std::array<int, 2> segment)
    {
      if (next[static_cast<std::size_t>(segment[0])] != -1)
      {
        throw std::logic_error("cube_topology: a crossing starts two segments");
      }
      next[static_cast<std::size_t>(segment[0])] = segment[1];
    };
    if (crossings == 2)
    {
      int q = -1;
      for (int i = 0; i < 4 && q < 0; ++i)
      {
        q = inside(in, face_corner(f, i)) ? face_corner(f, i) : -1;
      }
      add(orient_segment(f, face_edge(f, crossing_index[0]), face_edge(f, crossing_index[1]), q,
        true));
    }
    else if (crossings == 4)
    {
      const bool join = (connected >> f) & 1;
      for (int i = 0; i < 4; ++i)
      {
        const int q = face_corner(f, i);
        const bool q_inside = inside(in, q);
        // Joined inside corners: cut off the outside ones; separated: cut off the inside ones.
        if (q_inside != join)
        {
          add(orient_segment(f, face_edge(f, (i + 3) % 4), face_edge(f, i), q, q_inside));
        }
      }
    }
  }

  CellPolygons cell;
  std::array<bool, 12> used{};
  int written = 0;
  for (int start = 0; start < 12; ++start)
  {
    if (next[static_cast<std::size_t>(start)] < 0 || used[static_cast<std::size_t>(start)])
    {
      continue;
    }
    std::vector<int> loop;
    for (int e = start; !used[static_cast<std::size_t>(e)]; e = next[static_cast<std::size_t>(e)])
    {
      used[static_cast<std::size_t>(e)] = true;
      loop.push_back(e);
      if (next[static_cast<std::size_t>(e)] < 0)
      {
        throw std::logic_error("cube_topology: open loop");
      }
    }
    if (loop.front() != next[static_cast<std::size_t>(loop.back())])
    {
      throw std::logic_error("cube_topology: loop does not close");
    }
    // A fan apex whose chords never join two crossings of one face; else a centre point.
    const int n = static_cast<int>(loop.size());
    int apex = -1;
    for (int r = 0; r < n && apex < 0; ++r)
    {
      bool ok = true;
      for (int j = 2; j <= n - 2 && ok; ++j)
      {
        ok = !edges_share_face(loop[static_cast<std::size_t>(r)],
          loop[static_cast<std::size_t>((r + j) % n)]);
      }
      apex = ok ? r : -1;
    }
    const int loop_index = cell.loop_count++;
    cell.loop_size[static_cast<std::size_t>(loop_index)] = static_cast<std::uint8_t>(n);
    if (apex < 0)
    {
      cell.centre_loops |= static_cast<std::uint8_t>(1u << loop_index);
      apex = 0;
    }
    for (int j = 0; j < n; ++j)
    {
      cell.edges[static_cast<std::size_t>(written++)] =
        static_cast<std::uint8_t>(loop[static_cast<std::size_t>((apex + j) % n)]);
    }
  }
  return cell;
}

FacePolygons build_cap(int face, std::uint8_t in, bool connected)
{
  std::vector<int> cycle;
  int crossings = 0;
  for (int i = 0; i < 4; ++i)
  {
    const int q = face_corner(face, i);
    const int q_next = face_corner(face, (i + 1) % 4);
    if (inside(in, q))
    {
      cycle.push_back(q);
    }
    if (inside(in, q) != inside(in, q_next))
    {
      cycle.push_back(8 + face_edge(face, i));
      ++crossings;
    }
  }
  FacePolygons cap;
  if (crossings == 4 && !connected)
  {
    // Two corner triangles: crossing before the inside corner, the corner, crossing after it.
    const int n = static_cast<int>(cycle.size());
    int written = 0;
    for (int k = 0; k < n; ++k)
    {
      if (cycle[static_cast<std::size_t>(k)] < 8)
      {
        cap.polygon_size[cap.polygon_count++] = 3;
        cap.items[static_cast<std::size_t>(written++)] =
          static_cast<std::uint8_t>(cycle[static_cast<std::size_t>((k + n - 1) % n)]);
        cap.items[static_cast<std::size_t>(written++)] =
          static_cast<std::uint8_t>(cycle[static_cast<std::size_t>(k)]);
        cap.items[static_cast<std::size_t>(written++)] =
          static_cast<std::uint8_t>(cycle[static_cast<std::size_t>((k + 1) % n)]);
      }
    }
  }
  else if (cycle.size() >= 3)
  {
    cap.polygon_count = 1;
    cap.polygon_size[0] = static_cast<std::uint8_t>(cycle.size());
    for (std::size_t k = 0; k < cycle.size(); ++k)
    {
      cap.items[k] = static_cast<std::uint8_t>(cycle[k]);
    }
  }
  return cap;
}

struct Tables
{
  std::vector<CellPolygons> cells;   // [inside * 64 + connected]
  std::vector<FacePolygons> caps;    // [(face * 256 + inside) * 2 + connected]
  std::array<std::uint8_t, 256> ambiguous{};
  std::vector<SquareSegments> squares; // [inside * 2 + connected]

  Tables()
  {
    for (int in = 0; in < 256; ++in)
    {
      std::uint8_t mask = 0;
      for (int f = 0; f < 6; ++f)
      {
        const bool q0 = inside(static_cast<std::uint8_t>(in), face_corner(f, 0));
        const bool q1 = inside(static_cast<std::uint8_t>(in), face_corner(f, 1));
        const bool q2 = inside(static_cast<std::uint8_t>(in), face_corner(f, 2));
        const bool q3 = inside(static_cast<std::uint8_t>(in), face_corner(f, 3));
        if (q0 == q2 && q1 == q3 && q0 != q1)
        {
          mask |= static_cast<std::uint8_t>(1u << f);
        }
      }
      ambiguous[static_cast<std::size_t>(in)] = mask;
    }
    // build_cell reads connected's bit f only for an ambiguous face f (four crossings): the
    // other bits give the same cell, so each is built once and copied (16384 builds were ~15 ms,
    // most of meshing a sphere at 256^3 in a fresh process).
    cells.resize(256 * 64);
    for (int in = 0; in < 256; ++in)
    {
      for (int c = 0; c < 64; ++c)
      {
        const int canonical = c & ambiguous[static_cast<std::size_t>(in)];
        cells[static_cast<std::size_t>(in * 64 + c)] = canonical == c
          ? build_cell(static_cast<std::uint8_t>(in), static_cast<std::uint8_t>(c))
          : cells[static_cast<std::size_t>(in * 64 + canonical)];
      }
    }
    caps.resize(6 * 256 * 2);
    for (int f = 0; f < 6; ++f)
    {
      for (int in = 0; in < 256; ++in)
      {
        for (int c = 0; c < 2; ++c)
        {
          caps[static_cast<std::size_t>((f * 256 + in) * 2 + c)] =
            build_cap(f, static_cast<std::uint8_t>(in), c != 0);
        }
      }
    }
    squares.resize(16 * 2);
    for (int in = 0; in < 16; ++in)
    {
      for (int c = 0; c < 2; ++c)
      {
        squares[static_cast<std::size_t>(in * 2 + c)] =
          build_square(static_cast<std::uint8_t>(in), c != 0);
      }
    }
  }

  // Square corners 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1); counter-clockwise cycle 0, 1, 3, 2
  // with edges 0, 1, 2, 3 between consecutive corners.
  static SquareSegments build_square(std::uint8_t in, bool connected)
  {
    static constexpr std::array<int, 4> cycle{ 0, 1, 3, 2 };
    static constexpr std::array<std::array<double, 2>, 4> corner{ { { 0, 0 }, { 1, 0 }, { 0, 1 },
      { 1, 1 } } };
    static constexpr std::array<std::array<double, 2>, 4> midpoint{ { { 0.5, 0 }, { 1, 0.5 },
      { 0.5, 1 }, { 0, 0.5 } } };
    auto is_in = [&](int c) { return ((in >> c) & 1) != 0; };
    // Inside on the left: cross(b - a, q - a) > 0 for an inside corner q.
    auto oriented = [&](int ea, int eb, int q, bool q_inside)
    {
      const auto& a = midpoint[static_cast<std::size_t>(ea)];
      const auto& b = midpoint[static_cast<std::size_t>(eb)];
      const auto& p = corner[static_cast<std::size_t>(q)];
      const double z = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
      const bool keep = q_inside ? z > 0 : z < 0;
      return keep ? std::array<std::uint8_t, 2>{ std::uint8_t(ea), std::uint8_t(eb) }
                  : std::array<std::uint8_t, 2>{ std::uint8_t(eb), std::uint8_t(ea) };
    };
    std::array<int, 4> crossing{};
    int crossings = 0;
    for (int i = 0; i < 4; ++i)
    {
      if (is_in(cycle[static_cast<std::size_t>(i)]) != is_in(cycle[static_cast<std::size_t>((i + 1) % 4)]))
      {
        crossing[static_cast<std::size_t>(crossings++)] = i;
      }
    }
    SquareSegments s;
    if (crossings == 2)
    {
      int q = -1;
      for (int i = 0; i < 4 && q < 0; ++i)
      {
        q = is_in(i) ? i : -1;
      }
      s.segments[s.count++] = oriented(crossing[0], crossing[1], q, true);
    }
    else if (crossings == 4)
    {
      for (int i = 0; i < 4; ++i)
      {
        const int q = cycle[static_cast<std::size_t>(i)];
        if (is_in(q) != connected)
        {
          s.segments[s.count++] = oriented((i + 3) % 4, i, q, is_in(q));
        }
      }
    }
    return s;
  }
};

const Tables& tables()
{
  static const Tables instance; // immutable after construction (thread-safe static init)
  return instance;
}

} // namespace

int face_corner(int face, int i)
{
  const int axis = face / 2;
  const int side = face % 2;
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  // (u, v) = (0,0), (1,0), (1,1), (0,1) is counter-clockwise about +e_axis; reversed for side 0.
  static constexpr std::array<std::array<int, 2>, 4> ccw{ { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } };
  const auto& uv = ccw[static_cast<std::size_t>(side == 1 ? i : (4 - i) % 4)];
  return (side << axis) | (uv[0] << u) | (uv[1] << v);
}

int face_edge(int face, int i)
{
  return edge_between(face_corner(face, i), face_corner(face, (i + 1) % 4));
}

std::uint8_t ambiguous_faces(std::uint8_t inside_corners)
{
  return tables().ambiguous[inside_corners];
}

const CellPolygons& cell_polygons(std::uint8_t inside_corners, std::uint8_t connected_faces)
{
  return tables().cells[static_cast<std::size_t>(inside_corners) * 64 + (connected_faces & 63u)];
}

const FacePolygons& face_cap(int face, std::uint8_t inside_corners, bool connected)
{
  return tables().caps[static_cast<std::size_t>((face * 256 + inside_corners) * 2 + (connected ? 1 : 0))];
}

const SquareSegments& square_segments(std::uint8_t inside_corners, bool connected)
{
  return tables().squares[static_cast<std::size_t>((inside_corners & 15u) * 2 + (connected ? 1 : 0))];
}

} // namespace frep::mesh
