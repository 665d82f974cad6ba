#include "Morph/key_frame.h"

#include "Mesh/solid_bounds.h"
#include "Sample/grid.h"
#include "Sample/grid_sampler.h"

#include <cmath>
#include <exception>

namespace frep::morph
{

std::optional<Alignment> alignment_from_name(std::string_view name)
{
  if (name == "none")
    return Alignment::None;
  if (name == "centroid")
    return Alignment::Centroid;
  if (name == "size")
    return Alignment::CentroidAndSize;
  return std::nullopt;
}

std::string_view alignment_name(Alignment alignment)
{
  switch (alignment)
  {
    case Alignment::None:
      return "none";
    case Alignment::Centroid:
      return "centroid";
    case Alignment::CentroidAndSize:
      return "size";
  }
  return "none";
}

KeyFrame measure_key_frame(const std::shared_ptr<const Tape>& tape, int samples)
{
  KeyFrame frame;
  try
  {
    const mesh::SolidBounds bounds = mesh::find_solid_bounds(tape);
    if (!bounds.bounded())
    {
      frame.error = bounds.status == mesh::SolidBounds::Status::Empty
                      ? "the key's solid is empty"
                      : "the key's solid is not bounded (it reaches 1000 units)";
      return frame;
    }
    const std::size_t d = bounds.box.size();
    std::vector<double> lo(d), hi(d);
    std::vector<std::int64_t> count(d, samples);
    double cell = 1.0;
    for (std::size_t k = 0; k < d; ++k)
    {
      lo[k] = bounds.box[k].lo;
      hi[k] = bounds.box[k].hi;
      cell *= (hi[k] - lo[k]) / (samples - 1);
    }
    SampleOptions options;
    options.sign_only = true; // only the side matters
    options.threads = 1;      // a key at a time; the caller may measure keys side by side
    std::vector<double> sum(d, 0.0);
    const SampleResult result = sample_grid(tape,
      box_grid(lo, hi, count),
      options,
      [&](const SampleBlock& block)
      {
        for (std::size_t p = 0; p < block.count; ++p)
        {
          if (block.failed[p] || !(block.values[p] >= 0.0))
            continue;
          ++frame.inside;
          for (std::size_t k = 0; k < d; ++k)
            sum[k] += block.coordinates[k][p];
        }
      });
    if (!result.ok())
    {
      frame.error = result.error.empty() ? "cancelled" : result.error;
      return frame;
    }
    if (frame.inside == 0)
    {
      frame.error = "no sample of the key's bounds is inside (a solid thinner than the grid)";
      return frame;
    }
    frame.centroid.resize(d);
    for (std::size_t k = 0; k < d; ++k)
      frame.centroid[k] = sum[k] / static_cast<double>(frame.inside);
    frame.size = std::pow(static_cast<double>(frame.inside) * cell, 1.0 / static_cast<double>(d));
  }
  catch (const std::exception& e)
  {
    frame.error = e.what();
  }
  return frame;
}

} // namespace frep::morph
