#include "Scene/sample_picture.h"

#include "Eval/thread_pool.h"
#include "Scene/floor_scene.h"
#include "Scene/pictures.h"
#include "Scene/section_mesh.h"
#include "Scene/section_raycast.h"

#include <chrono>
#include <exception>

namespace frep::mapping
{

namespace
{

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// One draw_sample call's arguments, for its two methods.
struct Drawing
{
  const Model& model;
  const std::vector<double>& parameters;
  const Plan& plan;
  const Sample& sample;
  const imaging::Camera& camera;
  int width;
  int height;
  const DrawOptions& options;
  int threads; ///< the pool's participants, or the options' threads
  const mesh::SolidBounds* bounds; ///< the framing's bounds of the sample's solid, or null
};

void draw_by_rays(SamplePicture& p, const Drawing& d)
{
  RaycastOptions ro;
  static_cast<RunControl&>(ro) = d.options;
  ro.progress = nullptr;
  ro.floor = d.options.floor;
  // On the floor scene's board the solid stands on its lowest point.
  const Sample placed =
    d.options.floor
      ? stand_on_floor(
          d.model, d.parameters, d.plan, d.sample, *d.options.floor, d.threads, d.bounds)
      : d.sample;
  ro.bounds = d.bounds;
  RaycastPicture r =
    raycast_sample(d.model, d.parameters, d.plan, placed, d.camera, d.width, d.height, ro);
  if (d.options.cancel_requested())
  {
    p.cancelled = true;
    return;
  }
  p.error = std::move(r.error);
  p.image = std::move(r.image);
}

void draw_by_mesh(SamplePicture& p,
  const Drawing& d,
  const RenderSettings& settings,
  const Framing& framing)
{
  const auto start = Clock::now();
  SectionOptions so;
  static_cast<RunControl&>(so) = d.options;
  so.progress = nullptr;
  so.samples = d.options.samples;
  Section section = make_section(d.model, d.parameters, d.plan, d.sample, so);
  p.failed_samples = section.statistics.failed_samples;
  if (!section.ok())
  {
    p.cancelled = section.cancelled || d.options.cancel_requested();
    p.error = p.cancelled ? std::string() : std::move(section.error);
    return;
  }
  if (d.options.floor)
  {
    stand_on_floor(section, *d.options.floor); // the mesh's lowest vertex on the board
  }
  p.triangles = section.surface.cell_count();
  p.mesh_seconds = seconds_since(start);
  p.image = render_sample(d.plan,
    section,
    d.sample,
    d.camera,
    d.width,
    d.height,
    settings,
    d.threads,
    d.options.floor,
    framing);
}

} // namespace

SamplePicture draw_sample(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& sample,
  const imaging::Camera& camera,
  int width,
  int height,
  const RenderSettings& settings,
  RenderSettings::Method method,
  const DrawOptions& options,
  const Framing& framing)
{
  SamplePicture p;
  if (width < 1 || height < 1)
  {
    p.error = "the picture needs at least one pixel each way";
    return p;
  }
  // Rasterising takes a thread count: the pool's participants, or the options' threads.
  const Drawing drawing{ model,
    parameters,
    plan,
    sample,
    camera,
    width,
    height,
    options,
    options.pool ? options.pool->size() : options.threads,
    framing.solid_of(plan, sample, parameters) };
  const auto start = Clock::now();
  try
  {
    if (method == RenderSettings::Method::Raycast)
    {
      draw_by_rays(p, drawing);
    }
    else
    {
      draw_by_mesh(p, drawing, settings, framing);
    }
  }
  catch (const std::exception& e)
  {
    p.error = e.what();
  }
  if (!p.ok())
  {
    p.image = imaging::Image();
    return p;
  }
  p.render_seconds = seconds_since(start) - p.mesh_seconds;
  return p;
}

} // namespace frep::mapping
