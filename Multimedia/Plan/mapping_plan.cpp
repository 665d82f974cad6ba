// make_plan: checks a Spec against the model and expands it into the world box, the
// spreadsheet cells and the animation frames. The order of the work: resolve every channel
// (range, target, map), check the placing channels (world, dynamic, spreadsheet, fixed), then,
// only when nothing is wrong, fill the samples.
#include "Plan/mapping_plan.h"

#include "Plan/colour_maps.h"
#include "Plan/path.h"
#include "Plan/unit_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <optional>

namespace frep::mapping
{
namespace
{

// Refused before allocating: a typo in fps or step must not eat the machine's memory.
constexpr std::size_t max_cells = 10'000;
constexpr double max_frames = 100'000;

using Matrix = std::array<double, 16>;

constexpr Matrix identity{ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

Matrix multiply(const Matrix& a, const Matrix& b)
{
  Matrix m{};
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      double s = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        s += a[i * 4 + k] * b[k * 4 + j];
      }
      m[i * 4 + j] = s;
    }
  }
  return m;
}

Matrix translation(double x, double y, double z)
{
  Matrix m = identity;
  m[3] = x;
  m[7] = y;
  m[11] = z;
  return m;
}

std::array<double, 3> normalised(const std::array<double, 3>& v)
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / n, v[1] / n, v[2] / n };
}

// Rodrigues: rotation by `degrees` about the unit axis a (right-handed).
Matrix rotation(const std::array<double, 3>& axis, double degrees)
{
  const auto a = normalised(axis);
  const double t = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(t);
  const double s = std::sin(t);
  const double d = 1.0 - c;
  return { c + a[0] * a[0] * d,
    a[0] * a[1] * d - a[2] * s,
    a[0] * a[2] * d + a[1] * s,
    0,
    a[1] * a[0] * d + a[2] * s,
    c + a[1] * a[1] * d,
    a[1] * a[2] * d - a[0] * s,
    0,
    a[2] * a[0] * d - a[1] * s,
    a[2] * a[1] * d + a[0] * s,
    c + a[2] * a[2] * d,
    0,
    0,
    0,
    0,
    1 };
}

std::string format_value(double v)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

std::string name_list(const std::vector<std::string>& names)
{
  std::string list;
  for (const std::string& n : names)
  {
    list += (list.empty() ? "" : ", ") + n;
  }
  return list;
}

const char* type_name(Channel::Type t)
{
  switch (t)
  {
    case Channel::Type::World:
      return "world";
    case Channel::Type::Dynamic:
      return "dynamic";
    case Channel::Type::Spreadsheet:
      return "spreadsheet";
    case Channel::Type::Fixed:
      return "fixed";
    case Channel::Type::Colour:
      return "colour";
    case Channel::Type::Transparency:
      return "transparency";
    case Channel::Type::Transformation:
      return "transformation";
    case Channel::Type::Audio:
      return "audio";
  }
  return "?";
}

const char* axis_name(WorldSystem system, int axis)
{
  static constexpr const char* names[3][3] = {
    { "x", "y", "z" }, { "r", "phi", "z" }, { "r", "theta", "phi" }
  };
  return names[static_cast<int>(system)][std::clamp(axis, 0, 2)];
}

Interval default_target(const Channel& c, Interval range, double duration)
{
  switch (c.type)
  {
    case Channel::Type::Dynamic:
      return { 0.0, duration };
    case Channel::Type::Colour:
      return { 0.0, 1.0 };
    case Channel::Type::Transparency:
      return { 1.0, 0.2 };
    case Channel::Type::Transformation:
      switch (c.transform)
      {
        case Channel::Transform::Rotate:
          return { 0.0, 360.0 };
        case Channel::Transform::Scale:
          return { 1.0, 2.0 };
        case Channel::Transform::Translate:
          return { 0.0, 1.0 };
      }
      break;
    case Channel::Type::Audio:
      return c.audio_parameter == Channel::AudioParameter::Pitch ? Interval{ 220.0, 880.0 }
                                                                 : Interval{ 0.0, 1.0 };
    default:
      break;
  }
  return range; // world (identity), spreadsheet and fixed (unused)
}

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

// The bounding box of the world region a box of (r, angle, ...) maps onto.
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

// One channel with everything make_plan needs resolved.
struct Resolved
{
  const Channel* channel = nullptr;
  int coordinate = -1; ///< model index
  std::string place;   ///< "coordinates.x4[1]"
  Interval range;
  Interval target;
  ChannelMap map;
  bool map_ok = false;
};

