// The Planner's channels: each resolved (range, target, map), the placing channels (world,
// dynamic, spreadsheet, fixed) checked, and the values of the others.
#include "Mapping/detail/planner.h"

#include "Mapping/colour_maps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace frep::mapping::planning
{
namespace
{

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

} // namespace

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
    case Channel::Type::Projected:
      return "projected";
  }
  return "?";
}

void Planner::resolve_channels()
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

const Resolved* Planner::find(std::size_t i, Channel::Type type) const
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

namespace
{

bool is_placing(Channel::Type t)
{
  return t == Channel::Type::World || t == Channel::Type::Dynamic ||
         t == Channel::Type::Spreadsheet || t == Channel::Type::Fixed ||
         t == Channel::Type::Projected;
}

} // namespace

// Each coordinate is free (world), eliminated (projected) or gets a value per sample: fixed
// everywhere, or a spreadsheet value in the cells and/or a dynamic value in the frames (one
// coordinate may drive both the spreadsheet and the animation, as x4 and x5 of Meta5D do).
void Planner::check_placing()
{
  for (std::size_t i = 0; i < n(); ++i)
  {
    const std::string place = "coordinates." + model_.names[i];
    std::map<Channel::Type, const Resolved*> first;
    for (const Resolved& r : by_coordinate_[i])
    {
      const Channel::Type t = r.channel->type;
      if (!is_placing(t))
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
      error(place,
        "missing: every coordinate needs a world, dynamic, spreadsheet, fixed or projected "
        "channel");
      continue;
    }
    const bool world = first.count(Channel::Type::World) != 0;
    const bool fixed = first.count(Channel::Type::Fixed) != 0;
    const bool projected = first.count(Channel::Type::Projected) != 0;
    if (projected && by_coordinate_[i].size() > 1)
    {
      // Nothing has one value of it: the shape is the union over its whole range.
      error(place, "a projected coordinate has no value: it takes no other channel");
    }
    else if ((world || fixed) && first.size() > 1)
    {
      error(place,
        world ? "a world coordinate cannot also be dynamic, spreadsheet, fixed or projected"
              : "a fixed coordinate cannot also be dynamic, spreadsheet or projected");
    }
  }
}

void Planner::fill_projected()
{
  for (std::size_t i = 0; i < n(); ++i)
  {
    if (const Resolved* r = find(i, Channel::Type::Projected))
    {
      plan().projected.push_back({ static_cast<int>(i), r->range, r->channel->tolerance });
    }
  }
}

void Planner::check_channel_values()
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

} // namespace frep::mapping::planning
