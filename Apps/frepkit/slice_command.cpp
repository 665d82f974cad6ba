#include "slice_command.h"

#include "Compiler/attribute_rgb.h"
#include "Durable/atomic_output.h"
#include "box_option.h"
#include "section_axes.h"
#include "mesh_writers/mesh_format.h"
#include "mesh_writers/vtp_writer.h"
#include "model_loading.h"
#include "number_format.h"
#include "sampling_grid.h"
#include "section_sampling.h"
#include "Imaging/png_writer.h"
#include "section_writers/section_image.h"
#include "section_writers/vti_writer.h"
#include "surface_extraction.h"
#include "surface_output.h"
#include "user_error.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace frepkit
{
namespace
{

enum class SliceKind
{
  Png,     ///< 2 free: a picture
  Image,   ///< 2 or 3 free: .vti, the sampled F
  Contour, ///< 2 free: .vtp lines
  Mesh     ///< 3 free: a mesh format
};

const char* const kSliceFormats = "2 free coordinates: .png (picture), .vti (sampled F), .vtp "
                                  "(contour lines); 3 free: .stl .obj .ply .wrl .pov .vtp "
                                  "(mesh), .vti (sampled volume)";

SliceKind slice_kind(const std::string& path, std::size_t free_count)
{
  const std::string extension = lower_extension(path);
  if (extension == ".png")
  {
    if (free_count != 2)
    {
      throw UserError(path + ": a .png needs 2 free coordinates (" + kSliceFormats + ")");
    }
    return SliceKind::Png;
  }
  if (extension == ".vti")
  {
    return SliceKind::Image;
  }
  if (extension == ".vtp" && free_count == 2)
  {
    return SliceKind::Contour;
  }
  if (mesh_format_for(path))
  {
    if (free_count != 3)
    {
      throw UserError(path + ": a mesh needs 3 free coordinates (" + kSliceFormats + ")");
    }
    return SliceKind::Mesh;
  }
  throw UserError(path + ": unknown slice format " +
                  (extension.empty() ? std::string("(no extension)") : "'" + extension + "'") +
                  "; " + kSliceFormats);
}

void require_available(SliceKind kind, const std::string& path)
{
#ifndef FREPKIT_HAVE_VTK
  if (kind != SliceKind::Mesh)
  {
    throw UserError(path + ": " + lower_extension(path) +
                    " is not available in this build (built with FREPKIT_ENABLE_VTK off)");
  }
#else
  (void)kind;
  (void)path;
#endif
}

/// "x3 = 0, x4 = 0.5"
std::string describe_fixed(const SectionAxes& axes)
{
  std::string text;
  for (std::size_t i = 0; i < axes.fixed.size(); ++i)
  {
    if (axes.fixed[i])
    {
      text += (text.empty() ? "x" : ", x") + std::to_string(i + 1) + " = " +
              format_short(*axes.fixed[i]);
    }
  }
  return text;
}

} // namespace

CLI::App* add_slice_command(CLI::App& app, SliceOptions& options)
{
  CLI::App* slice = app.add_subcommand("slice",
    "A cross-section of an n-D model: fix coordinates by name, the free ones (2 or 3) drive the "
    "output. " +
      std::string(kSliceFormats) + ".");
  slice->add_option("model", options.model, "HyperFun model file (.hf)")->required();
  slice
    ->add_option("-o,--output",
      options.output,
      "Output file; its extension chooses the format (written under a temporary name, renamed "
      "when complete)")
    ->required();
  slice
    ->add_option("--fix",
      options.fix,
      "Fixed coordinates, e.g. x4=0.5,x5=0.25 (every coordinate not listed in --free must be "
      "fixed)")
    ->delimiter(',');
  slice
    ->add_option("--free",
      options.free,
      "The free coordinates in axis order, e.g. x1,x3 (default: the coordinates not fixed, in "
      "increasing order); 2 or 3 of them")
    ->delimiter(',');
  slice->add_option("--object",
    options.object,
    "Object (case-insensitive); default: my_model, else the first object");
  slice
    ->add_option("-a,--parameters",
      options.parameters,
      "Values of a[1], a[2], ... separated by commas (missing ones are 0)")
    ->delimiter(',');
  slice
    ->add_option("--box",
      options.box,
      "Box over the free coordinates: all minima then all maxima (4 or 6 numbers), or a range per "
      "free coordinate by name, x1=-1:1,x3=-1:1 (or x=,y=,z= in axis order); default: the "
      "solid's own bounds plus 5%, -10..10 on each axis when it is unbounded")
    ->delimiter(',');
  slice
    ->add_option("--grid",
      options.grid,
      "Samples per axis: N or one per free axis (default 128); an image has one pixel per sample")
    ->delimiter(',');
  slice->add_option("--iso", options.iso, "Iso value: F >= iso is inside")->capture_default_str();
  slice->add_flag("--ascii", options.ascii, "ASCII STL instead of binary (3 free, .stl)");
  slice->add_flag("--no-cap", options.no_cap, "Leave a mesh open where it meets the box");
  slice->add_flag("--no-normals", options.no_normals, "Do not write per-point normals (meshes)");
  slice->add_option("-j,--threads", options.threads, "Worker threads (0 = all cores)")
    ->capture_default_str()
    ->check(CLI::Range(0, 1024));
  slice->add_flag("-q,--quiet", options.quiet, "No progress bar and no report (warnings remain)");
  add_user_input_options(slice, options.user);
  add_projection_options(slice, options.projection);
  return slice;
}

int run_slice(const SliceOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  const frep::LoadedModel loaded = apply_projection(
    load_model(options.model, options.user, options.object, options.parameters.size()),
    options.projection,
    options.parameters,
    options.quiet);
  const frep::ast::Object& object =
    loaded.program->objects[static_cast<std::size_t>(loaded.object)];
  const SectionAxes axes = parse_fix_free(
    fix_projected(options.fix, options.free, options.projection), options.free, object.x_dim);
  const int axis_count = static_cast<int>(axes.free.size());
  const SliceKind kind = slice_kind(options.output, axes.free.size());
  require_available(kind, options.output);
  const std::shared_ptr<const frep::Model> model = loaded.model;
  const std::shared_ptr<const frep::Tape> tape =
    model->specialise(axes.specialisation(options.parameters));
  const frep::GridSpec grid =
    make_grid(box_or_solid_bounds(parse_box(options.box, axes.free), tape, options.quiet),
      options.grid,
      axis_count);
  const bool colours = frep::tape_sets_colours(*tape, object.s_dim);
  const bool attributes = frep::tape_sets_attributes(*tape, static_cast<std::size_t>(object.s_dim));
  const std::string fixed = describe_fixed(axes);

  if (kind == SliceKind::Mesh)
  {
    SurfaceJob job;
    job.start = start;
    job.tape = tape;
    job.grid = grid;
    job.extract.iso = options.iso;
    job.extract.cap_boundary = !options.no_cap;
    job.extract.threads = options.threads;
    job.format = require_mesh_format(options.output);
    job.ascii = options.ascii;
    job.normals = !options.no_normals;
    job.colours = colours;
    job.attributes = attributes;
    job.quiet = options.quiet;
    job.output = options.output;
    job.name = object.name;
    job.source = options.model;
    return write_surface_file(std::move(job));
  }

  frep::durable::AtomicOutput output(options.output);
  std::string summary;
  std::size_t failed = 0;
  if (kind == SliceKind::Contour)
  {
    frep::mesh::ExtractOptions extract;
    extract.iso = options.iso;
    extract.normals = false;
    extract.attributes = attributes;
    extract.threads = options.threads;
    ExtractionRun run;
    run.contour = true;
    run.show_progress = !options.quiet;
    run.label = "contouring";
    const frep::mesh::ExtractResult result = run_extraction(tape, grid, extract, run);
    MeshDocument document;
    document.surface = &result.surface;
    document.name = object.name;
    document.source = options.model;
    if (colours)
    {
      document.colours = frep::attribute_colours(result.surface.attributes,
        static_cast<std::size_t>(result.surface.attribute_count),
        result.surface.point_count());
    }
    write_vtp(document, output.stream());
    failed = result.statistics.failed_samples;
    summary = std::to_string(result.surface.cell_count()) + " segments, " +
              std::to_string(result.surface.point_count()) + " points";
    if (result.surface.cell_count() == 0)
    {
      std::cerr << "frepkit: warning: no contour in the box; wrote an empty .vtp\n";
    }
  }
  else
  {
    // A picture without colours shows each sample's side of iso only: tiles proved wholly on
    // one side are not evaluated (the picture is the same bit for bit; .vti files get F).
    const bool want_attributes = (kind == SliceKind::Image && attributes) || colours;
    SampledSection section = sample_section(tape,
      grid,
      want_attributes,
      options.threads,
      !options.quiet,
      kind == SliceKind::Png && !want_attributes,
      options.iso);
    for (int k = 0; k < axis_count; ++k)
    {
      section.axis_names[static_cast<std::size_t>(k)] =
        "x" + std::to_string(axes.free[static_cast<std::size_t>(k)] + 1);
    }
    failed = section.failed;
    std::size_t inside = 0;
    for (double value : section.values)
    {
      inside += value >= options.iso ? 1 : 0;
    }
    if (kind == SliceKind::Png)
    {
      frep::imaging::write_png(output.stream(),
        section.samples[0],
        section.samples[1],
        render_section(section, options.iso, colours));
      summary = std::to_string(section.samples[0]) + " x " + std::to_string(section.samples[1]) +
                " image" + (colours ? " coloured by s[1..3]" : "");
    }
    else
    {
      write_vti(output.stream(), section);
      summary = "sampled F";
    }
    summary +=
      ", " + std::to_string(inside) + " of " + std::to_string(section.count()) + " samples inside";
  }
  output.commit();

  if (const std::string warning = failed_samples_warning(failed); !warning.empty())
  {
    std::cerr << "frepkit: warning: " << warning
              << (kind == SliceKind::Png ? "; they are magenta in the picture" : "") << '\n';
  }
  if (!options.quiet)
  {
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char time[32];
    std::snprintf(time, sizeof time, "%.3g s", seconds);
    std::cout << options.output << ": " << summary << ", " << time << " (axes " << axes.free_names()
              << (fixed.empty() ? "" : "; " + fixed) << "; " << describe_grid(grid)
              << "); failed samples " << failed << '\n';
  }
  return 0;
}

} // namespace frepkit
