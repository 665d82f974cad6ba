#include "Project/detail/section_shape.h"

#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"

#include <numeric>

namespace frep::project::detail
{
namespace
{

// The pieces of a contour: its segments joined by shared points.
std::size_t contour_loops(const mesh::Surface& contour)
{
  std::vector<std::uint32_t> parent(contour.point_count());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto root = [&](std::uint32_t i)
  {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<bool> used(parent.size(), false);
  for (std::size_t c = 0; c + 1 < contour.cells.size(); c += 2)
  {
    const std::uint32_t a = root(contour.cells[c]), b = root(contour.cells[c + 1]);
    used[contour.cells[c]] = used[contour.cells[c + 1]] = true;
    if (a != b)
      parent[a] = b;
  }
  std::size_t pieces = 0;
  for (std::uint32_t i = 0; i < parent.size(); ++i)
    pieces += used[i] && root(i) == i ? 1 : 0;
  return pieces;
}

// The area inside a contour whose segments have the inside on their left (shoelace).
double contour_area(const mesh::Surface& contour)
{
  double twice = 0.0;
  for (std::size_t c = 0; c + 1 < contour.cells.size(); c += 2)
  {
    const double* p = &contour.points[3 * contour.cells[c]];
    const double* q = &contour.points[3 * contour.cells[c + 1]];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * twice;
}

} // namespace

GridSpec section_grid(const std::vector<Interval>& space, int samples)
{
  std::vector<double> lo, hi;
  for (const Interval& i : space)
  {
    lo.push_back(i.lo);
    hi.push_back(i.hi);
  }
  const std::vector<std::int64_t> counts(space.size(), samples);
  return box_grid(lo, hi, counts);
}

SectionShape section_shape(const Model& model, int time_coordinate, double time,
  const GridSpec& grid, const std::vector<double>& parameters)
{
  Specialisation s;
  s.parameters = parameters;
  s.fixed.assign(static_cast<std::size_t>(model.x_dim()), std::nullopt);
  s.fixed[static_cast<std::size_t>(time_coordinate - 1)] = time;
  const auto tape = model.specialise(s);
  mesh::ExtractOptions extract;
  extract.normals = false;
  extract.attributes = false;
  const bool solid = grid.axes.size() == 3;
  const mesh::ExtractResult r =
    solid ? mesh::extract_surface(tape, grid, extract) : mesh::extract_contour(tape, grid, extract);
  SectionShape shape;
  if (!r.ok())
  {
    shape.error = "the section at t = " + std::to_string(time) + ": " + r.error;
    return shape;
  }
  if (!solid)
  {
    shape.measure = contour_area(r.surface);
    shape.components = contour_loops(r.surface);
    return shape;
  }
  const mesh::MeshTopology topology = mesh::analyse_topology(r.surface);
  shape.measure = topology.signed_volume;
  shape.components = topology.components;
  // Each closed piece has Euler characteristic 2 - 2 g: the genus summed over the pieces.
  shape.genus = static_cast<long long>(topology.components) - topology.euler_characteristic / 2;
  return shape;
}

} // namespace frep::project::detail
