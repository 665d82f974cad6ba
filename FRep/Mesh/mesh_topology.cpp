#include "Mesh/mesh_topology.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace frep::mesh
{
namespace
{

// Union-find over points, for connected components.
struct Components
{
  std::vector<std::uint32_t> parent;
  explicit Components(std::size_t n)
    : parent(n)
  {
    std::iota(parent.begin(), parent.end(), 0u);
  }
  std::uint32_t find(std::uint32_t a)
  {
    while (parent[a] != a)
    {
      parent[a] = parent[parent[a]];
      a = parent[a];
    }
    return a;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// The loops of a contour (its segments joined by shared points) and the area each encloses
// (shoelace; the inside on the left of the segments).
std::vector<double> contour_loop_areas(const Surface& contour)
{
  Components components(contour.point_count());
  for (std::size_t c = 0; c + 1 < contour.cells.size(); c += 2)
  {
    components.join(contour.cells[c], contour.cells[c + 1]);
  }
  std::vector<double> twice(contour.point_count(), 0.0);
  std::vector<unsigned char> root(contour.point_count(), 0);
  for (std::size_t c = 0; c + 1 < contour.cells.size(); c += 2)
  {
    const double* p = &contour.points[3 * contour.cells[c]];
    const double* q = &contour.points[3 * contour.cells[c + 1]];
    const std::uint32_t r = components.find(contour.cells[c]);
    twice[r] += p[0] * q[1] - q[0] * p[1];
    root[r] = 1;
  }
  std::vector<double> areas;
  for (std::uint32_t p = 0; p < root.size(); ++p)
  {
    if (root[p])
      areas.push_back(0.5 * twice[p]);
  }
  return areas;
}

std::size_t count_slivers(const std::vector<double>& measures)
{
  double largest = 0.0;
  for (const double m : measures)
    largest = std::max(largest, std::abs(m));
  std::size_t slivers = 0;
  for (const double m : measures)
    slivers += std::abs(m) < sliver_fraction * largest ? 1 : 0;
  return slivers;
}

} // namespace

ShapeTopology shape_topology(const Surface& surface)
{
  if (surface.dimension != 3)
  {
    const std::vector<double> areas = contour_loop_areas(surface);
    return { areas.size(), 0, count_slivers(areas) };
  }
  const MeshTopology t = analyse_topology(surface);
  return { t.components, t.genus(), count_slivers(t.component_volumes) };
}

MeshTopology analyse_topology(const Surface& surface)
{
  MeshTopology t;
  const auto& x = surface.points;
  const auto& cells = surface.cells;
  t.triangles = cells.size() / 3;
  // Directed half-edges (from, to), sorted by their undirected edge.
  struct HalfEdge
  {
    std::uint32_t lo, hi;
    bool forward; // from == lo
  };
  std::vector<HalfEdge> half;
  half.reserve(cells.size());
  std::vector<unsigned char> used(surface.point_count(), 0);
  Components components(surface.point_count());
  std::vector<double> tet(t.triangles); // the signed volume of (origin, triangle)
  for (std::size_t f = 0; f < t.triangles; ++f)
  {
    const std::array<std::uint32_t, 3> v{ cells[3 * f], cells[3 * f + 1], cells[3 * f + 2] };
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
    {
      ++t.degenerate_triangles;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = v[static_cast<std::size_t>(k)];
      const std::uint32_t b = v[static_cast<std::size_t>((k + 1) % 3)];
      half.push_back({ std::min(a, b), std::max(a, b), a < b });
      used[a] = 1;
      components.join(a, b);
    }
    // Signed volume of the tetrahedron (origin, a, b, c) and the triangle's area.
    const double* a = &x[3 * v[0]];
    const double* b = &x[3 * v[1]];
    const double* c = &x[3 * v[2]];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
      u[0] * w[1] - u[1] * w[0] };
    t.area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    tet[f] = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
    t.signed_volume += tet[f];
  }
  std::sort(half.begin(), half.end(),
    [](const HalfEdge& p, const HalfEdge& q)
    { return p.lo != q.lo ? p.lo < q.lo : p.hi < q.hi; });
  for (std::size_t i = 0; i < half.size();)
  {
    std::size_t j = i;
    int forward = 0;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi)
    {
      forward += half[j].forward ? 1 : 0;
      ++j;
    }
    const std::size_t count = j - i;
    ++t.edges;
    if (count == 1)
    {
      ++t.boundary_edges;
    }
    else if (count > 2)
    {
      ++t.nonmanifold_edges;
    }
    else if (forward != 1)
    {
      ++t.misoriented_edges;
    }
    i = j;
  }
  for (std::uint32_t p = 0; p < used.size(); ++p)
  {
    if (used[p])
    {
      ++t.points;
      t.components += components.find(p) == p ? 1 : 0;
    }
  }
  t.euler_characteristic =
    static_cast<long long>(t.points) - static_cast<long long>(t.edges) + static_cast<long long>(t.triangles);
  // Each component's volume: its triangles' tetrahedra, summed at the component's root.
  std::vector<double> volume(surface.point_count(), 0.0);
  for (std::size_t f = 0; f < t.triangles; ++f)
  {
    volume[components.find(cells[3 * f])] += tet[f];
  }
  for (std::uint32_t p = 0; p < used.size(); ++p)
  {
    if (used[p] && components.find(p) == p)
      t.component_volumes.push_back(volume[p]);
  }
  return t;
}

} // namespace frep::mesh
