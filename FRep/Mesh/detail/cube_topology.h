// The combinatorics of one grid cell: corners, edges and faces of the unit cube (and square),
// and the polygons marching cubes makes in a cell for each inside/outside pattern and each
// decision on the ambiguous faces. Computed once, from geometry, not typed in: every polygon is
// a closed loop of edge crossings, oriented outward, built from per-face segments; two cells
// sharing a face build the same segment there (same four values, same decision), which is what
// makes the surface watertight.
#pragma once

#include <array>
#include <cstdint>

namespace frep::mesh
{

/// Corner c of the unit cube is at ((c >> 0) & 1, (c >> 1) & 1, (c >> 2) & 1).
constexpr int corner_offset(int corner, int axis)
{
  return (corner >> axis) & 1;
}

/// Edge e runs along axis e / 4 from corner edge_start(e) to edge_start(e) | (1 << axis).
/// With u = (axis + 1) % 3, v = (axis + 2) % 3 and k = e % 4: the start has bit u = k & 1 and
/// bit v = k >> 1.
constexpr int edge_axis(int edge)
{
  return edge / 4;
}
constexpr int edge_start(int edge)
{
  const int axis = edge / 4;
  const int k = edge % 4;
  return ((k & 1) << ((axis + 1) % 3)) | ((k >> 1) << ((axis + 2) % 3));
}
constexpr int edge_end(int edge)
{
  return edge_start(edge) | (1 << edge_axis(edge));
}

/// Face f lies at coordinate (f % 2) of axis f / 2; its outward normal is -e_axis for side 0 and
/// +e_axis for side 1. face_corner(f, i), i = 0..3, walks its corners counter-clockwise about
/// the outward normal; face_edge(f, i) joins corners i and i + 1 (mod 4).
int face_corner(int face, int i);
int face_edge(int face, int i);

/// Faces of a case whose four corners alternate inside/outside (two crossings pairs): there the
/// cell needs a decision, bit f of the result.
std::uint8_t ambiguous_faces(std::uint8_t inside_corners);

/// The polygons of one cell: closed loops of crossing edges, oriented so that their normal (by
/// the right-hand rule) points from inside to outside.
struct CellPolygons
{
  std::uint8_t loop_count = 0;
  std::array<std::uint8_t, 4> loop_size{};
  std::array<std::uint8_t, 12> edges{}; ///< the loops one after the other
  /// Bit i: loop i must be triangulated around an extra centre point (a fan would add a chord
  /// between two crossings of one face, which the neighbouring cell could add as well).
  std::uint8_t centre_loops = 0;
};

/// inside_corners: bit c set when corner c is inside (F >= iso). connected_faces: for each
/// ambiguous face f, bit f set when the face's two inside corners are joined across it (its
/// outside corners are cut off), clear when they are separated. Other bits are ignored.
const CellPolygons& cell_polygons(std::uint8_t inside_corners, std::uint8_t connected_faces);

/// A cap polygon on a cube face lying on the boundary of the grid's box: the part of the face
/// inside the solid, as items (0..7 = a corner, 8 + e = the crossing on edge e), counter-
/// clockwise about the face's outward normal, so it closes the surface consistently oriented.
struct FacePolygons
{
  std::uint8_t polygon_count = 0;
  std::array<std::uint8_t, 2> polygon_size{};
  std::array<std::uint8_t, 8> items{};
};

/// The cap of face `face` for the cell's inside corners; `connected` is the face's decision when
/// it is ambiguous.
const FacePolygons& face_cap(int face, std::uint8_t inside_corners, bool connected);

/// Marching squares on the unit square (corner c at (c & 1, c >> 1)): segments between crossing
/// edges 0 (y=0, along x), 1 (x=1, along y), 2 (y=1), 3 (x=0), each oriented with the inside on
/// its left. connected: the decision when the square is ambiguous (corners 0,3 vs 1,2).
struct SquareSegments
{
  std::uint8_t count = 0;
  std::array<std::array<std::uint8_t, 2>, 2> segments{};
};
const SquareSegments& square_segments(std::uint8_t inside_corners, bool connected);

} // namespace frep::mesh
