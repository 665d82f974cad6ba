#include "Media/frequency_analysis.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace frep::media
{
namespace
{

double hann(std::size_t i, std::size_t n)
{
  return 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / (n - 1));
}

// In-place iterative radix-2 FFT; data.size() is a power of two. Small and dependency-free:
// the windows measured here are a few thousand samples.
void fft(std::vector<std::complex<double>>& data)
{
  const std::size_t n = data.size();
  for (std::size_t i = 1, j = 0; i < n; ++i)
  {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1)
      j ^= bit;
    j ^= bit;
    if (i < j)
      std::swap(data[i], data[j]);
  }
  for (std::size_t length = 2; length <= n; length <<= 1)
  {
    const double angle = -2.0 * std::numbers::pi / static_cast<double>(length);
    const std::complex<double> step(std::cos(angle), std::sin(angle));
    for (std::size_t start = 0; start < n; start += length)
    {
      std::complex<double> w(1.0, 0.0);
      for (std::size_t k = 0; k < length / 2; ++k)
      {
        const std::complex<double> even = data[start + k];
        const std::complex<double> odd = data[start + k + length / 2] * w;
        data[start + k] = even + odd;
        data[start + k + length / 2] = even - odd;
        w *= step;
      }
    }
  }
}

} // namespace

std::optional<double> dominant_frequency(std::span<const float> samples,
  int sample_rate,
  double min_hz,
  double max_hz)
{
  const std::size_t n = samples.size();
  if (n < 16 || sample_rate <= 0)
    return std::nullopt;
  const double nyquist = sample_rate / 2.0;
  if (max_hz <= 0.0 || max_hz > nyquist)
    max_hz = nyquist;
  min_hz = std::max(min_hz, 0.0);
  if (!(min_hz < max_hz))
    return std::nullopt;

  // Zero-padding to 4x the next power of two samples the spectrum finely enough that the
  // three-point interpolation below is well within its accurate range.
  const std::size_t size = std::bit_ceil(n) * 4;
  std::vector<std::complex<double>> data(size);
  for (std::size_t i = 0; i < n; ++i)
    data[i] = samples[i] * hann(i, n);
  fft(data);

  const double bin_hz = static_cast<double>(sample_rate) / static_cast<double>(size);
  const auto first = static_cast<std::size_t>(std::max(1.0, std::ceil(min_hz / bin_hz)));
  const auto last = std::min(static_cast<std::size_t>(std::floor(max_hz / bin_hz)), size / 2 - 1);
  std::size_t peak = 0;
  double peak_magnitude = 0.0;
  for (std::size_t k = first; k <= last; ++k)
  {
    const double magnitude = std::abs(data[k]);
    if (magnitude > peak_magnitude)
    {
      peak_magnitude = magnitude;
      peak = k;
    }
  }
  if (peak == 0 || !(peak_magnitude > 1e-12))
    return std::nullopt;

  // A Hann-windowed peak is close to a Gaussian, so a parabola through the log magnitudes of
  // the peak bin and its neighbours locates its centre to a small fraction of a bin.
  const double left = std::log(std::abs(data[peak - 1]) + 1e-300);
  const double centre = std::log(peak_magnitude);
  const double right = std::log(std::abs(data[peak + 1]) + 1e-300);
  const double denominator = left - 2.0 * centre + right;
  double offset = denominator < 0.0 ? 0.5 * (left - right) / denominator : 0.0;
  offset = std::clamp(offset, -0.5, 0.5);
  return (static_cast<double>(peak) + offset) * bin_hz;
}

double amplitude_at(std::span<const float> samples, int sample_rate, double frequency)
{
  const std::size_t n = samples.size();
  if (n < 2 || sample_rate <= 0)
    return 0.0;
  // Goertzel: one DFT term at an arbitrary (not necessarily bin-centred) frequency.
  const double omega = 2.0 * std::numbers::pi * frequency / sample_rate;
  const double coefficient = 2.0 * std::cos(omega);
  double s1 = 0.0;
  double s2 = 0.0;
  double window_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double w = hann(i, n);
    window_sum += w;
    const double s0 = samples[i] * w + coefficient * s1 - s2;
    s2 = s1;
    s1 = s0;
  }
  const double power = s1 * s1 + s2 * s2 - coefficient * s1 * s2;
  // |X| of a sine of amplitude A is A * sum(w) / 2.
  return 2.0 * std::sqrt(std::max(power, 0.0)) / window_sum;
}

double rms(std::span<const float> samples)
{
  if (samples.empty())
    return 0.0;
  double sum = 0.0;
  for (const float s : samples)
    sum += static_cast<double>(s) * s;
  return std::sqrt(sum / static_cast<double>(samples.size()));
}

} // namespace frep::media
