#include "Morph/key_distance.h"

#include "Mesh/solid_bounds.h"
#include "Sample/grid.h"
#include "Sample/grid_sampler.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <vector>

namespace frep::morph
{
namespace
{

// A squared distance no grid reaches: finite, so that the envelope's arithmetic has no inf - inf.
constexpr double kFar = 1e30;

// One line of the squared distance transform: d[p] = min over q of f[q] + ((p - q) h)^2, the
// lower envelope of parabolas (Felzenszwalb and Huttenlocher 2012), in O(n). `f` and `d` are
// strided views of the volume; `v` and `z` are scratch of n and n + 1 entries.
void transform_line(double* line,
  std::size_t stride,
  int n,
  double h,
  std::vector<double>& f,
  std::vector<int>& v,
  std::vector<double>& z)
{
  for (int i = 0; i < n; ++i)
    f[static_cast<std::size_t>(i)] = line[static_cast<std::size_t>(i) * stride];
  const auto x = [h](int i) { return i * h; };
  const auto meet = [&](int q, int p)
  {
    const double fq = f[static_cast<std::size_t>(q)], fp = f[static_cast<std::size_t>(p)];
    return ((fq + x(q) * x(q)) - (fp + x(p) * x(p))) / (2.0 * (x(q) - x(p)));
  };
  int k = 0;
  v[0] = 0;
  z[0] = -kFar;
  z[1] = kFar;
  for (int q = 1; q < n; ++q)
  {
    double s = meet(q, v[static_cast<std::size_t>(k)]);
    while (k > 0 && s <= z[static_cast<std::size_t>(k)])
    {
      --k;
      s = meet(q, v[static_cast<std::size_t>(k)]);
    }
    ++k;
    v[static_cast<std::size_t>(k)] = q;
    z[static_cast<std::size_t>(k)] = s;
    z[static_cast<std::size_t>(k) + 1] = kFar;
  }
  k = 0;
  for (int p = 0; p < n; ++p)
  {
    while (z[static_cast<std::size_t>(k) + 1] < x(p))
      ++k;
    const int q = v[static_cast<std::size_t>(k)];
    const double dx = x(p) - x(q);
    line[static_cast<std::size_t>(p) * stride] =
      std::min(kFar, dx * dx + f[static_cast<std::size_t>(q)]);
  }
}

// Squared distance from every sample to the nearest sample where `seed` is true (kFar if none).
std::vector<double> squared_distance(const std::vector<bool>& seed, const shapes::VolumeGrid& grid)
{
  std::vector<double> d(seed.size());
  for (std::size_t i = 0; i < seed.size(); ++i)
    d[i] = seed[i] ? 0.0 : kFar;
  const auto& n = grid.dims;
  const std::size_t stride[3] = { 1,
    static_cast<std::size_t>(n[0]),
    static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) };
  const int largest = std::max({ n[0], n[1], n[2] });
  std::vector<double> f(static_cast<std::size_t>(largest));
  std::vector<int> v(static_cast<std::size_t>(largest));
  std::vector<double> z(static_cast<std::size_t>(largest) + 1);
  for (int axis = 0; axis < 3; ++axis)
  {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3; // the other two axes
    for (int j = 0; j < n[b]; ++j)
      for (int i = 0; i < n[a]; ++i)
        transform_line(d.data() + static_cast<std::size_t>(i) * stride[a] +
                         static_cast<std::size_t>(j) * stride[b],
          stride[axis],
          n[axis],
          grid.spacing[axis],
          f,
          v,
          z);
  }
  return d;
}

// A grid over the solid's bounds padded by an eighth of their largest side, its origin and
// spacing dyadic (they print exactly in a decimal file).
shapes::VolumeGrid padded_grid(const mesh::SolidBounds& bounds, int samples)
{
  double side = 0.0;
  for (const Interval& axis : bounds.box)
    side = std::max(side, axis.hi - axis.lo);
  const double pad = side / 8.0;
  shapes::VolumeGrid grid;
  for (int k = 0; k < 3; ++k)
  {
    const Interval& axis = bounds.box[static_cast<std::size_t>(k)];
    const double lo = std::floor((axis.lo - pad) * 1024.0) / 1024.0;
    const double step = std::ceil((axis.hi + pad - lo) / (samples - 1) * 1024.0) / 1024.0;
    grid.dims[static_cast<std::size_t>(k)] = samples;
    grid.origin[static_cast<std::size_t>(k)] = lo;
    grid.spacing[static_cast<std::size_t>(k)] = step;
  }
  return grid;
}

} // namespace

std::optional<Normalisation> normalisation_from_name(std::string_view name)
{
  if (name == "none")
    return Normalisation::None;
  if (name == "distance")
    return Normalisation::Distance;
  return std::nullopt;
}

std::string_view normalisation_name(Normalisation normalisation)
{
  return normalisation == Normalisation::Distance ? "distance" : "none";
}

KeyDistance measure_key_distance(const std::shared_ptr<const Tape>& tape, int samples)
{
  KeyDistance result;
  try
  {
    if (tape->input_count != 3)
      return KeyDistance{ {}, 0.0, "distances are sampled for 3-D keys only" };
    const mesh::SolidBounds bounds = mesh::find_solid_bounds(tape);
    if (!bounds.bounded())
      return KeyDistance{ {},
        0.0,
        bounds.status == mesh::SolidBounds::Status::Empty
          ? "the key's solid is empty"
          : "the key's solid is not bounded (it reaches 1000 units)" };
    result.grid = padded_grid(bounds, samples);
    const auto& g = result.grid;
    std::vector<double> lo(3), hi(3);
    for (std::size_t k = 0; k < 3; ++k)
    {
      lo[k] = g.origin[k];
      hi[k] = g.origin[k] + g.spacing[k] * (g.dims[k] - 1);
    }
    const std::vector<std::int64_t> count(3, samples);
    std::vector<bool> inside(static_cast<std::size_t>(samples) * samples * samples, false);
    SampleOptions options;
    options.sign_only = true;
    options.threads = 1; // a key at a time; the caller may measure keys side by side
    const SampleResult sampled = sample_grid(tape,
      box_grid(lo, hi, count),
      options,
      [&](const SampleBlock& block)
      {
        for (std::size_t p = 0; p < block.count; ++p)
          inside[block.first + p] = !block.failed[p] && block.values[p] >= 0.0;
      });
    if (!sampled.ok())
      return KeyDistance{ {}, 0.0, sampled.error.empty() ? "cancelled" : sampled.error };
    std::vector<bool> outside(inside.size());
    std::transform(inside.begin(), inside.end(), outside.begin(), [](bool in) { return !in; });
    const std::vector<double> to_inside = squared_distance(inside, g);
    const std::vector<double> to_outside = squared_distance(outside, g);
    // The surface lies between samples: half the smallest cell from each side's samples.
    const double half = 0.5 * std::min({ g.spacing[0], g.spacing[1], g.spacing[2] });
    result.grid.values.resize(inside.size());
    for (std::size_t i = 0; i < inside.size(); ++i)
      result.grid.values[i] =
        inside[i] ? std::sqrt(to_outside[i]) - half : half - std::sqrt(to_inside[i]);
    result.band = 2.0 * std::max({ g.spacing[0], g.spacing[1], g.spacing[2] });
  }
  catch (const std::exception& e)
  {
    result.error = e.what();
  }
  return result;
}

} // namespace frep::morph
