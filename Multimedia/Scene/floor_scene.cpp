#include "Scene/floor_scene.h"

#include "Scene/pictures.h"
#include "Scene/section_raycast.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

namespace frep::mapping
{
namespace
{

// The spreadsheet's node values of coordinate `name`, if it has a spreadsheet channel.
std::vector<double> spreadsheet_values(const Spec& spec, const std::string& name)
{
  for (const CoordinateMapping& m : spec.coordinates)
  {
    if (m.name != name)
    {
      continue;
    }
    for (const Channel& c : m.channels)
    {
      if (c.type == Channel::Type::Spreadsheet && c.values.size() >= 2)
      {
        return c.values;
      }
    }
  }
  return {};
}

// Squares along one plane axis: centred on the spreadsheet's node values when they are evenly
// spaced (then square k is cell k), else 8 over the range. Returns {origin, size, count}.
std::array<double, 3> squares_along(const Spec& spec, const std::string& name, Interval range)
{
  const std::vector<double> values = spreadsheet_values(spec, name);
  if (values.size() >= 2)
  {
    const double step = values[1] - values[0];
    bool even = step > 0.0;
    for (std::size_t i = 2; i < values.size() && even; ++i)
    {
      even = std::abs((values[i] - values[i - 1]) - step) <= 1e-9 * std::abs(step);
    }
    if (even)
    {
      return { values.front() - 0.5 * step, step, static_cast<double>(values.size()) };
    }
  }
  const double lo = std::min(range.lo, range.hi), hi = std::max(range.lo, range.hi);
  return { lo, (hi - lo) / 8.0, 8.0 };
}

} // namespace

FloorScene make_floor_scene(const Plan& plan,
  const Spec& spec,
  double aspect,
  const Framing& framing)
{
  FloorScene scene;
  if (plan.dynamic_coordinates.size() != 2)
  {
    return scene;
  }
  const RenderSettings& settings = spec.render;
  const std::array<Interval, 3> shown = shown_box(plan, settings, framing);
  std::array<double, 3> lo, hi;
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = shown[k].lo;
    hi[k] = shown[k].hi;
  }
  // One square of the board is about half the shape's box: the shape stands out over the
  // board yet the board is large enough to read as the spreadsheet laid flat.
  const double shape_size = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const std::array<double, 3> u = squares_along(spec, plan.dynamic_coordinates[0], plan.path_plane[0]);
  const std::array<double, 3> v = squares_along(spec, plan.dynamic_coordinates[1], plan.path_plane[1]);
  const double world_square = 0.55 * shape_size;
  // u runs along +x; v along -y, so that from the default camera (looking along +y) v grows
  // towards the viewer, as the spreadsheet's rows grow down the page.
  const double sx = world_square / u[1], sy = -world_square / v[1];
  const double columns = u[2], rows = v[2];
  scene.plane_to_floor = { -sx * (u[0] + 0.5 * columns * u[1]), sx, -sy * (v[0] + 0.5 * rows * v[1]), sy };
  raycast::Floor& f = scene.floor;
  f.height = lo[2];
  f.square = world_square;
  f.columns = static_cast<int>(columns);
  f.rows = static_cast<int>(rows);
  f.origin = { -0.5 * columns * world_square, -0.5 * rows * world_square };
  f.path_width = 0.06 * world_square;
  for (const std::vector<double>& p : plan.path_polyline)
  {
    if (p.size() >= 2)
    {
      f.path.push_back(scene.plane_to_floor[0] + sx * p[0]);
      f.path.push_back(scene.plane_to_floor[2] + sy * p[1]);
    }
  }
  // The shape's box stands on the floor by its bottom centre.
  scene.shape_anchor = { 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), lo[2] };

  // The camera sees the board and each frame's shape where it stands (its solid's box when the
  // framing has it, else the shape's box; not one box over the whole board, which leaves the sky
  // over the board's far corners empty).
  std::vector<imaging::Vec3> seen;
  for (int c = 0; c < 4; ++c)
  {
    seen.push_back({ f.origin[0] + (c & 1 ? columns * world_square : 0.0),
      f.origin[1] + (c & 2 ? rows * world_square : 0.0),
      f.height });
  }
  scene.ok = true;
  const bool own = framing.frames.size() == plan.frames.size() && !settings.view_box;
  for (std::size_t k = 0; k < plan.frames.size(); ++k)
  {
    const Sample& frame = plan.frames[k];
    if (own && !framing.frames[k])
    {
      continue; // no solid in this frame
    }
    const std::array<Interval, 3> b =
      own ? *framing.frames[k] : std::array<Interval, 3>{ shown[0], shown[1], shown[2] };
    // on_floor's move, and stand_on_floor's: the solid's bottom on the board.
    const std::array<double, 16> m = on_floor(scene, frame).transform;
    const double dx = m[3] - frame.transform[3], dy = m[7] - frame.transform[7];
    for (int c = 0; c < 8; ++c)
    {
      seen.push_back({ (c & 1 ? b[0].hi : b[0].lo) + dx,
        (c & 2 ? b[1].hi : b[1].lo) + dy,
        f.height + (c & 4 ? b[2].hi - b[2].lo : 0.0) });
    }
  }
  imaging::FitOptions fit;
  fit.fill = 0.92;
  fit.free_bottom = caption_band(spec.render.height); // the frames' caption
  scene.camera =
    imaging::fit_points(seen, aspect, settings.azimuth, std::max(settings.elevation, 30.0), fit);
  return scene;
}

