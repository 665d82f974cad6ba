// produce, phase 6b: the animation's ghost (ghost.png), the union of every shape the animation
// shows: the sectioned model driven along the path through its dynamic coordinates
// (project::path_family) and projected along the path's parameter, meshed and drawn from the
// frames' view angles, fitted to its own box. Exact within the projection's tolerance, between frames too (a union of the
// frames' meshes would miss what a shape passes through between two of them).
#include "Production/detail/phases.h"

#include "Project/path_family.h"
#include "Project/projection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace frep::mapping::production
{
namespace
{

struct GhostPath
{
  std::vector<project::PathPiece> pieces;
  std::vector<int> coordinates; // 1-based model coordinates
};

// The path's pieces; one dynamic coordinate without a path goes through every value of its
// frames, which (a continuous function of time) are all those between the least and the most.
GhostPath ghost_path(const Plan& plan, const ModelCoordinates& coordinates)
{
  GhostPath g;
  if (!plan.path_pieces.empty())
  {
    g.pieces = plan.path_pieces;
    for (const int c : plan.path_model_coordinates)
      g.coordinates.push_back(c + 1);
    return g;
  }
  const auto name = std::find(coordinates.names.begin(), coordinates.names.end(),
    plan.dynamic_coordinates.front());
  const auto c = static_cast<std::size_t>(name - coordinates.names.begin());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Sample& f : plan.frames)
  {
    lo = std::min(lo, f.values[c]);
    hi = std::max(hi, f.values[c]);
  }
  g.pieces = { project::PathPiece{ { lo, hi - lo, 0.0, 0.0 } } };
  g.coordinates = { static_cast<int>(c) + 1 };
  return g;
}

std::shared_ptr<const Model> ghost_model(const Job& job, const GhostSettings& settings)
{
  const GhostPath path = ghost_path(job.plan, job.coordinates);
  const Model& source = job.section_source();
  const LoadedModel family = project::path_family(
    job.sectioned, path.coordinates, path.pieces, job.inputs.parameters);
  if (!family.ok())
    throw ProductionError("the ghost: " + family.message());
  project::ProjectionOptions options;
  options.tolerance = settings.tolerance;
  // The mesher needs exact values only next to the surface (its roots are refined along the
  // edges, where values within the band are exact): a narrow band lets a point well outside
  // stop early. Meta5D's ghost, a point's search: 55.6 boxes of t at band 0.1, 15.8 at 0.01.
  options.band = 10.0 * settings.tolerance;
  const int t = source.x_dim() + 1; // the path's parameter; the result keeps x1..xn
  const LoadedModel ghost = project::project(family.model, { { t, 0.0, 1.0 } }, options);
  if (!ghost.ok())
    throw ProductionError("the ghost: " + ghost.message());
  return ghost.model;
}


// The camera of the frames' view angles fitted to the ghost's own world box: the union is larger
// than any one frame's shape, so the frames' camera (fitted to their view) would cut it.
imaging::Camera ghost_camera(const mesh::Surface& surface, const RenderSettings& render)
{
  std::array<double, 3> lo{ INFINITY, INFINITY, INFINITY }, hi{ -INFINITY, -INFINITY, -INFINITY };
  for (std::size_t p = 0; p < surface.point_count(); ++p)
    for (std::size_t a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], surface.points[3 * p + a]);
      hi[a] = std::max(hi[a], surface.points[3 * p + a]);
    }
  return box_camera(lo, hi, static_cast<double>(render.width) / render.height, render.azimuth,
    render.elevation);
}

} // namespace

void render_ghost(const Job& job, Workers& workers, Record& record)
{
  const auto t0 = Clock::now();
  const Plan& plan = job.plan;
  const GhostSettings& settings = *job.spec().animation.ghost;
  const RenderSettings& render = job.spec().render;
  const std::shared_ptr<const Model> ghost = ghost_model(job, settings);
  SectionOptions options;
  options.threads = workers.count();
  options.cancel = [&job] { return job.stopped(); };
  options.samples.fill(settings.resolution);
  // The first frame's values and transform: the dynamic coordinates are read by nothing, the
  // others stay what every frame has; the colour is the render's (no one frame's).
  Sample sample = plan.frames.front();
  sample.colour = render.colour;
  sample.label = "ghost";
  const Section section = make_section(*ghost, job.inputs.parameters, plan, sample, options);
  job.throw_if_stopped();
  if (section.cancelled)
    throw Stopped();
  if (!section.ok())
    throw ProductionError("the ghost: " + section.error);
  const double mesh_seconds = seconds_since(t0);
  const std::size_t triangles = section.surface.cell_count();
  // An empty ghost is the background (render_sample draws nothing else then).
  const imaging::Camera camera = triangles == 0
    ? plan_camera(plan, render, static_cast<double>(render.width) / render.height, job.framing)
    : ghost_camera(section.surface, render);
  const imaging::Image image = render_sample(plan, section, sample, camera, render.width,
    render.height, render, workers.count(), nullptr, job.framing);
  write_png_file(job.options.directory / "ghost.png", image);
  workers.advance();
  record.files.push_back({ { "file", "ghost.png" },
    { "kind", "ghost" },
    { "width", image.width },
    { "height", image.height },
    { "coordinates", plan.dynamic_coordinates },
    { "resolution", settings.resolution },
    { "tolerance", settings.tolerance },
    { "triangles", triangles } });
  record.stages.push_back({ "ghost",
    seconds_since(t0),
    std::to_string(triangles) + " triangles at " + std::to_string(settings.resolution) +
      "^3 (mesh " + std::to_string(mesh_seconds).substr(0, 5) + " s)" });
}

} // namespace frep::mapping::production
