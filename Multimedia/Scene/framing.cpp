#include "Scene/framing.h"

#include "Scene/section_mesh.h"
#include "Scene/section_raycast.h"

#include "Raycast/raycast.h"

#include "Eval/thread_pool.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <exception>
#include <limits>
#include <string>

namespace frep::mapping
{
namespace
{

using Box = std::array<Interval, 3>;

// The hull of the box's eight corners moved by the row-major 4 x 4 transform.
Box moved(const Box& box, const std::array<double, 16>& m)
{
  Box out;
  for (int r = 0; r < 3; ++r)
  {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int c = 0; c < 8; ++c)
    {
      const double p[3] = {
        c & 1 ? box[0].hi : box[0].lo, c & 2 ? box[1].hi : box[1].lo, c & 4 ? box[2].hi : box[2].lo
      };
      const double w = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
      lo = std::min(lo, w);
      hi = std::max(hi, w);
    }
    out[static_cast<std::size_t>(r)] = Interval{ lo, hi };
  }
  return out;
}

struct Seen
{
  Box world; // the solid's world box
  Box view;  // its extent along the view's right, up and forward
  std::optional<mesh::SolidBounds> bounds; // in the model box (3-D sections only)
};

Box extent_in(const imaging::CameraFrame& view,
  const std::vector<imaging::Vec3>& points,
  double widen)
{
  Box e;
  const std::array<const imaging::Vec3*, 3> axes{ &view.right, &view.up, &view.forward };
  for (std::size_t k = 0; k < 3; ++k)
  {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const imaging::Vec3& p : points)
    {
      const imaging::Vec3& a = *axes[k];
      const double v = a[0] * p[0] + a[1] * p[1] + a[2] * p[2];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    const double w = k < 2 ? widen : 0.0; // across the view only
    e[k] = Interval{ lo - w, hi + w };
  }
  return e;
}

std::vector<imaging::Vec3> corners_of(const Box& b)
{
  std::vector<imaging::Vec3> corners(8);
  for (int c = 0; c < 8; ++c)
  {
    corners[static_cast<std::size_t>(c)] = {
      c & 1 ? b[0].hi : b[0].lo, c & 2 ? b[1].hi : b[1].lo, c & 4 ? b[2].hi : b[2].lo
    };
  }
  return corners;
}

// Points on the faces of the model box (17 per edge; flat in z for 2 axes) in world space,
// moved by the transform: the outline of the box's image, bent or not.
std::vector<imaging::Vec3> image_of(const WorldMapping& world,
  const Box& box,
  const std::array<double, 16>& m,
  int axes)
{
  constexpr int n = 17;
  std::vector<imaging::Vec3> points;
  const int nz = axes == 3 ? n : 1;
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        if (i != 0 && i != n - 1 && j != 0 && j != n - 1 && k != 0 && k != nz - 1)
        {
          continue; // inside the box
        }
        const auto at = [&](int a, int index, int count) {
          return count == 1 ? box[a].lo : box[a].lo + (box[a].hi - box[a].lo) * index / (count - 1);
        };
        const std::array<double, 3> w = world.to_world({ at(0, i, n), at(1, j, n), at(2, k, nz) });
        points.push_back({ m[0] * w[0] + m[1] * w[1] + m[2] * w[2] + m[3],
          m[4] * w[0] + m[5] * w[1] + m[6] * w[2] + m[7],
          m[8] * w[0] + m[9] * w[1] + m[10] * w[2] + m[11] });
      }
    }
  }
  return points;
}

// The sample's solid: its world box and, with a view, its extent seen along it (from its
// silhouette when the plan can be ray-cast, else from the image of its bounds). Empty: no solid.
std::optional<Seen> see(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const WorldMapping& world,
  const imaging::CameraFrame* view,
  const Sample& sample)
{
  const int axes = plan.world_coordinates[2] >= 0 ? 3 : 2;
  if (plan.world_coordinates[0] < 0 || plan.world_coordinates[1] < 0 ||
      static_cast<int>(sample.values.size()) != model.x_dim())
  {
    return std::nullopt;
  }
  try
  {
    raycast::Shape shape;
    shape.tape = model.specialise(section_specialisation(plan, sample, parameters));
    std::vector<frep::Interval> box;
    for (int k = 0; k < axes; ++k)
    {
      box.push_back(frep::Interval{ plan.model_box[k].lo, plan.model_box[k].hi });
    }
    shape.bounds = raycast::solid_bounds(shape.tape, box);
    if (!shape.bounds->bounded())
    {
      return std::nullopt;
    }
    Box model_box{ Interval{ 0.0, 0.0 }, Interval{ 0.0, 0.0 }, Interval{ 0.0, 0.0 } };
    for (int k = 0; k < axes; ++k)
    {
      model_box[k] = Interval{ shape.bounds->box[k].lo, shape.bounds->box[k].hi };
    }
    Seen seen;
    seen.world = moved(world.world_box(model_box), sample.transform);
    if (axes == 3)
    {
      seen.bounds = shape.bounds;
    }
    if (!view)
    {
      return seen;
    }
    raycast::Silhouette s;
    if (axes == 3 && raycast_supported(plan))
    {
      for (int k = 0; k < 3; ++k)
      {
        shape.box[k] = box[k];
      }
      shape.to_world = raycast_world_map(plan, sample);
      s = raycast::silhouette(shape, *view);
    }
    seen.view = s.points.empty()
                  ? extent_in(*view, image_of(world, model_box, sample.transform, axes), 0.0)
                  : extent_in(*view, s.points, s.spacing);
    return seen;
  }
  catch (const std::exception&)
  {
    return std::nullopt; // the section's picture reports the same failure
  }
}

