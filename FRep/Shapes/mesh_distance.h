// Distance to a triangle mesh through a bounding-volume hierarchy: the closest point in
// O(log n) per query (not a loop over triangles), the sign from angle-weighted pseudonormals
// (Baerentzen & Aanaes 2005: exact for a closed, consistently oriented mesh), and enclosures
// over boxes from one query at the box's centre, so that meshing culls boxes far from the
// surface. Plain C++ (no VTK) so that frepkit reads STL/OBJ/PLY shapes in any build.
#pragma once

#include "Shapes/triangle_mesh.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace frep::shapes
{

class MeshDistance
{
public:
  struct BuildResult
  {
    std::shared_ptr<const MeshDistance> distance; ///< null on error
    std::string error;
    MeshEdges edges;
  };

  /// Builds the hierarchy. `signed_distance`: F = +d inside, -d outside, which needs a closed,
  /// consistently oriented mesh (else an error naming the open-edge count); otherwise
  /// F = -d everywhere (any triangle soup). Outward orientation is checked by the volume's sign;
  /// an inward mesh is flipped.
  static BuildResult build(TriangleMesh mesh, bool signed_distance);

  /// F at p (see build).
  double value(const std::array<double, 3>& p) const;
  /// F and its gradient (the unit direction from the closest point, signed).
  double value_and_gradient(const std::array<double, 3>& p, std::array<double, 3>& g) const;
  /// The unsigned distance.
  double distance(const std::array<double, 3>& p) const;
  /// An enclosure of F over the box [lo, hi]; false for an unbounded box.
  bool enclose(const std::array<double, 3>& lo, const std::array<double, 3>& hi, double& f_lo,
    double& f_hi) const;

  bool is_signed() const { return signed_; }
  std::array<double, 6> bounds() const; ///< xmin, ymin, zmin, xmax, ymax, zmax
  std::size_t triangle_count() const { return triangles_.size() / 3; }
  std::size_t node_count() const { return nodes_.size(); }
  bool flipped() const { return flipped_; }

private:
  struct Node
  {
    std::array<double, 3> lo;
    std::array<double, 3> hi;
    std::uint32_t first = 0; ///< leaf: first triangle in order_; inner: left child
    std::uint32_t count = 0; ///< leaf: triangles; inner: 0 (right child = left + 1... see cpp)
    std::uint32_t right = 0;
  };
  struct Closest
  {
    double d2 = 0;
    std::array<double, 3> point{};
    std::uint32_t triangle = 0;
    int feature = 0; ///< 0..2 vertex, 3..5 edge (k, k+1), 6 face
  };

  Closest closest(const std::array<double, 3>& p) const;
  double sign_at(const std::array<double, 3>& p, const Closest& c) const;
  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end,
    std::vector<std::array<double, 3>>& centroid);

  std::vector<double> points_;
  std::vector<std::uint32_t> triangles_;
  std::vector<std::uint32_t> order_; ///< triangles in leaf order
  std::vector<Node> nodes_;
  std::vector<std::array<double, 3>> face_normal_;
  std::vector<std::array<double, 3>> vertex_normal_;
  std::vector<std::array<double, 3>> edge_normal_; ///< 3 per triangle: edge (k, k+1)
  bool signed_ = true;
  bool flipped_ = false;
};

} // namespace frep::shapes
