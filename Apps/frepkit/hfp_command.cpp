#include "hfp_command.h"

#include "Compiler/attribute_rgb.h"
#include "Eval/point_evaluator.h"
#include "Durable/atomic_output.h"
#include "section_axes.h"
#include "hfp_arguments.h"
#include "Durable/interrupt_guard.h"
#include "mesh_writers/mesh_format.h"
#include "model_loading.h"
#include "progress_bar.h"
#include "section_writers/cli_writer.h"
#include "section_writers/contour_loops.h"
#include "surface_extraction.h"
#include "user_error.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

namespace frepkit
{
namespace
{

/// -t: "Time to ...: 0.0123 s" per stage, as hfp's timer reported its stages.
class StageTimer
{
public:
  explicit StageTimer(bool enabled)
    : enabled_(enabled)
  {
  }
  void stage(const char* name)
  {
    const auto now = std::chrono::steady_clock::now();
    if (enabled_)
    {
      std::printf("%s: %.4f s\n", name, std::chrono::duration<double>(now - last_).count());
    }
    last_ = now;
  }

private:
  bool enabled_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

/// The specialisation of -x: the three mapped coordinates are free (in X, Y, Z order), the others
/// take -x's constants (0 beyond the list, as hfp's x array).
SectionAxes hfp_axes(const HfpArguments& a, const frep::ast::Object& object)
{
  SectionAxes axes;
  for (int axis = 0; axis < 3; ++axis)
  {
    const int index = a.xyz_mapping[static_cast<std::size_t>(axis)];
    if (index >= object.x_dim)
    {
      throw UserError(object.name + " has x[" + std::to_string(object.x_dim) + "]: the " +
                      std::string(1, static_cast<char>('X' + axis)) + " axis would drive x[" +
                      std::to_string(index + 1) +
                      "] (see -x); a surface needs 3 of the model's coordinates");
    }
    axes.free.push_back(index);
  }
  axes.fixed.resize(static_cast<std::size_t>(object.x_dim));
  for (int i = 0; i < object.x_dim; ++i)
  {
    const bool free = i == a.xyz_mapping[0] || i == a.xyz_mapping[1] || i == a.xyz_mapping[2];
    if (!free)
    {
      axes.fixed[static_cast<std::size_t>(i)] =
        static_cast<std::size_t>(i) < a.x_constants.size()
          ? a.x_constants[static_cast<std::size_t>(i)]
          : 0.0;
    }
  }
  return axes;
}

/// -s D: hfp refined each vertex to D cells; bisection halves the interval per step.
int refine_steps(const HfpArguments& a)
{
  if (!a.search)
  {
    return 0;
  }
  return static_cast<int>(std::ceil(std::log2(1.0 / a.search_fraction)));
}

struct OutputFile
{
  MeshFormat format;
  bool ascii;
  std::string path;
};

int run_cli_layers(const HfpArguments& a,
  const frep::Model& model,
  const SectionAxes& axes,
  StageTimer& timer)
{
  const double zmin = a.box[2];
  const double zmax = a.box[5];
  const double dz = a.slicing_step[2];
  frep::durable::AtomicOutput output(a.cli_name);
  write_cli_header(output.stream());

  frep::GridSpec grid;
  for (std::size_t k = 0; k < 2; ++k)
  {
    const double lo = a.box[k];
    const double hi = a.box[k + 3];
    const double cells = std::ceil((hi - lo) / a.slicing_step[k] - 1e-9);
    grid.axes.push_back(
      { lo, hi, std::max<std::int64_t>(2, static_cast<std::int64_t>(cells) + 1) });
  }
  std::cout << "Z range: [" << zmin << "; " << zmax << "]\n";

  frep::mesh::ExtractOptions extract;
  extract.iso = a.iso;
  extract.normals = false;
  extract.attributes = false;
  ExtractionRun run;
  run.contour = true;
  run.show_progress = false;

  frep::durable::InterruptGuard interrupt;
  ProgressBar bar("slicing", true);
  const std::size_t layer_count =
    zmin < zmax ? static_cast<std::size_t>(std::ceil((zmax - zmin) / dz)) : 0;
  int layers = 0;
  std::size_t failed = 0;
  for (std::size_t i = 0;; ++i)
  {
    const double z = zmin + static_cast<double>(i) * dz;
    if (!(z < zmax))
    {
      break;
    }
    // The section z = const: the Z axis's coordinate fixed, X and Y the contour's inputs.
    SectionAxes layer = axes;
    layer.fixed[static_cast<std::size_t>(axes.free[2])] = z;
    layer.free.pop_back();
    const frep::Specialisation specialisation = layer.specialisation(a.parameters);
    const std::shared_ptr<const frep::Tape> tape = model.specialise(specialisation);
    const frep::mesh::ExtractResult result = run_extraction(tape, grid, extract, run);
    failed += result.statistics.failed_samples;
    frep::PointEvaluator corner(tape);
    const double corner_point[2] = { grid.axes[0].lo, grid.axes[1].lo };
    const bool box_inside = corner.value(corner_point) >= a.iso;
    const std::vector<ContourLoop> loops = close_contour_loops(result.surface,
      { grid.axes[0].lo, grid.axes[1].lo },
      { grid.axes[0].hi, grid.axes[1].hi },
      box_inside);
    if (!loops.empty())
    {
      write_cli_layer(output.stream(), z, loops);
      ++layers;
    }
    bar.update(
      layer_count > 0 ? static_cast<double>(i + 1) / static_cast<double>(layer_count) : 1.0);
    if (frep::durable::InterruptGuard::interrupted())
    {
      throw frep::durable::Interrupted();
    }
  }
  bar.finish();
  write_cli_end(output.stream());
  output.commit();
  timer.stage("Time to Slice and Write the CLI File");

  if (const std::string warning = failed_samples_warning(failed); !warning.empty())
  {
    std::cerr << "frepkit: warning: " << warning << '\n';
  }
  std::cout << "\n" << layers << " layers have been successfully written\n";
  std::cout << "triangles: " << -layers << '\n';
  if (layers == 0)
  {
    std::cerr << "Isosurface not generated.\n";
    return 1;
  }
  return 0;
}

/// hfp's order: wrl, stl (ASCII, which wins over -stlb), pov; a path named twice is written
/// once, by the last format (hfp overwrote it).
std::vector<OutputFile> hfp_output_files(const HfpArguments& a)
{
  std::vector<OutputFile> files;
  if (a.wrl)
  {
    files.push_back({ MeshFormat::Vrml, false, a.wrl_name });
  }
  if (a.stl || a.stlb)
  {
    files.push_back({ MeshFormat::Stl, a.stl, a.stl_name });
  }
  if (a.pov)
  {
    files.push_back({ MeshFormat::Pov, false, a.pov_name });
  }
  for (std::size_t i = 0; i < files.size(); ++i)
  {
    for (std::size_t j = i + 1; j < files.size(); ++j)
    {
      if (files[j].path == files[i].path)
      {
        files.erase(files.begin() + static_cast<std::ptrdiff_t>(i));
        --i;
        break;
      }
    }
  }
  return files;
}

} // namespace

int run_hfp(const std::vector<std::string>& args)
{
  const HfpParseResult parsed = parse_hfp_arguments(args, std::cout);
  switch (parsed.status)
  {
    case HfpParseStatus::Help:
      std::cout << "Usage:\n" << hfp_help_text();
      return 0;
    case HfpParseStatus::NoArguments:
      std::cerr << "No arguments specified.\nCheck Usage!\n\n" << hfp_help_text();
      return 1;
    case HfpParseStatus::NoModel:
      std::cerr << "No Model specified.\nCheck Usage!\n\n" << hfp_help_text();
      return 1;
    case HfpParseStatus::Ok:
      break;
  }
  const HfpArguments& a = parsed.arguments;
  StageTimer timer(a.time_report);

  if (!std::ifstream(a.model, std::ios::binary))
  {
    throw UserError("File: " + a.model + " not found");
  }
  const frep::LoadedProgram program = load_program(a.model);
  require_parsed(program);
  // hfp's rule: the object named exactly (names are stored in lower case), else the first.
  const int object_index =
    frep::ast::select_object(*program.program, a.object, frep::ast::NameMatch::Exact);
  if (object_index < 0)
  {
    throw UserError(a.model + ": the file defines no object");
  }
  frep::LoadOptions by_index;
  by_index.object = program.program->objects[static_cast<std::size_t>(object_index)].name;
  const frep::LoadedModel loaded = frep::compile_object(program, by_index);
  if (!loaded.ok())
  {
    std::cerr << loaded.message();
    throw UserError(a.model + ": the object cannot be compiled");
  }
  const frep::ast::Object& object = program.program->objects[static_cast<std::size_t>(object_index)];
  const std::shared_ptr<const frep::Model> model = loaded.model;
  timer.stage("Time to Read and Parse File");

  const SectionAxes axes = hfp_axes(a, object);
  if (a.reduce)
  {
    std::cout << "note: -r (reduce polygons) is not done by frepkit\n";
  }
  if (a.cli)
  {
    if (a.wrl || a.stl || a.stlb || a.pov)
    {
      std::cout << "note: -cli writes only the CLI file (as hfp): no -wrl/-stl/-stlb/-pov output\n";
    }
    return run_cli_layers(a, *model, axes, timer);
  }

  const std::shared_ptr<const frep::Tape> tape =
    model->specialise(axes.specialisation(a.parameters));
  if (a.attributes && object.s_dim < 3)
  {
    std::cout << "note: -ct: " << object.name << " has s[" << object.s_dim
              << "]: the missing colour components are 0\n";
  }

  const std::vector<OutputFile> files = hfp_output_files(a);
  // Opened before the work: an unwritable path fails at once and nothing is left behind.
  std::vector<std::unique_ptr<frep::durable::AtomicOutput>> outputs;
  for (const OutputFile& file : files)
  {
    outputs.push_back(std::make_unique<frep::durable::AtomicOutput>(file.path));
  }

  frep::GridSpec grid;
  for (std::size_t k = 0; k < 3; ++k)
  {
    grid.axes.push_back({ a.box[k], a.box[k + 3], a.grid[k] + 1 }); // hfp's -g counts cells
  }
  frep::mesh::ExtractOptions extract;
  extract.iso = a.iso;
  extract.normals = a.normals && (a.wrl || a.pov);
  extract.attributes = a.attributes;
  extract.refine_steps = refine_steps(a);
  ExtractionRun run;
  const frep::mesh::ExtractResult result = run_extraction(tape, grid, extract, run);
  const frep::mesh::Surface& surface = result.surface;
  timer.stage("Time to Polygonize");
  if (a.time_report)
  {
    std::cout << "  " << describe_statistics(result.statistics) << '\n';
  }

  MeshDocument document;
  document.surface = &surface;
  document.name = object.name;
  document.source = a.model;
  document.set_box(grid);
  document.normals = a.normals;
  for (std::size_t k = 0; k < 3; ++k)
  {
    document.face_colour[k] = static_cast<float>(a.face_colour[k]);
  }
  if (a.attributes)
  {
    document.colours = frep::attribute_colours(
      surface.attributes, static_cast<std::size_t>(surface.attribute_count), surface.point_count());
  }
  for (std::size_t i = 0; i < files.size(); ++i)
  {
    // hfp named the ASCII solid after the file.
    document.name = files[i].format == MeshFormat::Stl ? files[i].path : object.name;
    write_mesh(document, files[i].format, files[i].ascii, outputs[i]->stream());
    outputs[i]->commit();
  }
  timer.stage("Time to Write Files");

  if (const std::string warning = failed_samples_warning(result.statistics.failed_samples);
      !warning.empty())
  {
    std::cerr << "frepkit: warning: " << warning << '\n';
  }
  std::cout << "triangles: " << surface.cell_count() << '\n';
  if (surface.cell_count() == 0)
  {
    std::cerr << "Isosurface not generated.\n";
    return 1;
  }
  return 0;
}

} // namespace frepkit
