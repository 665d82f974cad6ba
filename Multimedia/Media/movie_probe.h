// What a movie file holds, as reported by ffprobe: for tests and end-to-end checks of encoded
// movies (frame count, duration, size, sound track).
#pragma once

#include <filesystem>
#include <string>

namespace frep::media
{

struct ProbeOptions
{
  std::string ffprobe = "ffprobe"; ///< looked up on PATH; a name with '/' is used as a path
  /// Decode the whole video to count its frames (-count_frames) instead of trusting the
  /// container's frame count: slower, but independent of the muxer's bookkeeping.
  bool count_frames = false;
};

struct MovieProbe
{
  int width = 0; ///< of the first video stream
  int height = 0;
  long long frame_count = 0;   ///< video frames
  double frame_rate = 0.0;     ///< r_frame_rate, frames per second
  double duration = 0.0;       ///< of the video stream, seconds
  bool has_audio = false;      ///< whether there is an audio stream
  double audio_duration = 0.0; ///< of the first audio stream, seconds
  std::string error;           ///< empty = success (a file without video is an error)
  bool ok() const { return error.empty(); }
};

/// Runs `ffprobe -v error -show_entries stream=... -of json` on `path`. Never throws.
MovieProbe probe_movie(const std::filesystem::path& path, const ProbeOptions& options = {});

} // namespace frep::media
