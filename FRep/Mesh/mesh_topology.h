// Checks of a triangle mesh's topology and measures of the solid it bounds: what tests, the
// command-line tool and benchmarks use to state that a mesh is closed, manifold and oriented.
#pragma once

#include "Mesh/surface.h"

#include <cstddef>

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

  /// Closed, every edge in exactly two triangles run in opposite directions.
  bool watertight_and_oriented() const
  {
    return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0 &&
      degenerate_triangles == 0;
  }
};

/// Analyses surface.cells as triangles (surface.dimension must be 3).
MeshTopology analyse_topology(const Surface& surface);

} // namespace frep::mesh