class Planner
{
public:
  Planner(const Spec& spec, const ModelCoordinates& model)
    : spec_(spec)
    , model_(model)
  {
  }

  PlanResult run()
  {
    resolve_channels();
    check_placing();
    check_world();
    check_spreadsheet();
    check_animation();
    check_render();
    check_channel_values();
    if (result_.ok())
    {
      fill_cells();
      fill_frames();
      fill_still();
    }
    return std::move(result_);
  }

private:
  void error(std::string place, std::string message)
  {
    result_.errors.push_back({ std::move(place), std::move(message) });
  }
  Plan& plan() { return result_.plan; }
  std::size_t n() const { return model_.names.size(); }
  Interval model_interval(std::size_t i) const
  {
    return i < model_.intervals.size() ? model_.intervals[i] : Interval{};
  }

  // --- channels -------------------------------------------------------------------------

  void resolve_channels()
  {
    by_coordinate_.assign(n(), {});
    std::map<std::string, int> index;
    for (std::size_t i = 0; i < n(); ++i)
    {
      index.emplace(model_.names[i], static_cast<int>(i));
    }
    std::vector<bool> seen(n(), false);
    for (const CoordinateMapping& m : spec_.coordinates)
    {
      const std::string place = "coordinates." + m.name;
      const auto it = index.find(m.name);
      if (it == index.end())
      {
        error(place, "not a coordinate of the model (" + name_list(model_.names) + ")");
        continue;
      }
      const int ci = it->second;
      if (seen[static_cast<std::size_t>(ci)])
      {
        error(place, "mapped twice");
        continue;
      }
      seen[static_cast<std::size_t>(ci)] = true;
      // A channel without its own range takes the previous channel's (the first: the model's
      // interval); spreadsheet node values without a range span their own range.
      Interval current = model_interval(static_cast<std::size_t>(ci));
      for (std::size_t k = 0; k < m.channels.size(); ++k)
      {
        const Channel& c = m.channels[k];
        Resolved r;
        r.channel = &c;
        r.coordinate = ci;
        r.place = place + "[" + std::to_string(k) + "]";
        if (c.range)
        {
          current = *c.range;
        }
        else if (c.type == Channel::Type::Spreadsheet && c.values.size() >= 2)
        {
          const auto [lo, hi] = std::minmax_element(c.values.begin(), c.values.end());
          if (*lo < *hi)
          {
            current = { *lo, *hi };
          }
        }
        r.range = current;
        r.target = c.target.value_or(default_target(c, current, spec_.animation.duration));
        if (!std::isfinite(r.range.lo) || !std::isfinite(r.range.hi))
        {
          error(r.place + ".range", "must be finite");
        }
        else if (r.range.lo == r.range.hi)
        {
          error(r.place + ".range",
            "zero width (" + format_value(r.range.lo) + " to " + format_value(r.range.hi) + ")");
        }
        else
        {
          ChannelMap::Result made = ChannelMap::make(r.range, c.curve, r.target);
          if (made.ok())
          {
            r.map = std::move(made.map);
            r.map_ok = true;
          }
          else
          {
            error(r.place + (c.target ? ".target" : ".curve"), made.error);
          }
        }
        by_coordinate_[static_cast<std::size_t>(ci)].push_back(std::move(r));
      }
    }
  }

  const Resolved* find(std::size_t i, Channel::Type type) const
  {
    for (const Resolved& r : by_coordinate_[i])
    {
      if (r.channel->type == type)
      {
        return &r;
      }
    }
    return nullptr;
  }

  // Each coordinate is free (world) or gets a value per sample: fixed everywhere, or a
  // spreadsheet value in the cells and/or a dynamic value in the frames (one coordinate may
  // drive both the spreadsheet and the animation, as x4 and x5 of Meta5D do).
  void check_placing()
  {
    for (std::size_t i = 0; i < n(); ++i)
    {
      const std::string place = "coordinates." + model_.names[i];
      std::map<Channel::Type, const Resolved*> first;
      for (const Resolved& r : by_coordinate_[i])
      {
        const Channel::Type t = r.channel->type;
        if (t != Channel::Type::World && t != Channel::Type::Dynamic &&
            t != Channel::Type::Spreadsheet && t != Channel::Type::Fixed)
        {
          continue;
        }
        if (first.count(t))
        {
          error(r.place + ".type",
            std::string("a second ") + type_name(t) + " channel (the first is " + first[t]->place +
              ")");
          continue;
        }
        first[t] = &r;
      }
      if (first.empty())
      {
        error(
          place, "missing: every coordinate needs a world, dynamic, spreadsheet or fixed channel");
        continue;
      }
      const bool world = first.count(Channel::Type::World) != 0;
      const bool fixed = first.count(Channel::Type::Fixed) != 0;
      if ((world || fixed) && first.size() > 1)
      {
        error(place,
          world ? "a world coordinate cannot also be dynamic, spreadsheet or fixed"
                : "a fixed coordinate cannot also be dynamic or spreadsheet");
      }
    }
  }

