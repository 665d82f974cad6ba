#include "Media/wav_writer.h"

#include "Media/system_message.h"

#include "Media/durable_file.h"

#include <sndfile.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <string>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace frep::media
{
namespace
{

using detail::system_message;

// Owns the temporary file until it is renamed: any early return removes it, so a failure
// leaves neither a half-written target nor a stray temporary behind.
class TemporaryFile
{
public:
  explicit TemporaryFile(std::string path_template)
    : path_(std::move(path_template))
  {
    fd_ = ::mkstemp(path_.data());
    error_ = fd_ < 0 ? errno : 0;
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile()
  {
    close();
    if (error_ == 0 && !renamed_)
      ::unlink(path_.c_str());
  }

  int fd() const { return fd_; }
  int open_error() const { return error_; }
  const std::string& path() const { return path_; }

  int close()
  {
    if (fd_ < 0)
      return 0;
    const int status = ::close(fd_);
    fd_ = -1;
    return status == 0 ? 0 : errno;
  }
  /// durable_rename: the data and the new name on disk. Empty on success.
  std::string rename_to(const std::string& target)
  {
    std::string problem = durable_rename(path_, target);
    renamed_ = problem.empty();
    return problem;
  }

private:
  std::string path_;
  int fd_ = -1;
  int error_ = 0; // errno of mkstemp, 0 if it succeeded
  bool renamed_ = false;
};

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

  // Beside the target, so that the final rename stays within one file system (atomic).
  const std::filesystem::path directory =
    path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  TemporaryFile temporary((directory / ("." + path.filename().string() + ".tmp-XXXXXX")).string());
  if (temporary.fd() < 0)
    return { where + "cannot create a temporary file in " + directory.string() + ": " +
             system_message(temporary.open_error()) };
  // mkstemp creates 0600; a sound file is an ordinary, shareable output.
  ::fchmod(temporary.fd(), 0644);

  SF_INFO info{};
  info.samplerate = sample_rate;
  info.channels = channels;
  info.format =
    SF_FORMAT_WAV | (encoding == WavEncoding::Pcm16 ? SF_FORMAT_PCM_16 : SF_FORMAT_FLOAT);
  if (!sf_format_check(&info))
    return { where + "libsndfile rejects this format" };

  // SF_FALSE: the descriptor stays ours (TemporaryFile closes it), whatever libsndfile does.
  SNDFILE* file = sf_open_fd(temporary.fd(), SFM_WRITE, &info, SF_FALSE);
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

  if (const int status = temporary.close(); status != 0)
    return { where + "close: " + system_message(status) };
  if (std::string problem = temporary.rename_to(path.string()); !problem.empty())
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
