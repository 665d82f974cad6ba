#include "Media/wav_writer.h"


#include "Durable/pending_file.h"

#include <sndfile.h>

#include <cmath>
#include <string>
#include <system_error>
#include <vector>

namespace frep::media
{
namespace
{

std::string validate(std::span<const float> samples, int sample_rate, int channels)
{
  if (sample_rate < 1 || sample_rate > 1000000)
    return "sample_rate must be in [1, 1000000] (got " + std::to_string(sample_rate) + ")";
  if (channels < 1 || channels > 64)
    return "channels must be in [1, 64] (got " + std::to_string(channels) + ")";
  if (samples.size() % static_cast<std::size_t>(channels) != 0)
    return std::to_string(samples.size()) + " samples are not a whole number of " +
           std::to_string(channels) + "-channel frames";
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (!std::isfinite(samples[i]))
      return "sample " + std::to_string(i) + " is not finite";
  return {};
}

} // namespace

WavWriteResult write_wav(const std::filesystem::path& path,
  std::span<const float> samples,
  int sample_rate,
  int channels,
  WavEncoding encoding)
{
  const std::string where = "writing " + path.string() + ": ";
  if (std::string problem = validate(samples, sample_rate, channels); !problem.empty())
    return { where + problem };
  if (path.filename().empty())
    return { where + "not a file name" };

  // The one temporary of the project (beside the target, removed on every early return), so a
  // failure leaves neither a half-written target nor a stray temporary behind.
  frep::durable::PendingFile temporary(path);
  if (!temporary.error().empty())
    return { where + temporary.error() };

  SF_INFO info{};
  info.samplerate = sample_rate;
  info.channels = channels;
  info.format =
    SF_FORMAT_WAV | (encoding == WavEncoding::Pcm16 ? SF_FORMAT_PCM_16 : SF_FORMAT_FLOAT);
  if (!sf_format_check(&info))
    return { where + "libsndfile rejects this format" };

  SNDFILE* file = sf_open(temporary.temporary().c_str(), SFM_WRITE, &info);
  if (file == nullptr)
    return { where + sf_strerror(nullptr) };
  if (encoding == WavEncoding::Pcm16)
    sf_command(file, SFC_SET_CLIPPING, nullptr, SF_TRUE); // clip rather than wrap around

  const auto frames = static_cast<sf_count_t>(samples.size() / channels);
  const sf_count_t written = sf_writef_float(file, samples.data(), frames);
  std::string write_error = written == frames ? std::string() : sf_strerror(file);
  if (const int status = sf_close(file); status != 0 && write_error.empty())
    write_error = sf_error_number(status);
  if (!write_error.empty())
    return { where + write_error };

  if (std::string problem = temporary.commit(); !problem.empty())
    return { where + problem };
  return {};
}

WavData read_wav(const std::filesystem::path& path)
{
  WavData data;
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (file == nullptr)
  {
    data.error = "reading " + path.string() + ": " + sf_strerror(nullptr);
    return data;
  }
  data.sample_rate = info.samplerate;
  data.channels = info.channels;
  data.samples.resize(static_cast<std::size_t>(info.frames) * info.channels);
  const sf_count_t read = sf_readf_float(file, data.samples.data(), info.frames);
  if (read != info.frames)
    data.error = "reading " + path.string() + ": " + std::to_string(read) + " of " +
                 std::to_string(info.frames) + " frames read: " + sf_strerror(file);
  sf_close(file);
  return data;
}

WavInfo wav_info(const std::filesystem::path& path)
{
  WavInfo result;
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (file == nullptr)
  {
    result.error = "reading " + path.string() + ": " + sf_strerror(nullptr);
    return result;
  }
  result.frame_count = info.frames;
  result.sample_rate = info.samplerate;
  result.channels = info.channels;
  sf_close(file);
  return result;
}

} // namespace frep::media