Sample on_floor(const FloorScene& scene, const Sample& frame)
{
  Sample s = frame;
  if (!scene.ok || frame.path_point.size() < 2)
  {
    return s;
  }
  const double x = scene.plane_to_floor[0] + scene.plane_to_floor[1] * frame.path_point[0];
  const double y = scene.plane_to_floor[2] + scene.plane_to_floor[3] * frame.path_point[1];
  const std::array<double, 3> t{ x - scene.shape_anchor[0], y - scene.shape_anchor[1], 0.0 };
  for (int r = 0; r < 3; ++r)
  {
    s.transform[4 * r + 3] += t[r]; // translation after the frame's own transform
  }
  return s;
}

double stand_on_floor(Section& section, const raycast::Floor& floor)
{
  mesh::Surface& surface = section.surface;
  if (surface.dimension != 3 || surface.points.empty())
  {
    return 0.0;
  }
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 2; i < surface.points.size(); i += 3)
  {
    lowest = std::min(lowest, surface.points[i]);
  }
  const double dz = floor.height - lowest;
  for (std::size_t i = 2; i < surface.points.size(); i += 3)
  {
    surface.points[i] += dz; // a translation: normals and orientation stay
  }
  return dz;
}

Sample stand_on_floor(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& frame,
  const raycast::Floor& floor,
  int threads,
  const mesh::SolidBounds* bounds)
{
  if (!raycast_supported(plan) || static_cast<int>(frame.values.size()) != model.x_dim())
  {
    return frame;
  }
  raycast::Shape shape;
  try
  {
    shape.tape = model.specialise(section_specialisation(plan, frame, parameters));
  }
  catch (const std::exception&)
  {
    return frame; // raycast_sample reports the same failure when it draws the frame
  }
  for (int k = 0; k < 3; ++k)
  {
    shape.box[k] = frep::Interval{ plan.model_box[k].lo, plan.model_box[k].hi };
  }
  shape.to_world = raycast_world_map(plan, frame);
  if (bounds)
  {
    shape.bounds = *bounds;
  }
  const std::optional<double> lowest = raycast::lowest_z(shape, 128, threads);
  Sample s = frame;
  if (lowest)
  {
    s.transform[4 * 2 + 3] += floor.height - *lowest; // world z after the frame's transform
  }
  return s;
}

} // namespace frep::mapping