std::vector<std::uint64_t> bits_of(const std::vector<double>& values)
{
  std::vector<std::uint64_t> bits(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    bits[i] = std::bit_cast<std::uint64_t>(values[i]);
  }
  return bits;
}

Box join(const Box& a, const Box& b)
{
  Box u;
  for (std::size_t k = 0; k < 3; ++k)
  {
    u[k] = Interval{ std::min(a[k].lo, b[k].lo), std::max(a[k].hi, b[k].hi) };
  }
  return u;
}

} // namespace

std::optional<std::array<Interval, 3>> solid_world_box(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& sample)
{
  std::string error;
  const std::unique_ptr<WorldMapping> world = WorldMapping::make(plan, error);
  const std::optional<Seen> seen =
    world ? see(model, parameters, plan, *world, nullptr, sample) : std::nullopt;
  return seen ? std::optional<Box>(seen->world) : std::nullopt;
}

const mesh::SolidBounds* Framing::solid_of(const Plan& plan,
  const Sample& sample,
  const std::vector<double>& with) const
{
  for (std::size_t k = 0; k < 3; ++k)
  {
    if (plan.model_box[k].lo != model_box[k].lo || plan.model_box[k].hi != model_box[k].hi)
    {
      return nullptr;
    }
  }
  if (with != parameters)
  {
    return nullptr;
  }
  const auto found = solids.find(bits_of(sample.values));
  return found == solids.end() ? nullptr : &found->second;
}

Framing frame_solids(const RenderSettings& settings,
  const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const RunControl& run)
{
  std::string error;
  const std::unique_ptr<WorldMapping> world = WorldMapping::make(plan, error);
  if (settings.view_box || !world)
  {
    return {}; // a world curve that does not compile: the pictures report it
  }
  std::vector<const Sample*> samples{ &plan.still };
  for (const Sample& s : plan.cells)
  {
    samples.push_back(&s);
  }
  for (const Sample& s : plan.frames)
  {
    samples.push_back(&s);
  }
  const imaging::CameraFrame view = imaging::view_frame(settings.azimuth, settings.elevation);
  std::vector<std::optional<Seen>> seen(samples.size());
  std::atomic<bool> stop{ false };
  std::atomic<std::size_t> done{ 0 };
  double reported = 0.0; // by the calling thread only
  const auto look = [&](std::size_t i, int slot)
  {
    if (stop.load(std::memory_order_relaxed) || run.cancel_requested())
    {
      stop = true;
      return;
    }
    seen[i] = see(model, parameters, plan, *world, &view, *samples[i]);
    const std::size_t finished = done.fetch_add(1) + 1;
    if (slot == 0 && run.progress) // the calling thread is slot 0: progress is reported there
    {
      reported = static_cast<double>(finished) / static_cast<double>(samples.size());
      stop = stop || !run.progress(reported);
    }
  };
  run.thread_pool()->parallel_for(samples.size(), look);
  if (stop)
  {
    Framing stopped;
    stopped.cancelled = true;
    return stopped;
  }
  if (run.progress && reported < 1.0)
  {
    run.progress(1.0); // another thread saw the last sample
  }
  Framing framing;
  framing.parameters = parameters;
  framing.model_box = plan.model_box;
  std::optional<Box> across; // the union of the extents along the view
  for (std::size_t i = 0; i < seen.size(); ++i)
  {
    const std::optional<Seen>& s = seen[i];
    if (s && s->bounds)
    {
      framing.solids.emplace(bits_of(samples[i]->values), *s->bounds);
    }
    if (s)
    {
      framing.box = framing.box ? join(*framing.box, s->world) : s->world;
      across = across ? join(*across, s->view) : s->view;
    }
  }
  const std::size_t first_frame = 1 + plan.cells.size();
  for (std::size_t k = 0; framing.box && k < plan.frames.size(); ++k)
  {
    const std::optional<Seen>& s = seen[first_frame + k];
    framing.frames.push_back(s ? std::optional<Box>(s->world) : std::nullopt);
  }
  if (across)
  {
    for (const imaging::Vec3& c : corners_of(*across)) // view coordinates -> world
    {
      framing.outline.push_back({ c[0] * view.right[0] + c[1] * view.up[0] + c[2] * view.forward[0],
        c[0] * view.right[1] + c[1] * view.up[1] + c[2] * view.forward[1],
        c[0] * view.right[2] + c[1] * view.up[2] + c[2] * view.forward[2] });
    }
  }
  return framing;
}

std::array<Interval, 3> shown_box(const Plan& plan,
  const RenderSettings& settings,
  const Framing& framing)
{
  if (settings.view_box)
  {
    const std::array<double, 6>& v = *settings.view_box;
    return { Interval{ v[0], v[3] }, Interval{ v[1], v[4] }, Interval{ v[2], v[5] } };
  }
  return framing.box ? *framing.box : plan.world_box;
}

} // namespace frep::mapping
