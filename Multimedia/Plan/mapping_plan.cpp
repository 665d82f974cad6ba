// make_plan: checks a Spec against the model and expands it into the world box, the
// spreadsheet cells and the animation frames. The order of the work: resolve every channel
// (range, target, map), check the placing channels (world, dynamic, spreadsheet, fixed), then,
// only when nothing is wrong, fill the samples.
#include "Plan/mapping_plan.h"

#include "Plan/planner.h"

#include <string>
#include <vector>

namespace frep::mapping
{

std::string format_errors(const std::vector<PlanError>& errors)
{
  std::string text;
  for (const PlanError& e : errors)
  {
    text += (e.place.empty() ? e.message : e.place + ": " + e.message) + "\n";
  }
  return text;
}

bool world_is_affine(const Plan& plan, std::string* why)
{
  const auto fail = [&](const std::string& text)
  {
    if (why)
    {
      *why = text;
    }
    return false;
  };
  if (plan.world_coordinates[2] < 0)
  {
    return fail("draws 3-D sections (the mapping has two world coordinates)");
  }
  if (plan.system != WorldSystem::Cartesian)
  {
    return fail("needs the cartesian world system (this one bends space)");
  }
  for (int k = 0; k < 3; ++k)
  {
    const Curve& c = plan.world_curves[k];
    if (!(c.kind == Curve::Kind::Linear || (c.kind == Curve::Kind::Power && c.exponent == 1.0)))
    {
      return fail("needs linear world curves (world axis " + std::to_string(k) + " has a curve)");
    }
  }
  return true;
}

PlanResult make_plan(const Spec& spec, const ModelCoordinates& model)
{
  return planning::Planner(spec, model).run();
}

} // namespace frep::mapping
