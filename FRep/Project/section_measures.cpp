#include "Project/detail/section_shape.h"
#include "Project/detail/space_time_checks.h"
#include "Project/space_time.h"

namespace frep::project
{

std::string detail::check_sections(const Model& model, const CoordinateRange& time,
  const std::vector<Interval>& space, int steps, int samples)
{
  std::string error = check_time(model, time);
  if (error.empty())
    error = check_space(model, space);
  if (error.empty() && space.size() != 2 && space.size() != 3)
    error = "a section's volume, area or topology needs 2 or 3 coordinates besides time (" +
            model.name() + " has " + std::to_string(space.size()) + ")";
  if (error.empty() && (steps < 1 || samples < 2))
    error = "at least one time and two samples per axis";
  return error;
}

SectionMeasures section_measures(const Model& model, const CoordinateRange& time,
  const std::vector<Interval>& space, int steps, int samples, const SpaceTimeOptions& options)
{
  SectionMeasures result;
  result.error = detail::check_sections(model, time, space, steps, samples);
  if (!result.error.empty())
    return result;
  result.dimension = static_cast<int>(space.size());
  const GridSpec grid = detail::section_grid(space, samples);
  for (int i = 0; i < steps; ++i)
  {
    SectionMeasure m;
    m.time = steps == 1 ? time.lo : time.lo + (time.hi - time.lo) * (i / double(steps - 1));
    const detail::SectionShape shape =
      detail::section_shape(model, time.coordinate, m.time, grid, options.parameters);
    if (!shape.error.empty())
    {
      result.error = shape.error;
      return result;
    }
    m.measure = shape.measure;
    m.components = shape.topology.components;
    m.genus = shape.topology.genus;
    result.table.push_back(m);
  }
  return result;
}

} // namespace frep::project
