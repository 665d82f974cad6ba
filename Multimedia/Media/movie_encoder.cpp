#include "Media/movie_encoder.h"

#include "Durable/pending_file.h"
#include "Media/program_runner.h"
#include "Media/wav_writer.h"

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <system_error>

namespace frep::media
{
namespace
{

// The shortest decimal that reads back as `value`: ffmpeg parses "24" or "29.97" as a rate.
std::string decimal(double value)
{
  char buffer[64];
  const auto [end, status] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return status == std::errc() ? std::string(buffer, end) : std::to_string(value);
}

std::string trimmed(std::string text)
{
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
    text.pop_back();
  return text;
}

std::string validate(const MovieInput& input, const MovieOptions& options)
{
  if (input.frame_count < 1)
    return "frame_count must be >= 1 (got " + std::to_string(input.frame_count) + ")";
  if (input.first_frame < 0)
    return "first_frame must be >= 0 (got " + std::to_string(input.first_frame) + ")";
  if (!std::isfinite(input.fps) || input.fps <= 0.0 || input.fps > 1000.0)
    return "fps must be in (0, 1000] (got " + decimal(input.fps) + ")";
  if (options.crf < 0 || options.crf > 51)
    return "crf must be in [0, 51] (got " + std::to_string(options.crf) + ")";
  if (options.audio_bitrate_kbps < 8 || options.audio_bitrate_kbps > 1024)
    return "audio_bitrate_kbps must be in [8, 1024] (got " +
           std::to_string(options.audio_bitrate_kbps) + ")";
  if (options.preset.empty() || options.preset.front() == '-')
    return "preset must be an x264 preset name (got '" + options.preset + "')";
  return {};
}

// Every frame must be there: ffmpeg would silently stop at the first gap and make a shorter
// movie whose sound track then overruns the picture.
std::string check_frames(const MovieInput& input)
{
  for (int k = 0; k < input.frame_count; ++k)
  {
    const FramePathResult frame = frame_path(input.frame_pattern, input.first_frame + k);
    if (!frame.ok())
      return frame.error;
    std::error_code error;
    if (!std::filesystem::is_regular_file(frame.path, error))
      return "frame " + std::to_string(input.first_frame + k) + " is missing: " + frame.path +
             " (pattern " + input.frame_pattern + ", " + std::to_string(input.frame_count) +
             " frames from " + std::to_string(input.first_frame) + ")";
  }
  return {};
}

std::string check_audio(const MovieInput& input)
{
  const WavInfo info = wav_info(input.audio);
  if (!info.ok())
    return "sound track: " + info.error;
  const double video = input.frame_count / input.fps;
  // Within one frame: the synthesis makes them equal to a sample, so a larger difference is a
  // mistake upstream, not something to paper over with -shortest.
  if (std::abs(info.duration() - video) > 1.0 / input.fps + 1e-9)
    return "sound track " + input.audio.string() + " lasts " + decimal(info.duration()) +
           " s but the " + std::to_string(input.frame_count) + " frames at " + decimal(input.fps) +
           " fps last " + decimal(video) + " s";
  return {};
}

// The error_code overload: the plain one throws when the working directory is gone.
std::string absolute_path(const std::filesystem::path& path)
{
  std::error_code error;
  const std::filesystem::path result = std::filesystem::absolute(path, error);
  return error ? path.string() : result.string();
}

} // namespace

FramePathResult frame_path(std::string_view pattern, int number)
{
  FramePathResult result;
  int conversions = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i)
  {
    if (pattern[i] != '%')
    {
      result.path += pattern[i];
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == '%')
    {
      result.path += '%';
      ++i;
      continue;
    }
    // "%d" or "%0Nd" (ffmpeg's av_get_frame_filename accepts a width, zero-padded or not).
    std::size_t j = i + 1;
    int width = 0;
    while (j < pattern.size() && pattern[j] >= '0' && pattern[j] <= '9' && width < 100)
      width = width * 10 + (pattern[j++] - '0');
    if (j >= pattern.size() || pattern[j] != 'd' || width >= 100)
    {
      result.error = "frame pattern '" + std::string(pattern) +
                     "': only one %d or %0Nd conversion (and %% for '%') is allowed";
      return result;
    }
    const bool zero_pad = j > i + 1 && pattern[i + 1] == '0';
    std::string digits = std::to_string(number);
    if (static_cast<int>(digits.size()) < width)
      digits.insert(0, static_cast<std::size_t>(width) - digits.size(), zero_pad ? '0' : ' ');
    result.path += digits;
    ++conversions;
    i = j;
  }
  if (conversions != 1)
    result.error = "frame pattern '" + std::string(pattern) + "' must contain exactly one %d " +
                   "or %0Nd conversion (it has " + std::to_string(conversions) + ")";
  return result;
}