  // --- world ----------------------------------------------------------------------------

  void check_world()
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

  // --- spreadsheet ----------------------------------------------------------------------

  void check_spreadsheet()
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

  // --- animation ------------------------------------------------------------------------

  // The ray caster's needs (an affine world mapping) and the floor scene's (ray-cast, two
  // dynamic coordinates).
  void check_render()
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

  void check_animation()
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
    for (std::size_t k = 0; k < 2 && k < dynamic_.size(); ++k)
    {
      p.path_plane[k] = find(static_cast<std::size_t>(dynamic_[k]), Channel::Type::Dynamic)->range;
    }
  }

  // --- photometric, transformation and audio channels -----------------------------------

  bool is_world(std::size_t i) const { return find(i, Channel::Type::World) != nullptr; }

  void check_channel_values()
  {
    Plan& p = plan();
    for (std::size_t i = 0; i < n(); ++i)
    {
      for (const Resolved& r : by_coordinate_[i])
      {
        const Channel& c = *r.channel;
        switch (c.type)
        {
          case Channel::Type::Colour:
            if (!is_colour_channel_name(c.colormap))
            {
              error(r.place + ".colormap",
                "unknown colour map \"" + c.colormap + "\" (expected " + colour_channel_names() +
                  ")");
            }
            if (is_world(i))
            {
              if (c.applies_to != PhotometricTarget::Shape)
              {
                error(r.place + ".applies_to",
                  "a world coordinate can colour only the shape (per vertex)");
              }
              else if (p.vertex_colouring.source != VertexColouring::Source::None)
              {
                error(r.place, "a second per-vertex colour (the shape has one already)");
              }
              else if (spec_.render.colour_source == RenderSettings::ColourSource::Attributes)
              {
                error(r.place, "conflicts with render.colour_source \"attributes\"");
              }
              else
              {
                VertexColouring& v = p.vertex_colouring;
                v.source = VertexColouring::Source::WorldCoordinate;
                v.coordinate = static_cast<int>(i);
                v.range = r.range;
                v.curve = c.curve;
                v.colormap = c.colormap;
              }
            }
            else
            {
              values_.push_back(&r);
            }
            break;
          case Channel::Type::Transparency:
            if (is_world(i))
            {
              error(r.place,
                "transparency on a world coordinate is not supported (it needs one value per "
                "sample)");
            }
            else if (c.applies_to == PhotometricTarget::Background)
            {
              error(r.place + ".applies_to", "the background has no transparency (shape or light)");
            }
            else
            {
              values_.push_back(&r);
            }
            break;
          case Channel::Type::Transformation:
          case Channel::Type::Audio:
            if (is_world(i))
            {
              error(r.place,
                std::string(type_name(c.type)) +
                  " on a world coordinate: it needs one value per frame or cell, and a world "
                  "coordinate varies over the shape");
              break;
            }
            if (c.type == Channel::Type::Transformation && c.vector == std::array<double, 3>{})
            {
              error(r.place + ".vector", "the vector must not be zero");
              break;
            }
            if (c.type == Channel::Type::Audio)
            {
              if (c.voice < 0 || c.voice > 63)
              {
                error(r.place + ".voice", "must be from 0 to 63");
                break;
              }
              p.voice_count = std::max(p.voice_count, c.voice + 1);
            }
            values_.push_back(&r);
            break;
          default:
            break;
        }
      }
    }
    if (p.vertex_colouring.source == VertexColouring::Source::None &&
        spec_.render.colour_source == RenderSettings::ColourSource::Attributes)
    {
      p.vertex_colouring.source = VertexColouring::Source::Attributes;
    }
  }

  // --- samples --------------------------------------------------------------------------

  Sample base_sample() const
  {
    Sample s;
    s.values.assign(n(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < n(); ++i)
    {
      if (const Resolved* r = find(i, Channel::Type::Fixed))
      {
        s.values[i] = r->channel->value;
      }
    }
    s.colour = spec_.render.colour;
    s.background = spec_.render.background;
    return s;
  }

  /// The photometric, transformation and audio channels at this sample's values, in file
  /// order (transformations compose in that order: a later one applies after an earlier one).
  void apply_channels(Sample& s) const
  {
    const Plan& p = result_.plan;
    s.voices.assign(static_cast<std::size_t>(p.voice_count), Voice{});
    Matrix m = identity;
    const double cx = 0.5 * (p.world_box[0].lo + p.world_box[0].hi);
    const double cy = 0.5 * (p.world_box[1].lo + p.world_box[1].hi);
    const double cz = 0.5 * (p.world_box[2].lo + p.world_box[2].hi);
    for (const Resolved* r : values_)
    {
      const Channel& c = *r->channel;
      const double x = s.values[static_cast<std::size_t>(r->coordinate)];
      if (std::isnan(x))
      {
        continue;
      }
      const double y = r->map.forward(x);
      switch (c.type)
      {
        case Channel::Type::Colour:
        {
          if (c.applies_to == PhotometricTarget::Light)
          {
            // The light is white: a colour channel on it sets its intensity.
            s.light_intensity = std::max(0.0, y);
            break;
          }
          std::array<double, 3>& colour =
            c.applies_to == PhotometricTarget::Shape ? s.colour : s.background;
          if (const auto component = colour_component(c.colormap))
          {
            colour[static_cast<std::size_t>(*component)] = std::clamp(y, 0.0, 1.0);
          }
          else if (const auto rgb = colour_map(c.colormap, y))
          {
            colour = *rgb;
          }
          break;
        }
        case Channel::Type::Transparency:
          if (c.applies_to == PhotometricTarget::Light)
          {
            s.light_intensity = std::max(0.0, y);
          }
          else
          {
            s.opacity = std::clamp(y, 0.0, 1.0);
          }
          break;
        case Channel::Type::Transformation:
        {
          Matrix t = identity;
          switch (c.transform)
          {
            case Channel::Transform::Rotate:
              t = multiply(translation(cx, cy, cz),
                multiply(rotation(c.vector, y), translation(-cx, -cy, -cz)));
              break;
            case Channel::Transform::Scale:
            {
              Matrix scale = identity;
              scale[0] = scale[5] = scale[10] = y;
              t = multiply(translation(cx, cy, cz), multiply(scale, translation(-cx, -cy, -cz)));
              break;
            }
            case Channel::Transform::Translate:
            {
              const auto v = normalised(c.vector);
              t = translation(v[0] * y, v[1] * y, v[2] * y);
              break;
            }
          }
          m = multiply(t, m);
          break;
        }
        case Channel::Type::Audio:
        {
          Voice& v = s.voices[static_cast<std::size_t>(c.voice)];
          switch (c.audio_parameter)
          {
            case Channel::AudioParameter::Pitch:
              v.pitch = y;
              break;
            case Channel::AudioParameter::Loudness:
              v.loudness = y;
              break;
            case Channel::AudioParameter::Timbre:
              v.timbre = y;
              break;
          }
          break;
        }
        default:
          break;
      }
    }
    s.transform = m;
  }

  /// "x4 = 0.25, x5 = 0.5" over the coordinates for which `shown` holds, in model order.
  std::string label(const Sample& s, const std::vector<bool>& shown) const
  {
    std::string text;
    for (std::size_t i = 0; i < n(); ++i)
    {
      if (shown[i])
      {
        text += (text.empty() ? "" : ", ") + model_.names[i] + " = " + format_value(s.values[i]);
      }
    }
    return text;
  }

  /// The dynamic coordinates' values at frame k (time k / fps), and the path parameter.
  void place_frame(Sample& s, std::size_t k) const
  {
    const AnimationSettings& a = spec_.animation;
    s.time = static_cast<double>(k) / a.fps;
    if (path_)
    {
      double fraction;
      if (path_->spec().timing == Path::Timing::Keys)
      {
        fraction = path_->fraction_at_time(s.time);
      }
      else if (path_->spec().closed)
      {
        // [0, duration): the last frame stops one step short of the start it loops back to.
        fraction = static_cast<double>(k) / static_cast<double>(frame_count_);
      }
      else
      {
        // Both ends of an open path are shown: the first frame at its start, the last at its end.
        fraction =
          frame_count_ > 1 ? static_cast<double>(k) / static_cast<double>(frame_count_ - 1) : 0.0;
      }
      s.path_parameter = fraction;
      s.path_point = path_->point_at(fraction);
      for (std::size_t d = 0; d < dynamic_.size(); ++d)
      {
        s.values[static_cast<std::size_t>(dynamic_[d])] = s.path_point[d];
      }
    }
    else if (dynamic_.size() == 1)
    {
      // One dynamic coordinate: its channel maps it onto time, so the value is the inverse.
      const Resolved* r = find(static_cast<std::size_t>(dynamic_.front()), Channel::Type::Dynamic);
      const double x = r->map.inverse(s.time);
      s.values[static_cast<std::size_t>(dynamic_.front())] = x;
      s.path_point = { x };
      s.path_parameter = std::clamp(s.time / a.duration, 0.0, 1.0);
    }
  }

  void fill_cells()
  {
    Plan& p = plan();
    if (std::none_of(grid_.begin(), grid_.end(), [](int g) { return g >= 0; }))
    {
      return;
    }
    std::vector<bool> shown(n(), false);
    std::array<std::size_t, 3> count{ 1, 1, 1 };
    std::array<const std::vector<double>*, 3> nodes{};
    for (std::size_t k = 0; k < 3; ++k)
    {
      if (grid_[k] >= 0)
      {
        shown[static_cast<std::size_t>(grid_[k])] = true;
        nodes[k] =
          &find(static_cast<std::size_t>(grid_[k]), Channel::Type::Spreadsheet)->channel->values;
        count[k] = nodes[k]->size();
      }
    }
    // Coordinates that are only dynamic take their value of the first frame.
    Sample base = base_sample();
    if (!dynamic_.empty())
    {
      place_frame(base, 0);
      base.time = 0.0;
      base.path_parameter = 0.0;
      base.path_point.clear();
    }
    p.cells.reserve(count[0] * count[1] * count[2]);
    for (std::size_t layer = 0; layer < count[2]; ++layer)
      for (std::size_t row = 0; row < count[1]; ++row)
        for (std::size_t column = 0; column < count[0]; ++column)
        {
          Sample s = base;
          const std::size_t index[3] = { column, row, layer };
          for (std::size_t k = 0; k < 3; ++k)
          {
            if (grid_[k] >= 0)
            {
              s.cell[k] = static_cast<int>(index[k]);
              s.values[static_cast<std::size_t>(grid_[k])] = (*nodes[k])[index[k]];
            }
          }
          apply_channels(s);
          s.label = label(s, shown);
          p.cells.push_back(std::move(s));
        }
  }

  void fill_frames()
  {
    Plan& p = plan();
    if (dynamic_.empty())
    {
      return;
    }
    std::vector<bool> shown(n(), false);
    for (int d : dynamic_)
    {
      shown[static_cast<std::size_t>(d)] = true;
    }
    // Coordinates that are only spreadsheet coordinates keep their first node value.
    Sample base = base_sample();
    for (std::size_t k = 0; k < 3; ++k)
    {
      if (grid_[k] >= 0 && !shown[static_cast<std::size_t>(grid_[k])])
      {
        base.values[static_cast<std::size_t>(grid_[k])] =
          find(static_cast<std::size_t>(grid_[k]), Channel::Type::Spreadsheet)
            ->channel->values.front();
      }
    }
    p.frames.reserve(frame_count_);
    for (std::size_t k = 0; k < frame_count_; ++k)
    {
      Sample s = base;
      place_frame(s, k);
      apply_channels(s);
      s.label = label(s, shown);
      p.frames.push_back(std::move(s));
    }
  }

  /// The shape with nothing varying: the first cell, else the first frame, else the fixed
  /// values with the channels applied (a mapping of world and fixed coordinates only).
  void fill_still()
  {
    Plan& p = plan();
    if (!p.cells.empty())
    {
      p.still = p.cells.front();
    }
    else if (!p.frames.empty())
    {
      p.still = p.frames.front();
    }
    else
    {
      p.still = base_sample();
      apply_channels(p.still);
    }
  }

  const Spec& spec_;
  const ModelCoordinates& model_;
  PlanResult result_;
  std::vector<std::vector<Resolved>> by_coordinate_; ///< per model coordinate, file order
  std::vector<const Resolved*> values_;              ///< the channels applied per sample
  std::array<int, 3> grid_{ -1, -1, -1 };            ///< model coordinate per grid axis
  std::vector<int> dynamic_;                         ///< dynamic coordinates, path axis order
  std::optional<SampledPath> path_;
  std::size_t frame_count_ = 0;
};

} // namespace

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
  return Planner(spec, model).run();
}

} // namespace frep::mapping
