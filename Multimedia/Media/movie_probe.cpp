#include "Media/movie_probe.h"

#include "Media/program_runner.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <optional>

namespace frep::media
{
namespace
{

// ffprobe's JSON gives most numbers as strings ("nb_frames": "48", "duration": "2.000000",
// "r_frame_rate": "24/1"); absent or "N/A" fields give nullopt.
std::optional<double> number(const nlohmann::json& stream, const char* key)
{
  const auto found = stream.find(key);
  if (found == stream.end())
    return std::nullopt;
  if (found->is_number())
    return found->get<double>();
  if (!found->is_string())
    return std::nullopt;
  const std::string& text = found->get_ref<const std::string&>();
  const std::size_t slash = text.find('/');
  double numerator = 0.0;
  const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), numerator);
  if (status != std::errc() || (slash == std::string::npos && end != text.data() + text.size()))
    return std::nullopt;
  if (slash == std::string::npos)
    return numerator;
  double denominator = 0.0;
  const auto [rest, fraction_status] =
    std::from_chars(text.data() + slash + 1, text.data() + text.size(), denominator);
  if (fraction_status != std::errc() || denominator == 0.0)
    return std::nullopt;
  return numerator / denominator;
}

} // namespace

MovieProbe probe_movie(const std::filesystem::path& path, const ProbeOptions& options)
{
  MovieProbe probe;
  const std::string where = "probing " + path.string() + ": ";
  const auto ffprobe = find_program(options.ffprobe);
  if (!ffprobe)
  {
    probe.error = where + "the program '" + options.ffprobe +
                  "' was not found on PATH (install ffmpeg, which provides ffprobe)";
    return probe;
  }
  std::error_code absolute_error;
  std::filesystem::path absolute = std::filesystem::absolute(path, absolute_error);
  if (absolute_error)
    absolute = path;
  std::vector<std::string> arguments{ "-v",
    "error",
    "-of",
    "json",
    "-show_entries",
    "stream=codec_type,nb_frames,nb_read_frames,duration,r_frame_rate,width,height" };
  if (options.count_frames)
    arguments.push_back("-count_frames");
  // An absolute path: a relative one starting with '-' would read as an option, and one with
  // ':' early on as a protocol.
  arguments.push_back(absolute.string());
  const ProgramResult run = run_program(*ffprobe, arguments);
  if (!run.ok())
  {
    const std::string failure =
      run.error.empty() ? "ffprobe exited with status " + std::to_string(run.exit_code) : run.error;
    std::string message = run.standard_error;
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r'))
      message.pop_back();
    probe.error = where + failure + (message.empty() ? "" : ": " + message);
    return probe;
  }

  const nlohmann::json document = nlohmann::json::parse(run.standard_output, nullptr, false);
  if (document.is_discarded() || !document.is_object() || !document.contains("streams") ||
      !document["streams"].is_array())
  {
    probe.error = where + "ffprobe's output is not the expected JSON: " + run.standard_output;
    return probe;
  }
  bool has_video = false;
  for (const nlohmann::json& stream : document["streams"])
  {
    if (!stream.is_object())
      continue;
    const auto type = stream.find("codec_type");
    if (type == stream.end() || !type->is_string())
      continue;
    if (*type == "video" && !has_video)
    {
      has_video = true;
      probe.width = static_cast<int>(number(stream, "width").value_or(0));
      probe.height = static_cast<int>(number(stream, "height").value_or(0));
      probe.frame_rate = number(stream, "r_frame_rate").value_or(0.0);
      probe.duration = number(stream, "duration").value_or(0.0);
      const auto frames =
        options.count_frames ? number(stream, "nb_read_frames") : number(stream, "nb_frames");
      probe.frame_count = static_cast<long long>(std::llround(frames.value_or(0.0)));
    }
    else if (*type == "audio" && !probe.has_audio)
    {
      probe.has_audio = true;
      probe.audio_duration = number(stream, "duration").value_or(0.0);
    }
  }
  if (!has_video)
    probe.error = where + "no video stream";
  return probe;
}

} // namespace frep::media
