// make_plan: checks a Spec against the model and expands it into the world box, the
// spreadsheet cells and the animation frames. The order of the work: resolve every channel
// (range, target, map), check the placing channels (world, dynamic, spreadsheet, fixed), then,
// only when nothing is wrong, fill the samples.
#include "Mapping/mapping_plan.h"

#include "Mapping/detail/planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace frep::mapping
{
namespace
{

// Multiples of pi/2 inside [lo, hi] (at most one period's worth: the rest repeat), where sin
// and cos take their extremes.
std::vector<double> critical_angles(double lo, double hi)
{
  std::vector<double> angles{ lo, hi };
  const double quarter = std::numbers::pi / 2;
  const double first = std::ceil(std::min(lo, hi) / quarter);
  for (int k = 0; k < 4; ++k)
  {
    const double a = (first + k) * quarter;
    if (a <= std::max(lo, hi))
    {
      angles.push_back(a);
    }
  }
  return angles;
}

} // namespace

std::array<Interval, 3> curvilinear_box(WorldSystem system, const std::array<Interval, 3>& w)
{
  std::array<double, 3> lo;
  std::array<double, 3> hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  auto add = [&](double x, double y, double z)
  {
    const double p[3] = { x, y, z };
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  };
  const double rs[2] = { w[0].lo, w[0].hi };
  if (system == WorldSystem::Cylindrical)
  {
    for (double r : rs)
      for (double phi : critical_angles(w[1].lo, w[1].hi))
        for (double z : { w[2].lo, w[2].hi })
          add(r * std::cos(phi), r * std::sin(phi), z);
  }
  else
  {
    for (double r : rs)
      for (double theta : critical_angles(w[1].lo, w[1].hi))
        for (double phi : critical_angles(w[2].lo, w[2].hi))
          add(r * std::sin(theta) * std::cos(phi),
            r * std::sin(theta) * std::sin(phi),
            r * std::cos(theta));
  }
  return { Interval{ lo[0], hi[0] }, Interval{ lo[1], hi[1] }, Interval{ lo[2], hi[2] } };
}

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

ModelCoordinates hyperfun_coordinates(int dimension)
{
  ModelCoordinates coordinates;
  for (int i = 0; i < dimension; ++i)
  {
    coordinates.names.push_back("x" + std::to_string(i + 1));
    coordinates.intervals.push_back({ -10.0, 10.0 }); // hfp's default box
  }
  return coordinates;
}

PlanResult make_plan(const Spec& spec, const ModelCoordinates& model)
{
  return planning::Planner(spec, model).run();
}

} // namespace frep::mapping
