#include "Media/tone_synthesis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace frep::media
{
namespace
{

constexpr int min_sample_rate = 8000;
constexpr int max_sample_rate = 192000;
// 2^31 samples: hours of sound at any rate; beyond that the input is surely a mistake.
constexpr double max_samples = 2147483648.0;

// One voice's parameters at every frame, with the gaps (frames that do not list the voice)
// filled so that the voice is silent there but keeps the pitch and timbre of its nearest
// frame: fading out must not also glide towards some default pitch.
struct VoiceTrack
{
  std::vector<VoiceParams> frames;
};

VoiceTrack make_track(const VoiceFrames& frames, std::size_t voice)
{
  VoiceTrack track;
  track.frames.resize(frames.size());
  std::size_t first = frames.size(); // the first frame that lists the voice
  for (std::size_t k = 0; k < frames.size(); ++k)
  {
    if (voice < frames[k].size())
    {
      track.frames[k] = frames[k][voice];
      first = std::min(first, k);
    }
    else if (first < k) // a gap after the voice appeared: silent, pitch and timbre held
      track.frames[k] = { track.frames[k - 1].pitch, 0.0, track.frames[k - 1].timbre };
  }
  // The frames before the voice first appears take its first pitch and timbre.
  for (std::size_t k = 0; k < first && first < frames.size(); ++k)
    track.frames[k] = { track.frames[first].pitch, 0.0, track.frames[first].timbre };
  return track;
}

std::string describe(double value)
{
  if (std::isnan(value))
    return "nan";
  if (std::isinf(value))
    return value > 0 ? "inf" : "-inf";
  return std::to_string(value);
}

std::string validate(const VoiceFrames& frames,
  double fps,
  int sample_rate,
  const SynthesisOptions& options)
{
  if (!std::isfinite(fps) || fps <= 0.0)
    return "fps must be finite and > 0 (got " + describe(fps) + ")";
  if (sample_rate < min_sample_rate || sample_rate > max_sample_rate)
    return "sample_rate must be in [8000, 192000] Hz (got " + std::to_string(sample_rate) + ")";
  if (options.max_harmonics < 1 || options.max_harmonics > 64)
    return "max_harmonics must be in [1, 64] (got " + std::to_string(options.max_harmonics) + ")";
  if (!std::isfinite(options.fade_seconds) || options.fade_seconds < 0.0)
    return "fade_seconds must be finite and >= 0 (got " + describe(options.fade_seconds) + ")";
  if (static_cast<double>(frames.size()) * sample_rate / fps >= max_samples)
    return "the track would be longer than 2^31 samples (" + std::to_string(frames.size()) +
           " frames at " + describe(fps) + " fps)";
  for (std::size_t k = 0; k < frames.size(); ++k)
    for (std::size_t v = 0; v < frames[k].size(); ++v)
    {
      const VoiceParams& p = frames[k][v];
      const std::string place = "frames[" + std::to_string(k) + "][" + std::to_string(v) + "].";
      if (!std::isfinite(p.pitch) || p.pitch <= 0.0)
        return place + "pitch must be finite and > 0 Hz (got " + describe(p.pitch) + ")";
      if (!(p.loudness >= 0.0 && p.loudness <= 1.0))
        return place + "loudness must be in 0..1 (got " + describe(p.loudness) + ")";
      if (!(p.timbre >= 0.0 && p.timbre <= 1.0))
        return place + "timbre must be in 0..1 (got " + describe(p.timbre) + ")";
    }
  return {};
}

// The parameters at `frame_position` (in frames, 0 = centre of frame 0), held constant before
// the first and after the last centre.
VoiceParams parameters_at(const VoiceTrack& track, double frame_position, Interpolation mode)
{
  const std::size_t count = track.frames.size();
  if (frame_position <= 0.0)
    return track.frames.front();
  if (frame_position >= static_cast<double>(count - 1))
    return track.frames.back();
  const auto k = static_cast<std::size_t>(frame_position);
  double s = frame_position - static_cast<double>(k);
  if (mode == Interpolation::Cosine)
    s = 0.5 - 0.5 * std::cos(std::numbers::pi * s);
  const VoiceParams& a = track.frames[k];
  const VoiceParams& b = track.frames[k + 1];
  return { a.pitch + (b.pitch - a.pitch) * s,
    a.loudness + (b.loudness - a.loudness) * s,
    a.timbre + (b.timbre - a.timbre) * s };
}

// One sample of an additive tone at `phase` (cycles): sum over harmonics k of
// timbre^(k-1)/k * sin(2 pi k phase), divided by the sum of the weights so that the result
// never exceeds 1 in magnitude (exactly 1 at the peak of a pure tone). Harmonics approaching
// Nyquist fade out instead of aliasing, and fade gradually so that a gliding pitch does not
// switch a harmonic off abruptly.
double tone_sample(double phase, double pitch, double timbre, int max_harmonics, double rate)
{
  const double x = 2.0 * std::numbers::pi * phase;
  const double s1 = std::sin(x);
  const double two_cos = 2.0 * std::cos(x);
  const double taper_end = 0.48 * rate;
  const double taper_width = 0.08 * rate;
  // sin(k x) by the recurrence sin(k x) = 2 cos(x) sin((k-1) x) - sin((k-2) x): one sine and
  // one cosine per sample whatever the number of harmonics.
  double previous = 0.0; // sin((k-1) x)
  double current = s1;   // sin(k x)
  double power = 1.0;    // timbre^(k-1)
  double sum = 0.0;
  double norm = 0.0;
  for (int k = 1; k <= max_harmonics; ++k)
  {
    if (k > 1)
    {
      const double next = two_cos * current - previous;
      previous = current;
      current = next;
      power *= timbre;
      if (power < 1e-6) // the rest contributes less than -120 dB
        break;
    }
    const double frequency = pitch * k;
    if (frequency >= taper_end)
      break;
    const double weight = power / k;
    const double taper = std::clamp((taper_end - frequency) / taper_width, 0.0, 1.0);
    sum += weight * taper * current;
    norm += weight;
  }
  return norm > 0.0 ? sum / norm : 0.0;
}

float soft_limit(double x)
{
  constexpr double knee = 0.8;
  const double magnitude = std::abs(x);
  if (magnitude <= knee)
    return static_cast<float>(x);
  // Slope 1 at the knee, approaching 1 asymptotically: continuous, no hard corner.
  const double limited = knee + (1.0 - knee) * std::tanh((magnitude - knee) / (1.0 - knee));
  return static_cast<float>(std::copysign(limited, x));
}

} // namespace

std::size_t synthesis_length(std::size_t frame_count, double fps, int sample_rate)
{
  if (!std::isfinite(fps) || fps <= 0.0 || sample_rate <= 0)
    return 0;
  // frame_count * rate / fps rather than frame_count / fps * rate: exact for integral fps.
  return static_cast<std::size_t>(
    std::llround(static_cast<double>(frame_count) * sample_rate / fps));
}

SynthesisResult synthesise(const VoiceFrames& frames,
  double fps,
  int sample_rate,
  const SynthesisOptions& options)
{
  SynthesisResult result;
  result.error = validate(frames, fps, sample_rate, options);
  if (!result.error.empty())
    return result;

  const std::size_t length = synthesis_length(frames.size(), fps, sample_rate);
  std::size_t voice_count = 0;
  for (const auto& frame : frames)
    voice_count = std::max(voice_count, frame.size());
  result.samples.assign(length, 0.0f);
  if (voice_count == 0 || length == 0)
    return result;

  const double rate = sample_rate;
  std::vector<double> mix(length, 0.0);
  for (std::size_t v = 0; v < voice_count; ++v)
  {
    const VoiceTrack track = make_track(frames, v);
    double phase = 0.0; // cycles in [0, 1); accumulated, so a pitch change never jumps
    for (std::size_t i = 0; i < length; ++i)
    {
      const double frame_position = static_cast<double>(i) / rate * fps - 0.5;
      const VoiceParams p = parameters_at(track, frame_position, options.interpolation);
      if (p.loudness > 0.0)
        mix[i] += p.loudness * tone_sample(phase, p.pitch, p.timbre, options.max_harmonics, rate);
      phase += p.pitch / rate;
      phase -= std::floor(phase);
    }
  }

  // A raised-cosine fade at both ends: a tone that starts at full amplitude clicks.
  const auto fade =
    std::min(static_cast<std::size_t>(std::llround(options.fade_seconds * rate)), length / 2);
  for (std::size_t i = 0; i < fade; ++i)
  {
    const double gain = 0.5 - 0.5 * std::cos(std::numbers::pi * (i + 0.5) / fade);
    mix[i] *= gain;
    mix[length - 1 - i] *= gain;
  }

  for (std::size_t i = 0; i < length; ++i)
  {
    const float value = options.mixing == Mixing::Average
                          ? static_cast<float>(mix[i] / static_cast<double>(voice_count))
                          : soft_limit(mix[i]);
    // Each voice is bounded by its loudness <= 1, so this only guards rounding.
    result.samples[i] = std::clamp(value, -1.0f, 1.0f);
  }
  return result;
}

} // namespace frep::media
