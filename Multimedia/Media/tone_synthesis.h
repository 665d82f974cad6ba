// Additive tone synthesis for the sound channels of a mapping: per animation frame, the pitch,
// loudness and timbre of each voice; out, a mono track exactly as long as the frames last, so
// the movie's picture and sound stay in step by construction.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace frep::media
{

/// The sound of one voice during one animation frame (the value holds at the frame's centre).
struct VoiceParams
{
  double pitch = 440.0;  ///< fundamental frequency, Hz (> 0)
  double loudness = 0.5; ///< peak amplitude bound, 0..1
  double timbre = 0.0;   ///< 0 pure sine .. 1 bright (harmonic k weighted timbre^(k-1)/k)
};

/// frames[k][v]: voice v during frame k. A frame may list fewer voices than others: a missing
/// voice is silent in that frame (it fades in/out over the neighbouring frame interval).
using VoiceFrames = std::vector<std::vector<VoiceParams>>;

enum class Interpolation
{
  Linear, ///< parameters change at a constant rate between frame centres
  Cosine, ///< eased: the rate of change is zero at each frame centre (no corner at the frames)
};

enum class Mixing
{
  /// The sum of the voices divided by the number of voices: can never exceed [-1, 1], but a
  /// lone voice in a many-voice mix is quieter.
  Average,
  /// The plain sum, linear up to 0.8 and smoothly compressed above towards (never beyond) 1.
  SoftLimit,
};

struct SynthesisOptions
{
  int max_harmonics = 16;      ///< 1..64; harmonics near and above Nyquist are faded out
  double fade_seconds = 0.010; ///< raised-cosine fade at the start and the end of the track
  Interpolation interpolation = Interpolation::Cosine;
  Mixing mixing = Mixing::Average;
};

struct SynthesisResult
{
  std::vector<float> samples; ///< mono, in [-1, 1]
  std::string error;          ///< empty = success
  bool ok() const { return error.empty(); }
};

/// round(frame_count / fps * sample_rate): the number of samples as long as the frames
/// (0 for an fps or sample_rate that is not > 0).
std::size_t synthesis_length(std::size_t frame_count, double fps, int sample_rate);

/// Synthesises `frames` (frame k at time k / fps, lasting 1 / fps) at `sample_rate` Hz into a
/// mono track of synthesis_length(frames.size(), fps, sample_rate) samples. Each voice is a
/// sum of harmonics of one continuously accumulated phase (no clicks when the pitch changes);
/// its parameters are interpolated per sample between frame centres and held before the first
/// and after the last centre. Frames without voices are silence. Validates fps > 0, sample_rate
/// in [8000, 192000], finite pitch > 0, loudness and timbre in 0..1; never throws.
SynthesisResult synthesise(const VoiceFrames& frames,
  double fps,
  int sample_rate,
  const SynthesisOptions& options = {});

} // namespace frep::media
