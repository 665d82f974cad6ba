// The movie tests run the real ffmpeg and ffprobe: without them they fail (CI installs ffmpeg).
#include "Media/movie_encoder.h"
#include "test_support.h"
#include "Media/tone_synthesis.h"
#include "Media/wav_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace frep::media
{
namespace
{

using testing::file_names;
using testing::fresh_directory;

constexpr int frame_count = 48;
constexpr double fps = 24.0;

// 48 frames 65 x 49 (odd on purpose: the encoder must make them even) in directory/frames.
MovieInput write_frames(const std::filesystem::path& directory, int count = frame_count)
{
  const auto frames = directory / "frames";
  std::filesystem::create_directories(frames);
  MovieInput input;
  input.frame_pattern = (frames / "frame_%05d.png").string();
  input.frame_count = count;
  input.fps = fps;
  for (int k = 0; k < count; ++k)
  {
    const auto path = frame_path(input.frame_pattern, k);
    EXPECT_TRUE(path.ok()) << path.error;
    const auto shade = static_cast<std::uint8_t>(k * 5);
    EXPECT_TRUE(testing::write_png(path.path, 65, 49, { shade, 80, 200 }, k));
  }
  return input;
}

std::filesystem::path write_tone(const std::filesystem::path& path, int frames)
{
  const auto track = synthesise(VoiceFrames(frames, { { 330.0, 0.5, 0.5 } }), fps, 44100);
  EXPECT_TRUE(track.ok()) << track.error;
  const auto written = write_wav(path, track.samples, 44100);
  EXPECT_TRUE(written.ok()) << written.error;
  return path;
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

TEST(FramePath, ExpandsLikeFfmpeg)
{
  EXPECT_EQ(frame_path("frames/frame_%05d.png", 7).path, "frames/frame_00007.png");
  EXPECT_EQ(frame_path("f%d.png", 123).path, "f123.png");
  EXPECT_EQ(frame_path("f%3d.png", 5).path, "f  5.png");
  EXPECT_EQ(frame_path("100%%_%03d.png", 7).path, "100%_007.png");
  EXPECT_EQ(frame_path("f_%02d.png", 1234).path, "f_1234.png");
  EXPECT_FALSE(frame_path("frame.png", 1).ok());
  EXPECT_FALSE(frame_path("%d_%d.png", 1).ok());
  EXPECT_FALSE(frame_path("%s.png", 1).ok());
  EXPECT_FALSE(frame_path("frame_%05x.png", 1).ok());
  EXPECT_FALSE(frame_path("frame_%", 1).ok());
}

TEST(MovieEncoder, FramesAndSoundMakeAnMp4OfTheSameDuration)
{
  const auto directory = fresh_directory();
  MovieInput input = write_frames(directory);
  input.audio = write_tone(directory / "sound.wav", frame_count);
  MovieOptions options;
  std::vector<int> progress;
  options.progress = [&](const MovieProgress& p)
  {
    EXPECT_EQ(p.frame_count, frame_count);
    progress.push_back(p.frames_done);
  };
  const auto output = directory / "movie.mp4";
  const MovieResult result = encode_movie(input, output, options);
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_TRUE(std::filesystem::is_regular_file(output));
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
      << "temporary left behind: " << entry.path();
  ASSERT_FALSE(progress.empty());
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_EQ(progress.back(), frame_count);

  const MovieProbe probe = probe_movie(output);
  ASSERT_TRUE(probe.ok()) << probe.error;
  EXPECT_EQ(probe.frame_count, frame_count);
  EXPECT_EQ(probe.width, 64);
  EXPECT_EQ(probe.height, 48);
  EXPECT_DOUBLE_EQ(probe.frame_rate, 24.0);
  EXPECT_NEAR(probe.duration, 2.0, 1.0 / fps);
  EXPECT_TRUE(probe.has_audio);
  EXPECT_NEAR(probe.audio_duration, 2.0, 1.0 / fps);

  // Decoding every frame finds as many as the container says.
  ProbeOptions counting;
  counting.count_frames = true;
  const MovieProbe counted = probe_movie(output, counting);
  ASSERT_TRUE(counted.ok()) << counted.error;
  EXPECT_EQ(counted.frame_count, frame_count);
}

TEST(MovieEncoder, WithoutSoundTheMovieIsSilent)
{
  const auto directory = fresh_directory();
  MovieInput input = write_frames(directory, 12);
  input.first_frame = 2; // frames 2..11 of the 12 written
  input.frame_count = 10;
  const auto output = directory / "silent.mp4";
  const MovieResult result = encode_movie(input, output);
  ASSERT_TRUE(result.ok()) << result.error;
  const MovieProbe probe = probe_movie(output);
  ASSERT_TRUE(probe.ok()) << probe.error;
  EXPECT_EQ(probe.frame_count, 10);
  EXPECT_FALSE(probe.has_audio);
  EXPECT_NEAR(probe.duration, 10 / fps, 1.0 / fps);
}

TEST(MovieEncoder, MissingFramePatternFailsCleanly)
{
  const auto directory = fresh_directory();
  MovieInput input;
  input.frame_pattern = (directory / "nowhere" / "frame_%05d.png").string();
  input.frame_count = frame_count;
  input.fps = fps;
  const auto output = directory / "movie.mp4";
  const MovieResult result = encode_movie(input, output);
  ASSERT_FALSE(result.ok());
  EXPECT_TRUE(contains(result.error, "missing")) << result.error;
  EXPECT_TRUE(contains(result.error, (directory / "nowhere" / "frame_00000.png").string()))
    << result.error;
  EXPECT_TRUE(file_names(directory).empty());
}

TEST(MovieEncoder, AGapInTheFramesIsNamed)
{
  const auto directory = fresh_directory();
  MovieInput input = write_frames(directory);
  std::filesystem::remove(frame_path(input.frame_pattern, 20).path);
  const MovieResult result = encode_movie(input, directory / "movie.mp4");
  ASSERT_FALSE(result.ok());
  EXPECT_TRUE(contains(result.error, "frame_00020.png")) << result.error;
  EXPECT_EQ(file_names(directory), std::vector<std::string>{ "frames" });
}

TEST(MovieEncoder, FfmpegFailureLeavesNoPartialFileAndKeepsTheOldMovie)
{
  const auto directory = fresh_directory();
  MovieInput input = write_frames(directory, 4);
  // Files that exist but are not PNG: only ffmpeg can tell, after it has started.
  for (int k = 0; k < 4; ++k)
    std::ofstream(frame_path(input.frame_pattern, k).path) << "not a PNG image";
  const auto output = directory / "movie.mp4";
  std::ofstream(output) << "the previous movie";

  const MovieResult result = encode_movie(input, output);
  ASSERT_FALSE(result.ok());
  EXPECT_TRUE(contains(result.error, "ffmpeg exited with status")) << result.error;
  EXPECT_GT(result.error.size(),
    std::string("ffmpeg exited with status 1: ").size() + std::string("encoding ").size() +
      output.string().size())
    << "ffmpeg's own message is missing: " << result.error;
  EXPECT_EQ(file_names(directory), (std::vector<std::string>{ "frames", "movie.mp4" }));
  std::ifstream old(output);
  std::string text;
  std::getline(old, text);
  EXPECT_EQ(text, "the previous movie");
}

TEST(MovieEncoder, CancelStopsFfmpegAndPutsNothingInPlace)
{
  const auto directory = fresh_directory();
  const MovieInput input = write_frames(directory);
  MovieOptions options;
  int polls = 0;
  options.cancel = [&] { return ++polls >= 1; }; // asked at once: ffmpeg is stopped
  const auto output = directory / "movie.mp4";
  const MovieResult result = encode_movie(input, output, options);
  EXPECT_TRUE(result.cancelled);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.error.find("cancelled"), std::string::npos) << result.error;
  EXPECT_GE(polls, 1);
  EXPECT_FALSE(std::filesystem::exists(output));
  for (const std::string& name : file_names(directory))
  {
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "temporary left behind: " << name;
    EXPECT_EQ(name.find("partial"), std::string::npos) << "partial file left behind: " << name;
  }
}

TEST(MovieEncoder, SoundOfAnotherDurationIsRejected)
{
  const auto directory = fresh_directory();
  MovieInput input = write_frames(directory, 24);
  input.audio = write_tone(directory / "long.wav", 72); // 3 s against 1 s of frames
  const MovieResult result = encode_movie(input, directory / "movie.mp4");
  ASSERT_FALSE(result.ok());
  EXPECT_TRUE(contains(result.error, "lasts 3 s")) << result.error;

  input.audio = directory / "missing.wav";
  const MovieResult missing = encode_movie(input, directory / "movie.mp4");
  ASSERT_FALSE(missing.ok());
  EXPECT_TRUE(contains(missing.error, "missing.wav")) << missing.error;
  EXPECT_FALSE(std::filesystem::exists(directory / "movie.mp4"));
}

TEST(MovieEncoder, InvalidInputsAndAMissingProgramAreErrors)
{
  const auto directory = fresh_directory();
  MovieInput input = write_frames(directory, 2);
  const auto output = directory / "movie.mp4";

  MovieOptions missing_program;
  missing_program.ffmpeg = "frep-no-such-ffmpeg";
  const MovieResult no_ffmpeg = encode_movie(input, output, missing_program);
  ASSERT_FALSE(no_ffmpeg.ok());
  EXPECT_TRUE(contains(no_ffmpeg.error, "'frep-no-such-ffmpeg' was not found")) << no_ffmpeg.error;

  MovieInput bad = input;
  bad.fps = 0.0;
  EXPECT_TRUE(contains(encode_movie(bad, output).error, "fps"));
  bad = input;
  bad.frame_count = 0;
  EXPECT_TRUE(contains(encode_movie(bad, output).error, "frame_count"));
  bad = input;
  bad.frame_pattern = (directory / "frames" / "frame.png").string();
  EXPECT_TRUE(contains(encode_movie(bad, output).error, "exactly one"));
  EXPECT_FALSE(encode_movie(input, directory / "no" / "movie.mp4").ok());
  EXPECT_FALSE(std::filesystem::exists(output));

  ProbeOptions missing_probe;
  missing_probe.ffprobe = "frep-no-such-ffprobe";
  const MovieProbe no_ffprobe = probe_movie(output, missing_probe);
  EXPECT_TRUE(contains(no_ffprobe.error, "'frep-no-such-ffprobe' was not found"))
    << no_ffprobe.error;
}

TEST(MovieProbe, ANonMovieIsAnError)
{
  const auto directory = fresh_directory();
  const auto path = directory / "text.mp4";
  std::ofstream(path) << "not a movie";
  const MovieProbe probe = probe_movie(path);
  EXPECT_FALSE(probe.ok());
  EXPECT_TRUE(contains(probe.error, path.string())) << probe.error;
  EXPECT_FALSE(probe_movie(directory / "missing.mp4").ok());
}

} // namespace
} // namespace frep::media
