// The names the mapping file uses for the spec's enumerations, shared by its reader
// (mapping_json_reader.cpp) and its writer (mapping_json_writer.cpp). Private to FRepKit::MultimediaMapping.
#pragma once

#include "Mapping/mapping_spec.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace frep::mapping::json_names
{

// Ordered: coordinates keep the file's order (a std::map would put "x10" before "x2").
using Json = nlohmann::ordered_json;

template<typename E>
struct Name
{
  std::string_view name;
  E value;
};

inline constexpr Name<Channel::Type> channel_types[] = {
  { "world", Channel::Type::World },
  { "dynamic", Channel::Type::Dynamic },
  { "spreadsheet", Channel::Type::Spreadsheet },
  { "fixed", Channel::Type::Fixed },
  { "colour", Channel::Type::Colour },
  { "transparency", Channel::Type::Transparency },
  { "transformation", Channel::Type::Transformation },
  { "audio", Channel::Type::Audio },
  { "projected", Channel::Type::Projected },
};
inline constexpr Name<WorldSystem> world_systems[] = {
  { "cartesian", WorldSystem::Cartesian },
  { "cylindrical", WorldSystem::Cylindrical },
  { "spherical", WorldSystem::Spherical },
};
inline constexpr Name<int> cartesian_axes[] = { { "x", 0 }, { "y", 1 }, { "z", 2 } };
inline constexpr Name<int> cylindrical_axes[] = { { "r", 0 }, { "phi", 1 }, { "z", 2 } };
inline constexpr Name<int> spherical_axes[] = { { "r", 0 }, { "theta", 1 }, { "phi", 2 } };
// The first three are the names save_mapping writes.
inline constexpr Name<int> grid_axes[] = {
  { "columns", 0 },
  { "rows", 1 },
  { "layers", 2 },
  { "u", 0 },
  { "v", 1 },
  { "w", 2 },
};
inline constexpr Name<PhotometricTarget> photometric_targets[] = {
  { "shape", PhotometricTarget::Shape },
  { "background", PhotometricTarget::Background },
  { "light", PhotometricTarget::Light },
};
inline constexpr Name<Channel::Transform> transforms[] = {
  { "rotate", Channel::Transform::Rotate },
  { "scale", Channel::Transform::Scale },
  { "translate", Channel::Transform::Translate },
};
inline constexpr Name<Channel::AudioParameter> audio_parameters[] = {
  { "pitch", Channel::AudioParameter::Pitch },
  { "loudness", Channel::AudioParameter::Loudness },
  { "timbre", Channel::AudioParameter::Timbre },
};
inline constexpr Name<Path::Interpolation> interpolations[] = {
  { "polyline", Path::Interpolation::Polyline },
  { "catmull-rom", Path::Interpolation::CatmullRom },
};
inline constexpr Name<Path::Timing> timings[] = {
  { "arc-length", Path::Timing::ArcLength },
  { "keys", Path::Timing::Keys },
};
inline constexpr Name<RenderSettings::ColourSource> colour_sources[] = {
  { "uniform", RenderSettings::ColourSource::Uniform },
  { "attributes", RenderSettings::ColourSource::Attributes },
};
inline constexpr Name<RenderSettings::Method> render_methods[] = {
  { "mesh", RenderSettings::Method::Mesh },
  { "raycast", RenderSettings::Method::Raycast },
};
inline constexpr Name<RenderSettings::Scene> render_scenes[] = {
  { "page", RenderSettings::Scene::Page },
  { "floor", RenderSettings::Scene::Floor },
};

template<typename E, std::size_t N>
std::string name_of(const Name<E> (&names)[N], E value)
{
  for (const auto& n : names)
  {
    if (n.value == value)
    {
      return std::string(n.name);
    }
  }
  return std::string(names[0].name);
}

template<typename E, std::size_t N>
std::string name_list(const Name<E> (&names)[N])
{
  std::string list;
  for (const auto& n : names)
  {
    list += (list.empty() ? "" : ", ") + std::string(n.name);
  }
  return list;
}

} // namespace frep::mapping::json_names
