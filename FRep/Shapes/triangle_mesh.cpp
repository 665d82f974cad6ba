#include "Shapes/triangle_mesh.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace frep::shapes
{

MeshEdges count_edges(const TriangleMesh& mesh)
{
  MeshEdges result;
  // Undirected edge (low, high) -> uses in the direction low->high and high->low.
  struct Uses
  {
    std::uint32_t forward = 0;
    std::uint32_t backward = 0;
  };
  std::unordered_map<std::uint64_t, Uses> uses;
  uses.reserve(mesh.triangles.size());
  const std::size_t n = mesh.point_count();
  for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3)
  {
    const std::uint32_t v[3] = { mesh.triangles[t], mesh.triangles[t + 1], mesh.triangles[t + 2] };
    if (v[0] >= n || v[1] >= n || v[2] >= n)
    {
      continue;
    }
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
    {
      ++result.degenerate;
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = v[k];
      const std::uint32_t b = v[(k + 1) % 3];
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      Uses& u = uses[key];
      (a < b ? u.forward : u.backward) += 1;
    }
  }
  result.edges = uses.size();
  for (const auto& [key, u] : uses)
  {
    const std::uint32_t total = u.forward + u.backward;
    if (total == 1)
    {
      ++result.open;
    }
    else if (total > 2)
    {
      ++result.non_manifold;
    }
    else if (u.forward != 1)
    {
      ++result.misoriented;
    }
  }
  return result;
}

std::string validate(const TriangleMesh& mesh)
{
  if (mesh.points.size() % 3 != 0 || mesh.triangles.size() % 3 != 0)
  {
    return "the point or triangle array is not a multiple of 3 long";
  }
  if (mesh.triangles.empty())
  {
    return "the mesh has no triangle";
  }
  const std::size_t n = mesh.point_count();
  for (std::uint32_t id : mesh.triangles)
  {
    if (id >= n)
    {
      return "a triangle refers to point " + std::to_string(id) + " of " + std::to_string(n);
    }
  }
  for (double c : mesh.points)
  {
    if (!std::isfinite(c))
    {
      return "the mesh has a non-finite coordinate";
    }
  }
  return {};
}

std::string describe_open(const MeshEdges& e)
{
  if (e.closed())
  {
    return {};
  }
  return "the mesh is not closed and consistently oriented: " + std::to_string(e.open) +
    " open edges, " + std::to_string(e.non_manifold) + " non-manifold edges, " +
    std::to_string(e.misoriented) + " inconsistently oriented edges (of " +
    std::to_string(e.edges) + ")";
}

} // namespace frep::shapes
