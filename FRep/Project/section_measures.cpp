#include "Project/detail/space_time_checks.h"
#include "Project/space_time.h"

#include "Mesh/mesh_topology.h"
#include "Mesh/surface.h"
#include "Sample/grid.h"

#include <numeric>

namespace frep::project
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
  std::size_t pieces = 0;
  std::vector<bool> used(parent.size(), false);
  for (std::size_t c = 0; c + 1 < contour.cells.size(); c += 2)
  {
    const std::uint32_t a = root(contour.cells[c]), b = root(contour.cells[c + 1]);
    used[contour.cells[c]] = used[contour.cells[c + 1]] = true;
    if (a != b)
      parent[a] = b;
  }
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

SectionMeasures section_measures(const Model& model, const CoordinateRange& time,
  const std::vector<Interval>& space, int steps, int samples, const SpaceTimeOptions& options)
{
  SectionMeasures result;
  result.error = detail::check_time(model, time);
  if (result.error.empty())
    result.error = detail::check_space(model, space);
  if (result.error.empty() && space.size() != 2 && space.size() != 3)
    result.error = "a section's volume or area needs 2 or 3 coordinates besides time (" +
                   model.name() + " has " + std::to_string(space.size()) + ")";
  if (result.error.empty() && (steps < 1 || samples < 2))
    result.error = "at least one time and two samples per axis";
  if (!result.error.empty())
    return result;
  result.dimension = static_cast<int>(space.size());
  std::vector<double> lo, hi;
  for (const Interval& i : space)
  {
    lo.push_back(i.lo);
    hi.push_back(i.hi);
  }
  const std::vector<std::int64_t> counts(space.size(), samples);
  const GridSpec grid = box_grid(lo, hi, counts);
  for (int i = 0; i < steps; ++i)
  {
    SectionMeasure m;
    m.time = steps == 1 ? time.lo : time.lo + (time.hi - time.lo) * (i / double(steps - 1));
    Specialisation s;
    s.parameters = options.parameters;
    s.fixed.assign(static_cast<std::size_t>(model.x_dim()), std::nullopt);
    s.fixed[static_cast<std::size_t>(time.coordinate - 1)] = m.time;
    const auto tape = model.specialise(s);
    mesh::ExtractOptions extract;
    extract.normals = false;
    extract.attributes = false;
    const mesh::ExtractResult r = result.dimension == 3 ? mesh::extract_surface(tape, grid, extract)
                                                        : mesh::extract_contour(tape, grid, extract);
    if (!r.ok())
    {
      result.error = "the section at t = " + std::to_string(m.time) + ": " + r.error;
      return result;
    }
    if (result.dimension == 3)
    {
      const mesh::MeshTopology topology = mesh::analyse_topology(r.surface);
      m.measure = topology.signed_volume;
      m.components = topology.components;
    }
    else
    {
      m.measure = contour_area(r.surface);
      m.components = contour_loops(r.surface);
    }
    result.table.push_back(m);
  }
  return result;
}

} // namespace frep::project
