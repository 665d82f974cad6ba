// Checks of a triangle mesh's topology and measures of the solid it bounds: what tests, the
// command-line tool and benchmarks use to state that a mesh is closed, manifold and oriented.
#pragma once

#include "Mesh/surface.h"

#include <cstddef>
#include <vector>

namespace frep::mesh
{

struct MeshTopology
{
  std::size_t triangles = 0;
  std::size_t points = 0;          ///< points used by some triangle
  std::size_t edges = 0;           ///< distinct undirected edges
  std::size_t boundary_edges = 0;  ///< edges of one triangle (holes)
  std::size_t nonmanifold_edges = 0; ///< edges of more than two triangles
  std::size_t misoriented_edges = 0; ///< two-triangle edges run the same way by both
  std::size_t degenerate_triangles = 0; ///< a point repeated in one triangle
  std::size_t components = 0;      ///< connected by shared edges
  long long euler_characteristic = 0; ///< V - E + F
  double signed_volume = 0;        ///< > 0 for a closed mesh oriented outward
  double area = 0;
  /// Each component's signed volume (the same order as nothing else: one entry per component).
  /// A cavity's shell, oriented inward, is negative.
  std::vector<double> component_volumes;

  /// The genus summed over the pieces, for a closed mesh: each closed piece has Euler
  /// characteristic 2 - 2g.
  long long genus() const { return static_cast<long long>(components) - euler_characteristic / 2; }

  /// Closed, every edge in exactly two triangles run in opposite directions.
  bool watertight_and_oriented() const
  {
    return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0 &&
      degenerate_triangles == 0;
  }
};

/// Analyses surface.cells as triangles (surface.dimension must be 3).
MeshTopology analyse_topology(const Surface& surface);

/// What a closed mesh or contour says of the shape it bounds, the figures a map of the topology
/// compares (Project/space_time.h's topology_events, the mapping's topology map).
struct ShapeTopology
{
  std::size_t components = 0; ///< connected pieces: closed surfaces (3-D), contour loops (2-D)
  /// 3-D: the genus summed over the pieces (MeshTopology::genus); 0 in 2-D, where a hole is a
  /// loop of its own.
  long long genus = 0;
  /// Pieces that enclose less than sliver_fraction of the largest piece's volume (area in 2-D):
  /// specks beside the shape. Not compared: a piece that shrinks is no change of topology.
  std::size_t slivers = 0;

  /// The same pieces and genus.
  friend bool operator==(const ShapeTopology& a, const ShapeTopology& b)
  {
    return a.components == b.components && a.genus == b.genus;
  }
};

/// What counts as a sliver: under 1% of the largest piece.
inline constexpr double sliver_fraction = 0.01;

/// The pieces and genus of a surface (dimension 3: triangles) or contour (2: segments). The
/// figures are exact for the closed, manifold meshes the mesher makes.
ShapeTopology shape_topology(const Surface& surface);

} // namespace frep::mesh
