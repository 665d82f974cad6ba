#include "Media/frequency_analysis.h"
#include "Media/tone_synthesis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace frep::media
{
namespace
{

constexpr int rate = 44100;
constexpr std::size_t window = 4096;

VoiceFrames steady(int frame_count, VoiceParams voice)
{
  return VoiceFrames(static_cast<std::size_t>(frame_count), std::vector<VoiceParams>{ voice });
}

std::span<const float> slice(const std::vector<float>& samples,
  std::size_t start,
  std::size_t count = window)
{
  return std::span<const float>(samples).subspan(start, count);
}

double peak(const std::vector<float>& samples)
{
  double result = 0.0;
  for (const float s : samples)
    result = std::max(result, static_cast<double>(std::abs(s)));
  return result;
}

TEST(ToneSynthesis, LengthMatchesTheFramesDuration)
{
  const auto two_seconds = synthesise(steady(48, {}), 24.0, rate);
  ASSERT_TRUE(two_seconds.ok()) << two_seconds.error;
  EXPECT_EQ(two_seconds.samples.size(), 88200u);

  const auto ntsc = synthesise(steady(7, {}), 29.97, 48000);
  ASSERT_TRUE(ntsc.ok()) << ntsc.error;
  EXPECT_EQ(ntsc.samples.size(), static_cast<std::size_t>(std::llround(7 / 29.97 * 48000)));
  EXPECT_EQ(synthesis_length(7, 29.97, 48000), ntsc.samples.size());

  const auto none = synthesise({}, 24.0, rate);
  ASSERT_TRUE(none.ok()) << none.error;
  EXPECT_TRUE(none.samples.empty());
}

TEST(ToneSynthesis, EmptyVoiceListsAreSilence)
{
  const auto result = synthesise(VoiceFrames(24), 24.0, rate);
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_EQ(result.samples.size(), 44100u);
  EXPECT_EQ(peak(result.samples), 0.0);
}

TEST(ToneSynthesis, PitchRampMeasuresItsEndsAndRisesInBetween)
{
  // 48 frames at 24 fps: 220 Hz held for 6 frames, a linear ramp, 440 Hz for the last 6.
  VoiceFrames frames;
  for (int k = 0; k < 48; ++k)
  {
    const double t = std::clamp((k - 5) / 36.0, 0.0, 1.0);
    frames.push_back({ { 220.0 + 220.0 * t, 0.7, 0.3 } });
  }
  const auto result = synthesise(frames, 24.0, rate);
  ASSERT_TRUE(result.ok()) << result.error;
  const std::vector<float>& s = result.samples;

  const auto start = dominant_frequency(slice(s, 0), rate);
  const auto end = dominant_frequency(slice(s, s.size() - window), rate);
  ASSERT_TRUE(start && end);
  EXPECT_NEAR(*start, 220.0, 2.2);
  EXPECT_NEAR(*end, 440.0, 4.4);

  // Between the ends the pitch rises steadily: at the centre of frame 23 (the ramp is
  // symmetric about it over the window) it is the frame's value.
  const auto middle_start = static_cast<std::size_t>(23.5 / 24.0 * rate) - window / 2;
  const auto middle = dominant_frequency(slice(s, middle_start), rate);
  ASSERT_TRUE(middle);
  EXPECT_NEAR(*middle, frames[23][0].pitch, frames[23][0].pitch * 0.01);
  double previous = 0.0;
  for (std::size_t at = 0; at + window <= s.size(); at += window)
  {
    const auto f = dominant_frequency(slice(s, at), rate);
    ASSERT_TRUE(f);
    EXPECT_GT(*f, previous - 1.0) << "at sample " << at;
    previous = *f;
  }
}

TEST(ToneSynthesis, LoudnessIsTheAmplitudeOfAPureTone)
{
  const auto quiet = synthesise(steady(24, { 330.0, 0.2, 0.0 }), 24.0, rate);
  const auto loud = synthesise(steady(24, { 330.0, 0.8, 0.0 }), 24.0, rate);
  ASSERT_TRUE(quiet.ok() && loud.ok());
  const double quiet_rms = rms(slice(quiet.samples, 8000, 20000));
  const double loud_rms = rms(slice(loud.samples, 8000, 20000));
  EXPECT_NEAR(loud_rms / quiet_rms, 4.0, 0.04);
  EXPECT_NEAR(loud_rms, 0.8 / std::numbers::sqrt2, 0.008);
  EXPECT_NEAR(peak(loud.samples), 0.8, 0.001);
}

TEST(ToneSynthesis, TimbreZeroIsPureAndTimbreOneHasHarmonics)
{
  const double f = 330.0;
  const auto pure = synthesise(steady(24, { f, 0.8, 0.0 }), 24.0, rate);
  const auto bright = synthesise(steady(24, { f, 0.8, 1.0 }), 24.0, rate);
  ASSERT_TRUE(pure.ok() && bright.ok());
  const auto p = slice(pure.samples, 10000);
  const auto b = slice(bright.samples, 10000);

  const double pure_fundamental = amplitude_at(p, rate, f);
  EXPECT_NEAR(pure_fundamental, 0.8, 0.02);
  for (int k = 2; k <= 5; ++k)
    EXPECT_LT(amplitude_at(p, rate, k * f), 1e-3 * pure_fundamental) << "harmonic " << k;

  // Harmonic k has weight 1/k relative to the fundamental.
  const double bright_fundamental = amplitude_at(b, rate, f);
  for (int k = 2; k <= 5; ++k)
    EXPECT_NEAR(amplitude_at(b, rate, k * f) / bright_fundamental, 1.0 / k, 0.02 / k)
      << "harmonic " << k;
  // The dominant frequency is still the fundamental.
  EXPECT_NEAR(dominant_frequency(b, rate).value_or(0.0), f, f * 0.01);
}

TEST(ToneSynthesis, NoSampleExceedsOne)
{
  // Four loud bright voices, which would sum to well beyond 1.
  VoiceFrames frames(48);
  for (auto& frame : frames)
    for (double pitch : { 110.0, 165.0, 220.0, 330.0 })
      frame.push_back({ pitch, 1.0, 1.0 });
  for (const Mixing mixing : { Mixing::Average, Mixing::SoftLimit })
  {
    SynthesisOptions options;
    options.mixing = mixing;
    const auto result = synthesise(frames, 24.0, rate, options);
    ASSERT_TRUE(result.ok()) << result.error;
    EXPECT_LE(peak(result.samples), 1.0);
    if (mixing == Mixing::SoftLimit) // the sum really went into the limiter
    {
      EXPECT_GT(peak(result.samples), 0.8);
    }
  }
}

TEST(ToneSynthesis, PhaseIsContinuousAcrossPitchChanges)
{
  // An abrupt change 220 -> 660 -> 330 Hz between frames, at full loudness. A pure tone of
  // amplitude 1 at f changes by at most 2 pi f / rate per sample; a phase jump would break
  // that bound by far.
  VoiceFrames frames;
  for (int k = 0; k < 36; ++k)
    frames.push_back({ { k < 12 ? 220.0 : (k < 24 ? 660.0 : 330.0), 1.0, 0.0 } });
  for (const Interpolation mode : { Interpolation::Linear, Interpolation::Cosine })
  {
    SynthesisOptions options;
    options.interpolation = mode;
    const auto result = synthesise(frames, 12.0, rate, options);
    ASSERT_TRUE(result.ok()) << result.error;
    const double max_slope = 2.0 * std::numbers::pi * 660.0 / rate;
    double largest_step = 0.0;
    for (std::size_t i = 1; i < result.samples.size(); ++i)
      largest_step = std::max(
        largest_step, static_cast<double>(std::abs(result.samples[i] - result.samples[i - 1])));
    EXPECT_LE(largest_step, max_slope * 1.001);
    EXPECT_GT(largest_step, max_slope * 0.95); // the 660 Hz part is really there
  }
}

TEST(ToneSynthesis, FadesInAndOut)
{
  const auto result = synthesise(steady(24, { 440.0, 1.0, 0.0 }), 24.0, rate);
  ASSERT_TRUE(result.ok());
  const std::vector<float>& s = result.samples;
  EXPECT_LT(std::abs(s.front()), 0.01);
  EXPECT_LT(std::abs(s.back()), 0.01);
  // The first and last millisecond are much quieter than the steady tone.
  EXPECT_LT(rms(slice(s, 0, 44)), 0.1);
  EXPECT_LT(rms(slice(s, s.size() - 44, 44)), 0.1);
  EXPECT_GT(rms(slice(s, 20000, 4410)), 0.69);
}

TEST(ToneSynthesis, AVoiceMissingFromFramesIsSilentThere)
{
  // Frames 0..11: one voice at 220 Hz; frames 12..23: a second one at 550 Hz joins.
  VoiceFrames frames;
  for (int k = 0; k < 24; ++k)
  {
    frames.push_back({ { 220.0, 0.8, 0.0 } });
    if (k >= 12)
      frames.back().push_back({ 550.0, 0.8, 0.0 });
  }
  const auto result = synthesise(frames, 24.0, rate);
  ASSERT_TRUE(result.ok());
  const auto first = slice(result.samples, 2000);
  const auto second = slice(result.samples, result.samples.size() - window - 2000);
  EXPECT_LT(amplitude_at(first, rate, 550.0), 1e-3);
  EXPECT_NEAR(amplitude_at(second, rate, 550.0), 0.4, 0.02); // 0.8 / two voices
  EXPECT_NEAR(amplitude_at(first, rate, 220.0), 0.4, 0.02);
}

TEST(ToneSynthesis, InvalidInputsAreErrors)
{
  const auto frames = steady(4, {});
  const auto expect_error = [](const SynthesisResult& r, const std::string& word)
  {
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find(word), std::string::npos) << r.error;
    EXPECT_TRUE(r.samples.empty());
  };
  expect_error(synthesise(frames, 0.0, rate), "fps");
  expect_error(synthesise(frames, std::nan(""), rate), "fps");
  expect_error(synthesise(frames, 24.0, 4000), "sample_rate");
  expect_error(synthesise(frames, 24.0, 200000), "sample_rate");
  SynthesisOptions no_harmonics;
  no_harmonics.max_harmonics = 0;
  expect_error(synthesise(frames, 24.0, rate, no_harmonics), "max_harmonics");

  auto bad = frames;
  bad[2][0].pitch = std::nan("");
  expect_error(synthesise(bad, 24.0, rate), "frames[2][0].pitch");
  bad = frames;
  bad[1][0].pitch = -5.0;
  expect_error(synthesise(bad, 24.0, rate), "frames[1][0].pitch");
  bad = frames;
  bad[3][0].loudness = INFINITY;
  expect_error(synthesise(bad, 24.0, rate), "frames[3][0].loudness");
  bad = frames;
  bad[0][0].timbre = 1.5;
  expect_error(synthesise(bad, 24.0, rate), "frames[0][0].timbre");
}

} // namespace
} // namespace frep::media
