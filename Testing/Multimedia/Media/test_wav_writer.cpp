#include "test_support.h"
#include "Media/tone_synthesis.h"
#include "Media/wav_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

namespace frep::media
{
namespace
{

using testing::file_names;
using testing::fresh_directory;

std::vector<float> ramp(std::size_t count)
{
  std::vector<float> samples(count);
  for (std::size_t i = 0; i < count; ++i)
    samples[i] = static_cast<float>(std::sin(0.01 * i) * 0.9);
  return samples;
}

std::string contents(const std::filesystem::path& path)
{
  std::ifstream file(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>() };
}

TEST(WavWriter, SynthesisedTrackRoundTripsAsPcm16)
{
  const auto directory = fresh_directory();
  const auto track = synthesise(VoiceFrames(48, { { 440.0, 0.5, 0.2 } }), 24.0, 44100);
  ASSERT_TRUE(track.ok()) << track.error;
  const auto path = directory / "track.wav";
  const auto written = write_wav(path, track.samples, 44100);
  ASSERT_TRUE(written.ok()) << written.error;

  const WavData data = read_wav(path);
  ASSERT_TRUE(data.ok()) << data.error;
  EXPECT_EQ(data.sample_rate, 44100);
  EXPECT_EQ(data.channels, 1);
  ASSERT_EQ(data.samples.size(), 88200u);
  EXPECT_DOUBLE_EQ(data.duration(), 2.0);
  for (std::size_t i = 0; i < data.samples.size(); ++i)
    ASSERT_NEAR(data.samples[i], track.samples[i], 2.0 / 32768) << "sample " << i;
  // 44-byte header + 2 bytes per sample (libsndfile may add a chunk or two, not more).
  EXPECT_GE(std::filesystem::file_size(path), 44u + 2 * 88200u);
  EXPECT_LT(std::filesystem::file_size(path), 44u + 2 * 88200u + 512u);

  const WavInfo info = wav_info(path);
  ASSERT_TRUE(info.ok()) << info.error;
  EXPECT_EQ(info.frame_count, 88200);
  EXPECT_EQ(info.sample_rate, 44100);
  EXPECT_DOUBLE_EQ(info.duration(), 2.0);
}

TEST(WavWriter, FloatStereoIsExact)
{
  const auto directory = fresh_directory();
  const auto samples = ramp(2 * 1000);
  const auto path = directory / "stereo.wav";
  ASSERT_TRUE(write_wav(path, samples, 48000, 2, WavEncoding::Float32).ok());
  const WavData data = read_wav(path);
  ASSERT_TRUE(data.ok()) << data.error;
  EXPECT_EQ(data.channels, 2);
  EXPECT_EQ(data.sample_rate, 48000);
  EXPECT_EQ(data.frame_count(), 1000u);
  EXPECT_EQ(data.samples, samples);
}

TEST(WavWriter, Pcm16ClipsInsteadOfWrappingAround)
{
  const auto directory = fresh_directory();
  const auto path = directory / "clipped.wav";
  ASSERT_TRUE(write_wav(path, std::vector<float>{ 1.5f, -1.5f, 0.5f }, 8000).ok());
  const WavData data = read_wav(path);
  ASSERT_TRUE(data.ok()) << data.error;
  ASSERT_EQ(data.samples.size(), 3u);
  EXPECT_GT(data.samples[0], 0.999f);
  EXPECT_LE(data.samples[1], -0.999f);
  EXPECT_NEAR(data.samples[2], 0.5f, 1e-4);
}

TEST(WavWriter, ReplacesTheTargetAndLeavesNoTemporaryFile)
{
  const auto directory = fresh_directory();
  const auto path = directory / "track.wav";
  ASSERT_TRUE(write_wav(path, ramp(100), 22050).ok());
  ASSERT_TRUE(write_wav(path, ramp(300), 22050).ok());
  EXPECT_EQ(read_wav(path).samples.size(), 300u);
  EXPECT_EQ(file_names(directory), std::vector<std::string>{ "track.wav" });
  // An ordinary file, readable by others (mkstemp's 0600 is widened).
  const auto permissions = std::filesystem::status(path).permissions();
  EXPECT_NE(permissions & std::filesystem::perms::others_read, std::filesystem::perms::none);
}

TEST(WavWriter, InvalidSamplesLeaveTheOldFileUntouched)
{
  const auto directory = fresh_directory();
  const auto path = directory / "track.wav";
  ASSERT_TRUE(write_wav(path, ramp(100), 22050).ok());
  const std::string before = contents(path);

  auto samples = ramp(200);
  samples[150] = std::nanf("");
  const auto result = write_wav(path, samples, 22050);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.error.find("sample 150"), std::string::npos) << result.error;
  EXPECT_NE(result.error.find(path.string()), std::string::npos) << result.error;
  EXPECT_EQ(contents(path), before);
  EXPECT_EQ(file_names(directory), std::vector<std::string>{ "track.wav" });

  EXPECT_FALSE(write_wav(path, ramp(3), 22050, 2).ok()); // not whole stereo frames
  EXPECT_FALSE(write_wav(path, ramp(4), 0).ok());
  EXPECT_EQ(contents(path), before);
}

TEST(WavWriter, MissingDirectoryIsAnErrorWithThePath)
{
  const auto directory = fresh_directory();
  const auto path = directory / "no" / "such" / "track.wav";
  const auto result = write_wav(path, ramp(100), 22050);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.error.find(path.string()), std::string::npos) << result.error;
  EXPECT_TRUE(file_names(directory).empty());
}

TEST(WavWriter, ReadingAMissingOrBrokenFileIsAnError)
{
  const auto directory = fresh_directory();
  const WavData missing = read_wav(directory / "missing.wav");
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.error.find("missing.wav"), std::string::npos) << missing.error;

  const auto broken = directory / "broken.wav";
  std::ofstream(broken) << "RIFF but not really a wave file";
  EXPECT_FALSE(read_wav(broken).ok());
  EXPECT_FALSE(wav_info(broken).ok());
}

} // namespace
} // namespace frep::media
