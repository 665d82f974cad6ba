// The Planner's checks of the world, the spreadsheet, the animation and the renderer.
#include "Mapping/detail/planner.h"

#include <algorithm>
#include <cmath>

namespace frep::mapping::planning
{
namespace
{

// Refused before allocating: a typo in fps or step must not eat the machine's memory.
constexpr std::size_t max_cells = 10'000;
constexpr double max_frames = 100'000;

const char* axis_name(WorldSystem system, int axis)
{
  static constexpr const char* names[3][3] = {
    { "x", "y", "z" }, { "r", "phi", "z" }, { "r", "theta", "phi" }
  };
  return names[static_cast<int>(system)][std::clamp(axis, 0, 2)];
}

} // namespace

void Planner::check_world()
{
  Plan& p = plan();
  p.system = spec_.world.system;
  if (spec_.world.resolution < 2)
  {
    error("world.resolution", "must be >= 2");
  }
  std::vector<const Resolved*> world;
  for (std::size_t i = 0; i < n(); ++i)
  {
    if (const Resolved* r = find(i, Channel::Type::World))
    {
      world.push_back(r);
    }
  }
  if (world.size() < 2 || world.size() > 3)
  {
    error("coordinates",
      std::to_string(world.size()) + " world coordinates; 2 or 3 are needed (the shape's axes)");
  }
  std::array<Interval, 3> target_box{};
  for (const Resolved* r : world)
  {
    const int axis = r->channel->axis;
    if (axis < 0 || axis > 2)
    {
      error(r->place + ".axis", "must be 0, 1 or 2");
      continue;
    }
    const int used = p.world_coordinates[static_cast<std::size_t>(axis)];
    if (used >= 0)
    {
      error(r->place + ".axis",
        std::string("axis ") + axis_name(p.system, axis) + " is already used by " +
          model_.names[static_cast<std::size_t>(used)]);
      continue;
    }
    p.world_coordinates[static_cast<std::size_t>(axis)] = r->coordinate;
    p.model_box[static_cast<std::size_t>(axis)] = r->range;
    target_box[static_cast<std::size_t>(axis)] = r->target;
    p.world_curves[static_cast<std::size_t>(axis)] = r->channel->curve;
  }
  // An axis no coordinate drives sits at 0 (cartesian z, an angle) or at r = 1.
  double longest = 0.0;
  for (std::size_t k = 0; k < 3; ++k)
  {
    if (p.world_coordinates[k] < 0)
    {
      const double at = (k == 0 && p.system != WorldSystem::Cartesian) ? 1.0 : 0.0;
      p.model_box[k] = { 0.0, 0.0 };
      target_box[k] = { at, at };
    }
    else
    {
      longest = std::max(longest, std::abs(p.model_box[k].hi - p.model_box[k].lo));
    }
  }
  p.world_targets = target_box;
  if (p.system == WorldSystem::Cartesian)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      p.world_box[k] = { std::min(target_box[k].lo, target_box[k].hi),
        std::max(target_box[k].lo, target_box[k].hi) };
    }
  }
  else
  {
    p.world_box = curvilinear_box(p.system, target_box);
  }
  for (std::size_t k = 0; k < 3; ++k)
  {
    if (p.world_coordinates[k] >= 0 && longest > 0)
    {
      const double share = std::abs(p.model_box[k].hi - p.model_box[k].lo) / longest;
      p.samples[k] = std::max(2, static_cast<int>(std::lround(spec_.world.resolution * share)));
    }
  }
}

void Planner::check_spreadsheet()
{
  Plan& p = plan();
  std::size_t cells = 1;
  for (std::size_t i = 0; i < n(); ++i)
  {
    const Resolved* r = find(i, Channel::Type::Spreadsheet);
    if (!r)
    {
      continue;
    }
    const int axis = r->channel->grid_axis;
    if (axis < 0 || axis > 2)
    {
      error(r->place + ".axis", "must be columns, rows or layers");
      continue;
    }
    if (r->channel->values.empty())
    {
      error(r->place + ".values", "no node values");
      continue;
    }
    if (grid_[static_cast<std::size_t>(axis)] >= 0)
    {
      static constexpr const char* names[3] = { "columns", "rows", "layers" };
      error(r->place + ".axis",
        std::string("the ") + names[axis] + " are already driven by " +
          model_.names[static_cast<std::size_t>(grid_[static_cast<std::size_t>(axis)])]);
      continue;
    }
    grid_[static_cast<std::size_t>(axis)] = static_cast<int>(i);
    p.grid_shape[static_cast<std::size_t>(axis)] = static_cast<int>(r->channel->values.size());
    cells *= r->channel->values.size();
    cells = std::min(cells, max_cells + 1);
  }
  if (cells > max_cells)
  {
    error("coordinates",
      "the spreadsheet would have more than " + std::to_string(max_cells) + " cells");
  }
  if (std::any_of(grid_.begin(), grid_.end(), [](int g) { return g >= 0; }))
  {
    p.grid_coordinates.assign(3, std::string());
    for (std::size_t k = 0; k < 3; ++k)
    {
      if (grid_[k] >= 0)
      {
        p.grid_coordinates[k] = model_.names[static_cast<std::size_t>(grid_[k])];
      }
    }
  }
}

