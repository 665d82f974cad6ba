#include "Scene/section_model.h"

#include "Project/projection.h"

#include <algorithm>

namespace frep::mapping
{

SectionModel section_model(
  std::shared_ptr<const Model> model, const Plan& plan, const std::vector<double>& parameters)
{
  SectionModel result;
  if (plan.projected.empty() || !model)
  {
    result.model = std::move(model);
    if (!result.model)
      result.error = "no model";
    return result;
  }
  std::vector<project::CoordinateRange> axes;
  project::ProjectionOptions options;
  options.tolerance = plan.projected.front().tolerance;
  for (const ProjectedCoordinate& p : plan.projected)
  {
    axes.push_back({ p.coordinate + 1, p.range.lo, p.range.hi });
    options.tolerance = std::min(options.tolerance, p.tolerance);
  }
  options.parameters = parameters;
  options.keep_coordinates = true; // the plan's samples keep numbering the model's coordinates
  const LoadedModel projected = project::project(std::move(model), axes, options);
  if (!projected.ok())
  {
    result.error = "cannot project along " + project::eliminated_text(axes) + ": " +
                   projected.message();
    return result;
  }
  result.model = projected.model;
  return result;
}

} // namespace frep::mapping
