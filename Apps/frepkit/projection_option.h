// --project COORDINATE=LO:HI[,...] and --project-tolerance for the subcommands that draw a model
// (mesh, slice, render): the model replaced by its projection along those coordinates
// (FRep/Project), which keeps the model's numbering, so --axes/--fix/--free speak of the same
// coordinates as without it (a projected coordinate's value is read by nothing).
#pragma once

#include "Compiler/load_model.h"

#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace frepkit
{

struct ProjectionInput
{
  std::string along;         ///< --project, e.g. "x4=0:1"; empty: no projection
  double tolerance = 1e-4;   ///< --project-tolerance
  double band = 0.1;         ///< --project-band
};

void add_projection_options(CLI::App* command, ProjectionInput& input);

/// The coordinates --project names (0-based; empty without it).
std::vector<int> projected_coordinates(const ProjectionInput& input);

/// --fix with every projected coordinate the user did not fix or free himself fixed at its
/// range's start (its value is read by nothing): slice and render need no --fix for them.
std::vector<std::string> fix_projected(std::vector<std::string> fix,
  const std::vector<std::string>& free, const ProjectionInput& input);

/// `loaded` projected as `input` says (returned as it is without --project), its a[] fixed at
/// `parameters`. A bad range or coordinate is a UserError naming the option. Prints a note
/// saying what was projected unless `quiet`.
frep::LoadedModel apply_projection(frep::LoadedModel loaded, const ProjectionInput& input,
  const std::vector<double>& parameters, bool quiet);

} // namespace frepkit
