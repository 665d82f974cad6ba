#include "Scene/section_raycast.h"

#include "Scene/section_mesh.h"

#include "Mapping/colour_maps.h"
#include "Mapping/unit_map.h"


#include <algorithm>
#include <exception>
#include <optional>

namespace frep::mapping
{

bool raycast_supported(const Plan& plan, std::string* why)
{
  std::string reason;
  if (world_is_affine(plan, &reason))
  {
    return true;
  }
  if (why)
  {
    *why = "the ray caster " + reason;
  }
  return false;
}

std::array<double, 12> raycast_world_map(const Plan& plan, const Sample& sample)
{
  // Per axis w = s m + o (a linear channel), then the sample's 4 x 4 transform T: W = T (S m + o).
  std::array<double, 3> s{}, o{};
  for (int k = 0; k < 3; ++k)
  {
    const Interval range = plan.model_box[k], target = plan.world_targets[k];
    s[k] = (target.hi - target.lo) / (range.hi - range.lo);
    o[k] = target.lo - s[k] * range.lo;
  }
  const std::array<double, 16>& t = sample.transform;
  std::array<double, 12> m{};
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      m[4 * r + c] = t[4 * r + c] * s[c];
    }
    m[4 * r + 3] = t[4 * r] * o[0] + t[4 * r + 1] * o[1] + t[4 * r + 2] * o[2] + t[4 * r + 3];
  }
  return m;
}

RaycastPicture raycast_sample(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& sample,
  const imaging::Camera& camera,
  int width,
  int height,
  const RaycastOptions& options)
{
  RaycastPicture picture;
  picture.image = imaging::Image(width,
    height,
    imaging::srgb(sample.background[0], sample.background[1], sample.background[2]));
  std::string why;
  if (!raycast_supported(plan, &why))
  {
    picture.error = why;
    return picture;
  }
  if (static_cast<int>(sample.values.size()) != model.x_dim())
  {
    picture.error = "the sample has " + std::to_string(sample.values.size()) +
                    " coordinate values, the model " + std::to_string(model.x_dim()) +
                    " coordinates";
    return picture;
  }
  raycast::Shape shape;
  try
  {
    shape.tape = model.specialise(section_specialisation(plan, sample, parameters));
  }
  catch (const std::exception& e)
  {
    picture.error = std::string("specialisation failed: ") + e.what();
    return picture;
  }
  for (int k = 0; k < 3; ++k)
  {
    shape.box[k] = frep::Interval{ plan.model_box[k].lo, plan.model_box[k].hi };
  }
  shape.to_world = raycast_world_map(plan, sample);
  if (options.bounds)
  {
    shape.bounds = *options.bounds;
  }
  const imaging::Rgba c = imaging::srgb(sample.colour[0], sample.colour[1], sample.colour[2]);
  shape.colour = { c.r, c.g, c.b };
  shape.opacity = std::clamp(sample.opacity, 0.0, 1.0);

  // Colours per hit, by the rules make_section applies per vertex.
  const VertexColouring& vc = plan.vertex_colouring;
  std::optional<ChannelMap> colour_map_of_axis;
  int axis = -1;
  if (vc.source == VertexColouring::Source::WorldCoordinate)
  {
    for (int k = 0; k < 3; ++k)
    {
      axis = plan.world_coordinates[k] == vc.coordinate ? k : axis;
    }
    ChannelMap::Result map = ChannelMap::make(vc.range, vc.curve, mapping::Interval{ 0.0, 1.0 });
    if (!map.ok() || axis < 0)
    {
      picture.error =
        "vertex colours: " + (map.ok() ? "the coordinate is not a world one" : map.error);
      return picture;
    }
    const std::optional<int> component = colour_component(vc.colormap);
    const std::array<double, 3> base = sample.colour;
    const std::string name = vc.colormap;
    const ChannelMap unit = map.map;
    shape.colour_function = [=](const std::array<double, 3>& m, std::span<const double>)
    {
      const double v = std::clamp(unit.forward(m[axis]), 0.0, 1.0);
      Rgb rgb = base;
      if (component)
      {
        rgb[*component] = v;
      }
      else if (const std::optional<Rgb> mapped = colour_map(name, v))
      {
        rgb = *mapped;
      }
      return std::array<float, 3>{ imaging::srgb_to_linear(static_cast<float>(rgb[0])),
        imaging::srgb_to_linear(static_cast<float>(rgb[1])),
        imaging::srgb_to_linear(static_cast<float>(rgb[2])) };
    };
  }
  else if (vc.source == VertexColouring::Source::Attributes && shape.tape->outputs.size() > 1)
  {
    // s[1..3] as make_section reads them from the mesher (floats), then as sRGB like
    // render_sample treats vertex colours.
    shape.colour_function = raycast::attribute_colours();
  }

  raycast::Style style;
  // 3 x 3 rays at the edges of small pictures (FRepStudio's cells), 2 x 2 from 200 pixels up:
  // a 300-pixel cell of the demo's spreadsheet costs 1.9 s instead of 3.0 s at 3 x 3.
  style.render.supersample = std::max(width, height) <= 200 ? 3 : 2;
  for (auto& light : style.render.lights)
  {
    light.intensity *= sample.light_intensity;
  }
  style.render.ambient *= sample.light_intensity;
  style.self_shadows = options.self_shadows;
  const raycast::Result r =
    raycast::render(picture.image, camera, shape, options.floor, style, nullptr, options);
  picture.statistics = r.statistics;
  picture.error = r.error;
  return picture;
}

} // namespace frep::mapping
