#include "mesh_command.h"

#include "Compiler/attribute_rgb.h"
#include "box_option.h"
#include "projection_option.h"
#include "section_axes.h"
#include "mesh_writers/mesh_format.h"
#include "model_loading.h"
#include "sampling_grid.h"
#include "surface_output.h"
#include "user_error.h"

#include <CLI/CLI.hpp>

#include <algorithm>

#include <algorithm>
#include <chrono>
#include <iostream>

namespace frepkit
{

CLI::App* add_mesh_command(CLI::App& app, MeshOptions& options)
{
  CLI::App* mesh = app.add_subcommand("mesh",
    "Extract the surface F = iso of a model as a watertight, outward-oriented triangle mesh. "
    "The output's extension chooses the format: " +
      mesh_format_list() + ".");
  mesh->add_option("model", options.model, "HyperFun model file (.hf)")->required();
  mesh
    ->add_option("-o,--output",
      options.output,
      "Output mesh file (written under a temporary name, renamed when complete)")
    ->required();
  mesh->add_option("--object",
    options.object,
    "Object to mesh (case-insensitive); default: my_model, else the first object");
  mesh
    ->add_option("-a,--parameters",
      options.parameters,
      "Values of a[1], a[2], ... separated by commas (missing ones are 0)")
    ->delimiter(',');
  mesh
    ->add_option("--box",
      options.box,
      "Sampled box: xmin,ymin,zmin,xmax,ymax,zmax (all minima, then all maxima) or a range per "
      "axis by name, x1=-1:1,x2=-1:1,x3=-1:1 (the coordinates --axes puts on X, Y, Z; or "
      "x=-1:1,y=-1:1,z=-1:1); default: the solid's own bounds plus 5%, found by interval "
      "subdivision; -10..10 on each axis when it is unbounded")
    ->delimiter(',');
  mesh
    ->add_option("--grid",
      options.grid,
      "Samples per axis: N or NX,NY,NZ (default 128; samples, not cells: hfp's -g G is G+1 "
      "samples)")
    ->delimiter(',');
  mesh->add_option("--iso", options.iso, "Iso value: the surface is F = iso, F >= iso inside")
    ->capture_default_str();
  mesh->add_option("--axes,--map",
    options.axes,
    "Which coordinates the axes drive, as hfp's -x: one entry per x[i], X/Y/Z for the axes and "
    "numbers for fixed coordinates (e.g. X,Y,Z,0.25 meshes x4 = 0.25). Default: X,Y,Z and any "
    "further coordinates fixed at 0 (with a note). --map is the former name");
  mesh->add_flag("--ascii", options.ascii, "Write ASCII STL instead of binary");
  mesh->add_flag("--no-cap",
    options.no_cap,
    "Leave the mesh open where the solid meets the box (default: closed by the box faces)");
  mesh->add_flag("--no-normals",
    options.no_normals,
    "Do not compute or write per-point normals (from the model's gradient)");
  mesh
    ->add_option("--refine",
      options.refine,
      "Root refinement steps per point along its grid edge (0 = linear interpolation)")
    ->capture_default_str()
    ->check(CLI::Range(0, 60));
  mesh->add_option("-j,--threads", options.threads, "Worker threads (0 = all cores)")
    ->capture_default_str()
    ->check(CLI::Range(0, 1024));
  mesh->add_flag("-q,--quiet", options.quiet, "No progress bar and no report (warnings remain)");
  add_user_input_options(mesh, options.user);
  add_projection_options(mesh, options.projection);
  return mesh;
}

namespace
{

// Without --axes the coordinates beyond x3 are fixed at 0: say so, except for the projected
// ones (their value is read by nothing).
void note_default_fixed(const frep::ast::Object& object, const std::vector<int>& projected)
{
  std::string fixed;
  int count = 0;
  for (int i = 3; i < object.x_dim; ++i)
    if (std::find(projected.begin(), projected.end(), i) == projected.end())
    {
      fixed += (fixed.empty() ? "x" : ", x") + std::to_string(i + 1);
      ++count;
    }
  if (count > 0)
    std::cerr << "frepkit: note: " << object.name << " has x[" << object.x_dim << "]: " << fixed
              << (count == 1 ? " is" : " are")
              << " fixed at 0 (choose with --axes, e.g. --axes X,Y,Z,0.5)\n";
}

} // namespace

int run_mesh(const MeshOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  const MeshFormat format = require_mesh_format(options.output);
  const frep::LoadedModel loaded = apply_projection(
    load_model(options.model, options.user, options.object, options.parameters.size()),
    options.projection,
    options.parameters,
    options.quiet);
  const frep::ast::Object& object =
    loaded.program->objects[static_cast<std::size_t>(loaded.object)];

  SectionAxes axes;
  if (options.axes)
  {
    axes = parse_axes_option(*options.axes, object.x_dim);
  }
  else
  {
    if (object.x_dim < 3)
    {
      throw UserError(
        object.name + " has x[" + std::to_string(object.x_dim) +
        "]: a surface needs 3 coordinates (for a 2-D model use 'frepkit slice' to draw its "
        "contour)");
    }
    axes = default_axes(object.x_dim, 3);
    note_default_fixed(object, projected_coordinates(options.projection));
  }
  const std::shared_ptr<const frep::Model> model = loaded.model;
  SurfaceJob job;
  job.start = start;
  job.tape = model->specialise(axes.specialisation(options.parameters));
  job.grid =
    make_grid(box_or_solid_bounds(parse_box(options.box, axes.free), job.tape, options.quiet),
      options.grid,
      3);
  job.extract.iso = options.iso;
  job.extract.cap_boundary = !options.no_cap;
  job.extract.refine_steps = options.refine;
  job.extract.threads = options.threads;
  job.format = format;
  job.ascii = options.ascii;
  job.normals = !options.no_normals;
  job.colours = frep::tape_sets_colours(*job.tape, object.s_dim);
  job.attributes = frep::tape_sets_attributes(*job.tape, static_cast<std::size_t>(object.s_dim));
  job.quiet = options.quiet;
  job.output = options.output;
  job.name = object.name;
  job.source = options.model;
  return write_surface_file(std::move(job));
}

} // namespace frepkit
