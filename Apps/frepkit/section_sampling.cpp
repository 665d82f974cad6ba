#include "section_sampling.h"

#include "Eval/batch_evaluator.h"
#include "interrupt_guard.h"
#include "progress_bar.h"
#include "sampling_grid.h"
#include "user_error.h"

#include <cmath>
#include <cstdio>

namespace frepkit
{

SampledSection sample_section(std::shared_ptr<const frep::Tape> tape,
  const frep::mesh::Grid& grid,
  int axes,
  bool attributes,
  int threads,
  bool show_progress)
{
  const double total = grid_sample_count(grid, axes);
  if (total > kMaxSectionSamples)
  {
    char message[200];
    std::snprintf(message,
      sizeof message,
      "%.0f samples (%s) exceed the limit of %.0f for a sampled image or volume; lower --grid",
      total,
      describe_grid(grid, axes).c_str(),
      kMaxSectionSamples);
    throw UserError(message);
  }
  SampledSection section;
  section.axes = axes;
  for (int k = 0; k < axes; ++k)
  {
    const std::size_t i = static_cast<std::size_t>(k);
    section.samples[i] = grid.samples[i];
    section.origin[i] = grid.lo[i];
    section.spacing[i] = (grid.hi[i] - grid.lo[i]) / static_cast<double>(grid.samples[i] - 1);
  }
  const std::size_t nx = static_cast<std::size_t>(section.samples[0]);
  const std::size_t ny = static_cast<std::size_t>(section.samples[1]);
  const std::size_t nz = static_cast<std::size_t>(section.samples[2]);
  const std::size_t slab = nx * ny;
  section.values.resize(slab * nz);
  const std::size_t s_count = tape->outputs.size() > 0 ? tape->outputs.size() - 1 : 0;
  if (attributes)
  {
    section.attributes.assign(s_count, std::vector<double>(slab * nz));
  }

  // Sample i of axis k at lo + i * (hi - lo) / (samples - 1), as the mesher's grid.
  auto coordinate = [&grid](int axis, std::size_t i)
  {
    const std::size_t a = static_cast<std::size_t>(axis);
    return grid.lo[a] + static_cast<double>(i) * (grid.hi[a] - grid.lo[a]) /
                          static_cast<double>(grid.samples[a] - 1);
  };
  // The x and y coordinates of one slab are the same for every z.
  std::vector<double> xs(slab);
  std::vector<double> ys(slab);
  for (std::size_t j = 0; j < ny; ++j)
  {
    const double y = coordinate(1, j);
    for (std::size_t i = 0; i < nx; ++i)
    {
      xs[i + nx * j] = coordinate(0, i);
      ys[i + nx * j] = y;
    }
  }
  // The last sample sits exactly on the box's maximum, as in the mesher's grid.
  for (std::size_t j = 0; j < ny; ++j)
  {
    xs[nx - 1 + nx * j] = grid.hi[0];
  }
  for (std::size_t i = 0; i < nx; ++i)
  {
    ys[i + nx * (ny - 1)] = grid.hi[1];
  }
  std::vector<double> zs(axes == 3 ? slab : 0);

  frep::BatchOptions options;
  options.threads = threads;
  frep::BatchEvaluator evaluator(tape, options);
  InterruptGuard interrupt;
  ProgressBar bar("sampling", show_progress);
  for (std::size_t k = 0; k < nz; ++k)
  {
    std::vector<const double*> inputs{ xs.data(), ys.data() };
    if (axes == 3)
    {
      const double z = k + 1 == nz ? grid.hi[2] : coordinate(2, k);
      std::fill(zs.begin(), zs.end(), z);
      inputs.push_back(zs.data());
    }
    std::vector<double*> attribute_columns;
    for (auto& column : section.attributes)
    {
      attribute_columns.push_back(column.data() + k * slab);
    }
    section.failed += evaluator.evaluate(
      inputs, slab, section.values.data() + k * slab, nullptr, attribute_columns);
    bar.update(static_cast<double>(k + 1) / static_cast<double>(nz));
    if (InterruptGuard::interrupted())
    {
      throw UserError("cancelled (interrupted); no output written");
    }
  }
  return section;
}

} // namespace frepkit
