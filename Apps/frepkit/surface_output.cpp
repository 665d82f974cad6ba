#include "surface_output.h"

#include "Compiler/attribute_rgb.h"
#include "Durable/atomic_output.h"
#include "number_format.h"
#include "sampling_grid.h"
#include "surface_extraction.h"

#include <chrono>
#include <cstdio>
#include <iostream>

namespace frepkit
{

int write_surface_file(SurfaceJob job)
{
  // Opened first: an unwritable output fails before the work, and a failure later removes it.
  frep::durable::AtomicOutput output(job.output);

  job.extract.normals = job.normals && job.format != MeshFormat::Stl;
  job.extract.attributes = job.colours || (job.attributes && job.format == MeshFormat::Vtp);
  ExtractionRun run;
  run.show_progress = !job.quiet;
  const frep::mesh::ExtractResult result = run_extraction(job.tape, job.grid, job.extract, run);
  const frep::mesh::Surface& surface = result.surface;

  MeshDocument document;
  document.surface = &surface;
  document.name = job.name;
  document.source = job.source;
  document.set_box(job.grid);
  document.normals = job.normals;
  if (job.colours)
  {
    document.colours = frep::attribute_colours(
      surface.attributes, static_cast<std::size_t>(surface.attribute_count), surface.point_count());
  }
  write_mesh(document, job.format, job.ascii, output.stream());
  output.commit();

  if (const std::string warning = failed_samples_warning(result.statistics.failed_samples);
      !warning.empty())
  {
    std::cerr << "frepkit: warning: " << warning << '\n';
  }
  if (surface.cell_count() == 0)
  {
    std::cerr << "frepkit: warning: no surface in the box (F = " << format_short(job.extract.iso)
              << " is not crossed on the " << describe_grid(job.grid)
              << "); wrote an empty mesh to " << job.output << '\n';
  }
  if (!job.quiet)
  {
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - job.start).count();
    char line[160];
    std::snprintf(line,
      sizeof line,
      "%zu triangles, %zu points, %.3g s",
      surface.cell_count(),
      surface.point_count(),
      seconds);
    std::cout << job.output << ": " << line << " (" << describe_grid(job.grid)
              << (job.colours ? "; colours from s[1..3]" : "") << ")\n  "
              << describe_statistics(result.statistics) << '\n';
  }
  return 0;
}

} // namespace frepkit
