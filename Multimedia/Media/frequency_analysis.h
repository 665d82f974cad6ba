// Measurements of a window of sound samples: the dominant frequency, the amplitude at a given
// frequency and the RMS loudness. For tests and end-to-end checks of synthesised sound tracks.
#pragma once

#include <optional>
#include <span>

namespace frep::media
{

/// The frequency (Hz) of the strongest spectral peak of `samples` between min_hz and max_hz
/// (max_hz <= 0: Nyquist). Hann-windowed, zero-padded FFT with Gaussian (parabolic on the log
/// magnitude) peak interpolation: better than 0.1% for a steady tone filling a 4096-sample
/// window at 44.1 kHz. nullopt for fewer than 16 samples, a sample_rate <= 0, an empty band,
/// or silence.
std::optional<double> dominant_frequency(std::span<const float> samples,
  int sample_rate,
  double min_hz = 20.0,
  double max_hz = 0.0);

/// The amplitude of the component of `samples` at `frequency` Hz (Hann-windowed Goertzel,
/// scaled so that a steady sine of amplitude A, whose frequency is `frequency`, gives about A).
/// 0 for an empty window or a sample_rate <= 0.
double amplitude_at(std::span<const float> samples, int sample_rate, double frequency);

/// Root mean square of `samples` (0 for an empty window).
double rms(std::span<const float> samples);

} // namespace frep::media
