#include "render_command.h"

#include "Durable/atomic_output.h"
#include "box_option.h"
#include "section_axes.h"
#include "Durable/interrupt_guard.h"
#include "mesh_writers/mesh_format.h"
#include "model_loading.h"
#include "number_format.h"
#include "sampling_grid.h"
#include "Imaging/png_writer.h"
#include "user_error.h"

#include "picture_size.h"

#include "Raycast/raycast.h"
#include "Raycast/shape_camera.h"
#include "Imaging/camera.h"
#include "Imaging/image.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

namespace frepkit
{
namespace
{

std::array<float, 3> linear_rgb(const std::vector<double>& srgb, const char* option)
{
  if (srgb.size() != 3)
  {
    throw UserError(std::string(option) + " needs 3 numbers r,g,b in 0..1");
  }
  for (double c : srgb)
  {
    if (!(c >= 0.0 && c <= 1.0))
    {
      throw UserError(std::string(option) + ": every component must be in 0..1");
    }
  }
  const frep::imaging::Rgba c = frep::imaging::srgb(srgb[0], srgb[1], srgb[2]);
  return { c.r, c.g, c.b };
}

} // namespace

CLI::App* add_render_command(CLI::App& app, RenderOptions& options)
{
  CLI::App* cmd = app.add_subcommand("render",
    "One picture of a 3-D cross-section drawn directly from the function by rays (no mesh): "
    "fix the other coordinates by name, the 3 free ones are the box's axes; .png output.");
  cmd->add_option("model", options.model, "Model file (.hf or .vm)")->required();
  cmd
    ->add_option("-o,--output",
      options.output,
      "The picture (.png; written under a temporary name, renamed when complete)")
    ->required();
  cmd->add_option("--fix", options.fix, "Fixed coordinates, e.g. x4=0.5,x5=0.25")->delimiter(',');
  cmd
    ->add_option("--free",
      options.free,
      "The 3 free coordinates in axis order (default: those not fixed, in increasing order)")
    ->delimiter(',');
  cmd->add_option("--object", options.object, "Object; default: my_model, else the first");
  cmd->add_option("-a,--parameters", options.parameters, "Values of a[1], a[2], ...")
    ->delimiter(',');
  cmd
    ->add_option("--box",
      options.box,
      "Box over the free coordinates: xmin,ymin,zmin,xmax,ymax,zmax, or a range per coordinate "
      "by name, x1=-1:1,x2=-1:1,x3=-1:1 (or x=,y=,z=); default: the solid's own bounds plus 5%, "
      "-10..10 on each axis when it is unbounded; the solid is cut by it and the camera frames it")
    ->delimiter(',');
  cmd->add_option("--size", options.size, "Picture size in pixels: WIDTHxHEIGHT or WIDTH,HEIGHT")
    ->capture_default_str();
  cmd
    ->add_option("--view",
      options.view,
      "Camera azimuth,elevation in degrees (default 35,25; azimuth 0 looks along +y)")
    ->delimiter(',')
    ->expected(2);
  cmd->add_option("--colour", options.colour, "Shape colour r,g,b in 0..1 (sRGB)")->delimiter(',');
  cmd->add_option("--background", options.background, "Background r,g,b in 0..1 (sRGB)")
    ->delimiter(',');
  cmd->add_option("--supersample", options.supersample, "Rays per pixel along each axis (1..4)")
    ->capture_default_str()
    ->check(CLI::Range(1, 4));
  cmd->add_flag("--floor",
    options.floor,
    "A checkerboard floor under the shape, at its lowest point (it stands on it), with its shadow");
  cmd
    ->add_option("--frame",
      options.frame,
      "What the camera frames: solid (the solid's outline seen from the view) or box (the box's "
      "bounding sphere)")
    ->capture_default_str()
    ->check(CLI::IsMember({ "solid", "box" }));
  cmd->add_flag("--shadows", options.shadows, "The shape's shadows on itself");
  cmd->add_option("-j,--threads", options.threads, "Worker threads (0 = all cores)")
    ->capture_default_str()
    ->check(CLI::Range(0, 1024));
  cmd->add_flag("-q,--quiet", options.quiet, "No report");
  add_user_input_options(cmd, options.user);
  add_projection_options(cmd, options.projection);
  return cmd;
}

int run_render(const RenderOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  if (lower_extension(options.output) != ".png")
  {
    throw UserError(options.output + ": frepkit render writes .png pictures");
  }
  std::string size_error;
  const std::optional<PictureSize> size = parse_picture_size(options.size, &size_error);
  if (!size)
  {
    throw UserError("--size: " + size_error);
  }
  if (options.view.size() != 2 || !std::isfinite(options.view[0]) ||
      !std::isfinite(options.view[1]))
  {
    throw UserError("--view: azimuth,elevation as two finite numbers of degrees");
  }
  const std::array<float, 3> colour = linear_rgb(options.colour, "--colour");
  const std::array<float, 3> background = linear_rgb(options.background, "--background");

  const frep::LoadedModel loaded = apply_projection(
    load_model(options.model, options.user, options.object, options.parameters.size()),
    options.projection,
    options.parameters,
    options.quiet);
  const frep::ast::Object& object =
    loaded.program->objects[static_cast<std::size_t>(loaded.object)];
  const SectionAxes axes = parse_fix_free(
    fix_projected(options.fix, options.free, options.projection), options.free, object.x_dim);
  if (axes.free.size() != 3)
  {
    throw UserError("frepkit render draws 3-D sections: give 3 free coordinates (" +
                    std::to_string(axes.free.size()) + " are free)");
  }
  const std::shared_ptr<const frep::Model> model = loaded.model;

  frep::raycast::Shape shape;
  shape.tape = model->specialise(axes.specialisation(options.parameters));
  // The solid is cut by this box (its own bounds by default); the camera frames the solid in it.
  const frep::GridSpec grid = make_grid(
    box_or_solid_bounds(parse_box(options.box, axes.free), shape.tape, options.quiet), {}, 3);
  for (int k = 0; k < 3; ++k)
  {
    shape.box[k] = { grid.axes[k].lo, grid.axes[k].hi };
  }
  shape.colour = colour;
  const int width = size->width, height = size->height;
  frep::raycast::ShapeView view;
  view.azimuth_deg = options.view[0];
  view.elevation_deg = options.view[1];
  view.aspect = static_cast<double>(width) / height;
  view.frame_solid = options.frame == "solid";
  view.floor = options.floor;
  view.threads = options.threads;
  const frep::raycast::FramedShape framed = frep::raycast::frame_shape(shape, view);
  const frep::imaging::Camera& camera = framed.camera;

  frep::raycast::Style style;
  style.render.supersample = options.supersample;
  style.self_shadows = options.shadows;
  frep::RunControl run;
  run.threads = options.threads;
  run.cancel = [] { return frep::durable::InterruptGuard::interrupted(); };
  frep::imaging::Image picture(
    width, height, { background[0], background[1], background[2], 1.0F });
  const frep::raycast::Result r = frep::raycast::render(picture,
    camera,
    shape,
    framed.floor ? &*framed.floor : nullptr,
    style,
    nullptr,
    run);
  frep::durable::InterruptGuard::throw_if_interrupted();
  if (!r.ok())
  {
    throw UserError(options.model + ": " + r.error);
  }
  {
    frep::durable::AtomicOutput out(options.output);
    frep::imaging::write_png(out.stream(), width, height, frep::imaging::to_rgb8(picture));
    out.commit();
  }
  if (!options.quiet)
  {
    const frep::raycast::Statistics& s = r.statistics;
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char line[480];
    std::snprintf(line,
      sizeof line,
      "frepkit render: %s (%s) -> %s, %dx%d, %zu rays (%zu in the box, %zu hits), %zu interval "
      "and %zu point evaluations, %zu edge pixels, ray casting %.3f s (shadow map %.3f s, "
      "edges %.3f s), total %.3f s\n",
      object.name.c_str(),
      axes.free_names().c_str(),
      options.output.c_str(),
      width,
      height,
      s.rays,
      s.rays_in_box,
      s.hits,
      s.interval_evaluations,
      s.point_evaluations,
      s.edge_pixels,
      s.seconds,
      s.shadow_seconds,
      s.edge_seconds,
      seconds);
    std::cerr << line;
  }
  return 0;
}

} // namespace frepkit