MovieResult encode_movie(const MovieInput& input,
  const std::filesystem::path& output,
  const MovieOptions& options)
{
  const std::string where = "encoding " + output.string() + ": ";
  if (std::string problem = validate(input, options); !problem.empty())
    return { where + problem };
  if (output.filename().empty())
    return { where + "not a file name" };
  std::error_code filesystem_error;
  const std::filesystem::path directory =
    output.parent_path().empty() ? std::filesystem::path(".") : output.parent_path();
  if (!std::filesystem::is_directory(directory, filesystem_error))
    return { where + "the directory " + directory.string() + " does not exist" };
  if (std::string problem = check_frames(input); !problem.empty())
    return { where + problem };
  if (!input.audio.empty())
    if (std::string problem = check_audio(input); !problem.empty())
      return { where + problem };
  const auto ffmpeg = find_program(options.ffmpeg);
  if (!ffmpeg)
    return { where + "the program '" + options.ffmpeg +
             "' was not found on PATH (install ffmpeg, e.g. apt-get install ffmpeg)" };

  // The one temporary of the project, beside the output; removed unless put in place.
  frep::durable::PendingFile pending(output);
  if (!pending.error().empty())
    return { where + pending.error() };
  // Absolute paths: a relative one starting with '-' would read as an option, and one with a
  // ':' early on as a protocol ("a:b.png").
  const std::string partial = absolute_path(pending.temporary());
  std::vector<std::string> arguments;
  const auto add = [&arguments](std::initializer_list<std::string> more)
  { arguments.insert(arguments.end(), more); };
  add({ "-nostdin", "-y", "-loglevel", "error" });
  if (options.progress)
    add({ "-progress", "pipe:1", "-nostats" });
  // The frames: an explicit numbered sequence (no globbing), at the movie's rate.
  add({ "-f", "image2", "-pattern_type", "sequence" });
  add({ "-framerate", decimal(input.fps), "-start_number", std::to_string(input.first_frame) });
  add({ "-i", absolute_path(input.frame_pattern) });
  if (!input.audio.empty())
    add({ "-i", absolute_path(input.audio), "-map", "0:v:0", "-map", "1:a:0" });
  // trim: exactly frame_count frames even when more files follow in the sequence (not
  // -frames:v, which ends the whole output at the last video frame and so cuts the sound track
  // short by the encoder's lookahead). scale: yuv420p halves the chroma resolution, so libx264
  // needs even sizes; odd ones are scaled down by a pixel.
  add({ "-vf",
    "trim=end_frame=" + std::to_string(input.frame_count) + ",scale=trunc(iw/2)*2:trunc(ih/2)*2" });
  add({ "-c:v", "libx264", "-pix_fmt", "yuv420p" });
  add({ "-crf", std::to_string(options.crf), "-preset", options.preset });
  if (!input.audio.empty())
    add({ "-c:a", "aac", "-b:a", std::to_string(options.audio_bitrate_kbps) + "k" });
  // +faststart: the index at the front, so players start before the whole file has arrived.
  add({ "-movflags", "+faststart", "-f", "mp4", partial });

  std::function<void(std::string_view)> on_line;
  if (options.progress)
    on_line = [&](std::string_view line)
    {
      // -progress writes blocks of key=value lines; "frame=N" is the count encoded so far.
      if (!line.starts_with("frame="))
        return;
      int done = 0;
      const std::string_view value = line.substr(6);
      if (std::from_chars(value.data(), value.data() + value.size(), done).ec == std::errc())
        options.progress({ done, input.frame_count });
    };
  const ProgramResult run = run_program(*ffmpeg, arguments, on_line, options.cancel);
  if (run.stopped)
  {
    MovieResult stopped{ where + "cancelled" };
    stopped.cancelled = true;
    return stopped;
  }
  if (!run.ok())
  {
    const std::string message = trimmed(run.standard_error);
    const std::string failure =
      run.error.empty() ? "ffmpeg exited with status " + std::to_string(run.exit_code) : run.error;
    return { where + failure + (message.empty() ? "" : ": " + message) };
  }
  if (std::string problem = pending.commit(); !problem.empty())
    return { where + problem };
  return {};
}

} // namespace frep::media
