// WAV files through libsndfile: writing a synthesised track atomically (a temporary file in
// the target's directory, renamed over the target once complete) and reading one back.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace frep::media
{

enum class WavEncoding
{
  Pcm16,   ///< 16-bit signed PCM (plays everywhere); samples outside [-1, 1] are clipped
  Float32, ///< 32-bit IEEE float, lossless for float samples
};

struct WavWriteResult
{
  std::string error; ///< empty = success; otherwise names the path and libsndfile's message
  bool ok() const { return error.empty(); }
};

/// Writes interleaved `samples` (channels per frame, normally 1: mono) as a WAV file at `path`.
/// The data go to a unique temporary file beside `path`, renamed over it only when complete,
/// so `path` is either the old file or the complete new one, never a half-written one.
/// Validates sample_rate in [1, 1000000], channels in [1, 64], samples.size() divisible by
/// channels and all samples finite.
WavWriteResult write_wav(const std::filesystem::path& path,
  std::span<const float> samples,
  int sample_rate,
  int channels = 1,
  WavEncoding encoding = WavEncoding::Pcm16);

struct WavData
{
  std::vector<float> samples; ///< interleaved, PCM scaled to [-1, 1)
  int sample_rate = 0;
  int channels = 0;
  std::string error; ///< empty = success
  bool ok() const { return error.empty(); }
  std::size_t frame_count() const { return channels > 0 ? samples.size() / channels : 0; }
  double duration() const { return sample_rate > 0 ? double(frame_count()) / sample_rate : 0.0; }
};

/// Reads a sound file (WAV or anything else libsndfile reads) into float samples.
WavData read_wav(const std::filesystem::path& path);

struct WavInfo
{
  long long frame_count = 0; ///< samples per channel
  int sample_rate = 0;
  int channels = 0;
  std::string error; ///< empty = success
  bool ok() const { return error.empty(); }
  double duration() const { return sample_rate > 0 ? double(frame_count) / sample_rate : 0.0; }
};

/// The header of a sound file only (length, rate, channels), without reading the samples.
WavInfo wav_info(const std::filesystem::path& path);

} // namespace frep::media
