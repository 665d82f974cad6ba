// Assembling a movie from numbered PNG frames and an optional WAV sound track: H.264 (yuv420p)
// and AAC in an MP4 that starts playing before it is fully downloaded (+faststart), made by
// the ffmpeg program. The movie appears under its name only once ffmpeg has succeeded.
#pragma once

#include "Media/movie_probe.h"

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace frep::media
{

struct MovieInput
{
  /// printf-style pattern with exactly one integer conversion, "%d" or "%0Nd" (and "%%" for a
  /// literal '%'), as ffmpeg's image sequences take it: "frames/frame_%05d.png".
  std::string frame_pattern;
  int first_frame = 0; ///< the number of the first frame file
  int frame_count = 0; ///< >= 1; every frame file must exist
  double fps = 24.0;   ///< frames per second, > 0
  /// WAV sound track, as long as the frames (within one frame); empty: a silent movie.
  std::filesystem::path audio;
};

struct MovieProgress
{
  int frames_done = 0;
  int frame_count = 0;
};

struct MovieOptions
{
  std::string ffmpeg = "ffmpeg"; ///< looked up on PATH; a name with '/' is used as a path
  int crf = 18;                  ///< x264 constant rate factor 0..51 (18: visually lossless)
  std::string preset = "medium"; ///< x264 preset
  int audio_bitrate_kbps = 192;
  /// Called from the encoding thread as ffmpeg reports progress (-progress pipe:1); must not
  /// throw.
  std::function<void(const MovieProgress&)> progress;
  /// Polled while ffmpeg runs, from the calling thread: true stops it (the result says
  /// `cancelled`; nothing is put in place). Default none.
  std::function<bool()> cancel;
};

struct MovieResult
{
  std::string error; ///< empty = success; ffmpeg's own messages when it failed
  bool cancelled = false; ///< stopped by MovieOptions::cancel (error says so too)
  bool ok() const { return error.empty(); }
};

/// Encodes frames first_frame .. first_frame + frame_count - 1 of `input.frame_pattern` (and
/// the sound track) into `output` (MP4). Odd frame sizes are scaled down to even ones
/// (yuv420p needs them). ffmpeg writes `<stem>.partial.mp4` beside `output`, renamed to
/// `output` when it succeeds and removed when it fails, so `output` is never a half-written
/// movie. Checks beforehand that the pattern is valid, every frame file exists, the WAV is
/// readable and as long as the frames, and ffmpeg is installed. Never throws.
MovieResult encode_movie(const MovieInput& input,
  const std::filesystem::path& output,
  const MovieOptions& options = {});

struct FramePathResult
{
  std::string path;  ///< the pattern with its conversion replaced by the number
  std::string error; ///< empty = success (the pattern is valid)
  bool ok() const { return error.empty(); }
};

/// The file name of frame `number` of `pattern`, exactly as ffmpeg expands it; an error for a
/// pattern without exactly one "%d"/"%0Nd" conversion or with any other '%' sequence.
FramePathResult frame_path(std::string_view pattern, int number);

} // namespace frep::media
