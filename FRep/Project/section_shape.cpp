#include "Project/detail/section_shape.h"

#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"


namespace frep::project::detail
{
namespace
{

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
    shape.topology = mesh::shape_topology(r.surface);
    return shape;
  }
  const mesh::MeshTopology topology = mesh::analyse_topology(r.surface);
  shape.measure = topology.signed_volume;
  shape.topology = { topology.components, topology.genus() };
  return shape;
}

} // namespace frep::project::detail
