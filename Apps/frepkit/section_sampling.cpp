#include "section_sampling.h"

#include "Sample/grid_sampler.h"
#include "Durable/interrupt_guard.h"
#include "progress_bar.h"
#include "user_error.h"

#include <algorithm>
#include <cstdio>

namespace frepkit
{

SampledSection sample_section(std::shared_ptr<const frep::Tape> tape,
  const frep::GridSpec& grid,
  bool attributes,
  int threads,
  bool show_progress,
  bool sign_only,
  double iso)
{
  SampledSection section;
  section.axes = static_cast<int>(grid.axes.size());
  for (std::size_t i = 0; i < grid.axes.size(); ++i)
  {
    section.samples[i] = grid.axes[i].samples;
    section.origin[i] = grid.axes[i].lo;
    section.spacing[i] = grid.axes[i].step();
  }
  frep::SampleOptions options;
  options.attribute_count = attributes ? -1 : 0;
  options.failures = frep::FailurePolicy::NaN;
  options.max_samples = kMaxSectionSamples;
  options.threads = threads;
  options.sign_only = sign_only; // (with attributes the sampler refuses: check_grid)
  options.iso = iso;
  // Refused before the section's arrays are allocated.
  if (const std::string problem = frep::check_grid(grid, tape->input_count, options);
      !problem.empty())
  {
    char limit[120];
    std::snprintf(limit,
      sizeof limit,
      ". A sampled image or volume may not exceed the limit of %.0f samples; lower --grid",
      kMaxSectionSamples);
    throw UserError("cannot sample the " + std::string(section.axes == 3 ? "volume" : "image") +
                    ": " + problem + limit);
  }
  section.values.resize(section.count());
  const std::size_t s_count = tape->outputs.size() > 0 ? tape->outputs.size() - 1 : 0;
  if (attributes)
  {
    section.attributes.assign(s_count, std::vector<double>(section.count()));
  }

  frep::durable::InterruptGuard interrupt;
  ProgressBar bar("sampling", show_progress);
  options.progress = [&bar](double fraction)
  {
    bar.update(fraction);
    return !frep::durable::InterruptGuard::interrupted();
  };
  const frep::SampleResult result = frep::sample_grid(tape,
    grid,
    options,
    [&section](const frep::SampleBlock& b)
    {
      std::copy_n(b.values, b.count, section.values.begin() + b.first);
      for (std::size_t j = 0; j < section.attributes.size(); ++j)
      {
        std::copy_n(b.attributes[j], b.count, section.attributes[j].begin() + b.first);
      }
    });
  if (result.cancelled)
  {
    throw frep::durable::Interrupted();
  }
  if (!result.ok())
  {
    throw UserError(result.error);
  }
  section.failed = result.errors;
  return section;
}

} // namespace frepkit
