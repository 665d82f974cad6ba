#include "projection_option.h"

#include "Project/projection.h"
#include "number_format.h"
#include "section_axes.h"
#include "user_error.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>

namespace frepkit
{

void add_projection_options(CLI::App* command, ProjectionInput& input)
{
  command->add_option("--project",
    input.along,
    "Project the model along coordinates over ranges (COORDINATE=LO:HI, comma-separated, e.g. "
    "x4=0:1): inside where some value of them puts the point inside, e.g. the volume a moving "
    "solid sweeps. The coordinates keep their numbers; a projected one's value is not read");
  command
    ->add_option("--project-tolerance",
      input.tolerance,
      "The projection's values are within this of the maximum (its sign exact beyond it)")
    ->capture_default_str()
    ->check(CLI::PositiveNumber);
  command
    ->add_option("--project-band",
      input.band,
      "Beyond +-band (in the model's units) only the sign of a projected value is kept: faster; "
      "'inf' keeps every value within the tolerance")
    ->capture_default_str();
}

namespace
{

std::vector<frep::project::CoordinateRange> parse_along(const ProjectionInput& input)
{
  std::string error;
  std::vector<frep::project::CoordinateRange> axes =
    frep::project::parse_eliminated(input.along, error);
  if (!error.empty())
    throw UserError("--project " + error);
  return axes;
}

} // namespace

std::vector<int> projected_coordinates(const ProjectionInput& input)
{
  std::vector<int> coordinates;
  if (!input.along.empty())
    for (const frep::project::CoordinateRange& e : parse_along(input))
      coordinates.push_back(e.coordinate - 1);
  return coordinates;
}

std::vector<std::string> fix_projected(std::vector<std::string> fix,
  const std::vector<std::string>& free, const ProjectionInput& input)
{
  if (input.along.empty())
    return fix;
  std::vector<int> named; // 0-based coordinates --fix or --free names
  for (const std::vector<std::string>* list : { static_cast<const std::vector<std::string>*>(&fix), &free })
    for (const std::string& entry : *list)
      named.push_back(coordinate_index(entry.substr(0, entry.find('='))));
  for (const frep::project::CoordinateRange& e : parse_along(input))
    if (std::find(named.begin(), named.end(), e.coordinate - 1) == named.end())
      fix.push_back("x" + std::to_string(e.coordinate) + "=" + format_double(e.lo));
  return fix;
}

frep::LoadedModel apply_projection(frep::LoadedModel loaded, const ProjectionInput& input,
  const std::vector<double>& parameters, bool quiet)
{
  if (input.along.empty())
    return loaded;
  const std::vector<frep::project::CoordinateRange> axes = parse_along(input);
  frep::project::ProjectionOptions options;
  options.tolerance = input.tolerance;
  options.band = input.band;
  if (!(input.band > input.tolerance)) // NaN too
    throw UserError("--project-band must be greater than --project-tolerance");
  options.parameters = parameters;
  options.keep_coordinates = true;
  frep::LoadedModel projected = frep::project::project(loaded.model, axes, options);
  if (!projected.ok())
    throw UserError("--project " + input.along + ": " +
                    (projected.diagnostics.empty() ? std::string("refused")
                                                   : projected.diagnostics.front().message));
  if (!quiet)
    std::cerr << "frepkit: note: " << loaded.model->name() << " projected along "
              << frep::project::eliminated_text(axes) << " (tolerance " << input.tolerance
              << ")\n";
  return projected;
}

} // namespace frepkit