// The ray caster's needs (an affine world mapping) and the floor scene's (ray-cast, two
// dynamic coordinates).
void Planner::check_render()
{
  const RenderSettings& rs = spec_.render;
  std::string why;
  if ((rs.method == RenderSettings::Method::Raycast ||
        rs.frames_method == RenderSettings::Method::Raycast) &&
      !world_is_affine(plan(), &why))
  {
    error("render.method", "\"raycast\" " + why + "; use \"mesh\"");
  }
  if (rs.scene == RenderSettings::Scene::Floor)
  {
    if (plan().dynamic_coordinates.size() != 2)
    {
      error("render.scene",
        "the \"floor\" scene is the plane of two dynamic coordinates; the mapping has " +
          std::to_string(plan().dynamic_coordinates.size()));
    }
  }
}

void Planner::check_animation()
{
  const AnimationSettings& a = spec_.animation;
  bool timing_ok = true;
  if (!std::isfinite(a.duration) || !(a.duration > 0))
  {
    error("animation.duration", "must be > 0 (zero frames)");
    timing_ok = false;
  }
  if (!std::isfinite(a.fps) || !(a.fps > 0))
  {
    error("animation.fps", "must be > 0 (zero frames)");
    timing_ok = false;
  }
  if (timing_ok && a.duration * a.fps > max_frames)
  {
    error("animation", "more than " + format_value(max_frames) + " frames (duration x fps)");
    timing_ok = false;
  }
  if (timing_ok)
  {
    frame_count_ =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(a.duration * a.fps)));
  }

  std::vector<std::string> dynamic;
  for (std::size_t i = 0; i < n(); ++i)
  {
    if (find(i, Channel::Type::Dynamic))
    {
      dynamic.push_back(model_.names[i]);
      dynamic_.push_back(static_cast<int>(i));
    }
  }
  if (!a.path)
  {
    if (dynamic.size() >= 2)
    {
      error("animation.path",
        "missing: " + std::to_string(dynamic.size()) + " dynamic coordinates (" +
          name_list(dynamic) + ") need a path through their space");
    }
    else if (dynamic.size() == 1)
    {
      const Resolved* r =
        find(static_cast<std::size_t>(dynamic_.front()), Channel::Type::Dynamic);
      if (r->map_ok && !r->map.is_monotone())
      {
        error(
          r->place + ".curve", "must be monotone: the coordinate's value is found from the time");
      }
    }
    plan().dynamic_coordinates = dynamic;
    return;
  }
  const Path& path = *a.path;
  if (dynamic.empty())
  {
    error("animation.path", "there are no dynamic coordinates for the path to run through");
    return;
  }
  std::vector<std::string> sorted_path = path.coordinates;
  std::vector<std::string> sorted_dynamic = dynamic;
  std::sort(sorted_path.begin(), sorted_path.end());
  std::sort(sorted_dynamic.begin(), sorted_dynamic.end());
  if (sorted_path != sorted_dynamic)
  {
    error("animation.path.coordinates",
      "[" + name_list(path.coordinates) + "] must be the dynamic coordinates (" +
        name_list(dynamic) + "), each once");
    return;
  }
  SampledPath::Result sampled = SampledPath::make(path);
  for (const PlanError& e : sampled.errors)
  {
    error(e.place.empty() ? "animation.path" : "animation.path." + e.place, e.message);
  }
  if (!sampled.ok())
  {
    return;
  }
  path_ = std::move(sampled.path);
  // Follow the path's axis order from here on.
  dynamic_.clear();
  for (const std::string& name : path.coordinates)
  {
    dynamic_.push_back(static_cast<int>(
      std::find(model_.names.begin(), model_.names.end(), name) - model_.names.begin()));
  }
  Plan& p = plan();
  p.dynamic_coordinates = path.coordinates;
  p.path_polyline = path_->polyline(static_cast<int>(path_->segment_count()) * 32 + 1);
  p.path_pieces = path_->pieces();
  p.path_model_coordinates = dynamic_;
  for (std::size_t k = 0; k < 2 && k < dynamic_.size(); ++k)
  {
    p.path_plane[k] = find(static_cast<std::size_t>(dynamic_[k]), Channel::Type::Dynamic)->range;
  }
}

} // namespace frep::mapping::planning
