// The mapping file's writer: save_mapping, in the layout a hand-written file has. The reader is
// mapping_json_reader.cpp.
#include "Mapping/mapping_json.h"

#include "Mapping/detail/mapping_json_names.h"

#include <algorithm>
#include <string>

namespace frep::mapping
{
namespace
{

using namespace json_names;

Json curve_json(const Curve& c)
{
  switch (c.kind)
  {
    case Curve::Kind::Linear:
      return "linear";
    case Curve::Kind::EaseInOut:
      return "ease-in-out";
    case Curve::Kind::Power:
      return Json{ { "kind", "power" }, { "exponent", c.exponent } };
    case Curve::Kind::Table:
    {
      Json points = Json::array();
      for (const auto& p : c.table)
      {
        points.push_back(Json::array({ p[0], p[1] }));
      }
      return Json{ { "kind", "table" }, { "points", points } };
    }
    case Curve::Kind::Expression:
      return Json{ { "kind", "expression" }, { "expression", c.expression } };
  }
  return "linear";
}

Json interval_json(Interval i)
{
  return Json::array({ i.lo, i.hi });
}

Json channel_json(const Channel& c, WorldSystem system)
{
  Json j;
  j["type"] = name_of(channel_types, c.type);
  switch (c.type)
  {
    case Channel::Type::World:
      j["axis"] = system == WorldSystem::Cartesian     ? name_of(cartesian_axes, c.axis)
                  : system == WorldSystem::Cylindrical ? name_of(cylindrical_axes, c.axis)
                                                       : name_of(spherical_axes, c.axis);
      break;
    case Channel::Type::Spreadsheet:
      j["axis"] = name_of(grid_axes, c.grid_axis);
      break;
    default:
      break;
  }
  if (c.range)
  {
    j["range"] = interval_json(*c.range);
  }
  switch (c.type)
  {
    case Channel::Type::Spreadsheet:
      j["values"] = c.values;
      break;
    case Channel::Type::Fixed:
      j["value"] = c.value;
      break;
    case Channel::Type::Projected:
      j["tolerance"] = c.tolerance;
      break;
    case Channel::Type::Colour:
      j["colormap"] = c.colormap;
      j["applies_to"] = name_of(photometric_targets, c.applies_to);
      break;
    case Channel::Type::Transparency:
      j["applies_to"] = name_of(photometric_targets, c.applies_to);
      break;
    case Channel::Type::Transformation:
      j["transform"] = name_of(transforms, c.transform);
      j["vector"] = c.vector;
      break;
    case Channel::Type::Audio:
      j["parameter"] = name_of(audio_parameters, c.audio_parameter);
      j["voice"] = c.voice;
      break;
    default:
      break;
  }
  if (c.target)
  {
    j["target"] = interval_json(*c.target);
  }
  if (c.curve != Curve{})
  {
    j["curve"] = curve_json(c.curve);
  }
  return j;
}

bool is_flat(const Json& j)
{
  return std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_primitive(); });
}

// Like dump(2), but arrays of numbers (and arrays of those: path points, tables) stay on one
// line, so that a saved file reads like a hand-written one.
void write(const Json& j, int indent, std::string& out)
{
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  if (j.is_object() && !j.empty())
  {
    out += "{\n";
    std::size_t k = 0;
    for (const auto& item : j.items())
    {
      out += pad + Json(item.key()).dump() + ": ";
      write(item.value(), indent + 2, out);
      out += ++k < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "}";
  }
  else if (j.is_array() && !j.empty() &&
           !std::all_of(j.begin(),
             j.end(),
             [](const Json& e) { return e.is_primitive() || (e.is_array() && is_flat(e)); }))
  {
    out += "[\n";
    for (std::size_t k = 0; k < j.size(); ++k)
    {
      out += pad;
      write(j[k], indent + 2, out);
      out += k + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "]";
  }
  else if (j.is_array())
  {
    out += "[";
    for (std::size_t k = 0; k < j.size(); ++k)
    {
      out += (k ? ", " : "");
      write(j[k], indent, out);
    }
    out += "]";
  }
  else
  {
    out += j.dump();
  }
}

} // namespace

std::string save_mapping(const Spec& spec)
{
  Json doc;
  doc["version"] = spec.version;
  doc["object"] = spec.object;
  doc["parameters"] = spec.parameters;
  doc["world"] = Json{ { "system", name_of(world_systems, spec.world.system) },
    { "resolution", spec.world.resolution },
    { "iso", spec.world.iso } };
  Json coords = Json::object();
  for (const CoordinateMapping& m : spec.coordinates)
  {
    Json channels = Json::array();
    for (const Channel& c : m.channels)
    {
      channels.push_back(channel_json(c, spec.world.system));
    }
    coords[m.name] = channels;
  }
  doc["coordinates"] = coords;
  Json animation{ { "duration", spec.animation.duration }, { "fps", spec.animation.fps } };
  if (const auto& p = spec.animation.path)
  {
    animation["path"] = Json{ { "coordinates", p->coordinates },
      { "points", p->points },
      { "interpolation", name_of(interpolations, p->interpolation) },
      { "closed", p->closed },
      { "timing", name_of(timings, p->timing) },
      { "key_times", p->key_times } };
  }
  if (const auto& g = spec.animation.ghost)
  {
    animation["ghost"] = Json{ { "resolution", g->resolution }, { "tolerance", g->tolerance } };
  }
  doc["animation"] = animation;
  doc["spreadsheet"] = Json{ { "cell_size", spec.spreadsheet.cell_size },
    { "spacing", spec.spreadsheet.spacing },
    { "labels", spec.spreadsheet.labels } };
  const RenderSettings& rs = spec.render;
  doc["render"] = Json{ { "width", rs.width },
    { "height", rs.height },
    { "background", rs.background },
    { "colour", rs.colour },
    { "azimuth", rs.azimuth },
    { "elevation", rs.elevation },
    { "inset", rs.inset },
    { "colour_source", name_of(colour_sources, rs.colour_source) },
    { "method",
      rs.method == rs.frames_method
        ? Json(name_of(render_methods, rs.method))
        : Json{ { "cells", name_of(render_methods, rs.method) },
            { "frames", name_of(render_methods, rs.frames_method) } } },
    { "scene", name_of(render_scenes, rs.scene) } };
  if (rs.view_box)
  {
    doc["render"]["view_box"] = *rs.view_box;
  }
  doc["audio"] = Json{ { "sample_rate", spec.audio.sample_rate } };
  if (const auto& t = spec.topology)
  {
    doc["topology"] = Json{ { "resolution", t->resolution }, { "bisections", t->bisections } };
  }
  std::string text;
  write(doc, 0, text);
  return text + "\n";
}

} // namespace frep::mapping
