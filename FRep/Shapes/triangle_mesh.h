// A triangle mesh as plain arrays (what the readers produce and the distance structure takes),
// and the topology check that decides whether a signed distance means anything.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace frep::shapes
{

struct TriangleMesh
{
  std::vector<double> points;           ///< x, y, z per point
  std::vector<std::uint32_t> triangles; ///< three point ids per triangle
  std::size_t point_count() const { return points.size() / 3; }
  std::size_t triangle_count() const { return triangles.size() / 3; }
};

struct MeshEdges
{
  std::size_t edges = 0;         ///< distinct undirected edges
  std::size_t open = 0;          ///< used by one triangle
  std::size_t non_manifold = 0;  ///< used by more than two
  std::size_t misoriented = 0;   ///< used twice in the same direction (inconsistent winding)
  std::size_t degenerate = 0;    ///< triangles with a repeated point id
  bool closed() const { return open == 0 && non_manifold == 0 && misoriented == 0; }
};

/// Counts the edges by use. Point ids out of range are not counted (validate() reports them).
MeshEdges count_edges(const TriangleMesh& mesh);

/// Empty, or what is wrong with the arrays: sizes not multiples of 3, ids out of range,
/// non-finite coordinates, no triangle.
std::string validate(const TriangleMesh& mesh);

/// "the mesh is not closed: 12 open edges, 0 non-manifold edges, 0 inconsistently oriented
/// edges" — or empty when it is closed.
std::string describe_open(const MeshEdges& edges);

} // namespace frep::shapes
