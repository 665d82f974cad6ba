#include "Project/detail/space_time_checks.h"

#include <cmath>

namespace frep::project::detail
{

std::string check_time(const Model& model, const CoordinateRange& time)
{
  if (model.x_dim() < 2)
    return model.name() + " has x[" + std::to_string(model.x_dim()) +
           "]: a space-time model needs time and at least one coordinate of space";
  if (time.coordinate < 1 || time.coordinate > model.x_dim())
    return "time x" + std::to_string(time.coordinate) + ": " + model.name() + " has x[" +
           std::to_string(model.x_dim()) + "]";
  if (!std::isfinite(time.lo) || !std::isfinite(time.hi) || time.lo > time.hi)
    return "the time range must be finite, lo <= hi";
  return {};
}

std::string check_space(const Model& model, const std::vector<Interval>& space)
{
  if (static_cast<int>(space.size()) != model.x_dim() - 1)
    return "the box has " + std::to_string(space.size()) + " ranges, " + model.name() +
           " has " + std::to_string(model.x_dim() - 1) + " coordinates besides time";
  for (const Interval& i : space)
    if (!std::isfinite(i.lo) || !std::isfinite(i.hi) || i.lo > i.hi)
      return "the box's ranges must be finite, lo <= hi";
  return {};
}

std::string check_tolerances(const SpaceTimeOptions& options)
{
  if (!(options.time_tolerance > 0.0) || !std::isfinite(options.time_tolerance))
    return "the time tolerance must be > 0";
  if (!(options.value_tolerance >= 0.0) || !std::isfinite(options.value_tolerance))
    return "the value tolerance must be >= 0";
  if (options.max_boxes < 1)
    return "the query needs at least one box";
  return {};
}

std::vector<int> time_first_order(int x_dim, int time_coordinate)
{
  std::vector<int> order{ time_coordinate - 1 };
  for (int i = 0; i < x_dim; ++i)
    if (i != time_coordinate - 1)
      order.push_back(i);
  return order;
}

} // namespace frep::project::detail
