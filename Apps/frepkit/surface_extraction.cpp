#include "surface_extraction.h"

#include "Durable/interrupt_guard.h"
#include "progress_bar.h"
#include "user_error.h"

#include <cstdio>

namespace frepkit
{

frep::mesh::ExtractResult run_extraction(std::shared_ptr<const frep::Tape> tape,
  const frep::GridSpec& grid,
  frep::mesh::ExtractOptions options,
  const ExtractionRun& run)
{
  frep::durable::InterruptGuard interrupt;
  ProgressBar bar(run.label, run.show_progress);
  options.progress = [&bar](double fraction)
  {
    bar.update(fraction);
    return !frep::durable::InterruptGuard::interrupted();
  };
  frep::mesh::ExtractResult result =
    run.contour ? frep::mesh::extract_contour(std::move(tape), grid, options)
                : frep::mesh::extract_surface(std::move(tape), grid, options);
  bar.finish();
  if (!result.error.empty())
  {
    throw UserError(result.error);
  }
  if (result.cancelled || frep::durable::InterruptGuard::interrupted())
  {
    throw frep::durable::Interrupted();
  }
  return result;
}

std::string describe_statistics(const frep::mesh::ExtractStatistics& statistics)
{
  char line[256];
  const double dense = static_cast<double>(statistics.dense_samples);
  const double samples = static_cast<double>(statistics.samples);
  std::snprintf(line,
    sizeof line,
    "boxes %zu tested, %zu culled; samples %.4g of %.4g dense (%.1f%%); failed samples %zu",
    statistics.boxes_tested,
    statistics.boxes_culled,
    samples,
    dense,
    dense > 0 ? 100.0 * samples / dense : 0.0,
    statistics.failed_samples);
  return line;
}

std::string failed_samples_warning(std::size_t failed)
{
  if (failed == 0)
  {
    return {};
  }
  return std::to_string(failed) +
         " samples raised a run-time error in the model and were taken as outside (see "
         "'frepkit eval' to locate them)";
}

} // namespace frepkit
