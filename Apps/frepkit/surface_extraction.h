// Runs the mesher (frep::mesh::extract_surface / extract_contour) the way every subcommand
// wants it: a progress bar on a terminal, Ctrl-C cancels cleanly, the mesher's errors become
// UserErrors with its message, and the statistics are printed in one format.
#pragma once

#include "Mesh/surface.h"

#include <memory>
#include <string>

namespace frepkit
{

struct ExtractionRun
{
  bool contour = false;      ///< 2-D contour instead of a 3-D surface
  bool show_progress = true; ///< a bar on standard error when it is a terminal
  std::string label = "meshing";
};

/// Extracts, or throws UserError (the mesher's error, or "cancelled").
frep::mesh::ExtractResult run_extraction(std::shared_ptr<const frep::Tape> tape,
  const frep::GridSpec& grid,
  frep::mesh::ExtractOptions options,
  const ExtractionRun& run);

/// "boxes 1234 tested, 800 culled; samples 1.2e+06 of 2.1e+06 dense (57.1%); failed samples 0"
std::string describe_statistics(const frep::mesh::ExtractStatistics& statistics);

/// The warning for `failed` samples that raised run-time errors (empty when there were none).
std::string failed_samples_warning(std::size_t failed);

} // namespace frepkit
