#include "Media/frequency_analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace frep::media
{
namespace
{

std::vector<float> sine(double frequency,
  double amplitude,
  std::size_t count,
  int rate,
  double phase = 0.3)
{
  std::vector<float> samples(count);
  for (std::size_t i = 0; i < count; ++i)
    samples[i] = static_cast<float>(
      amplitude * std::sin(2.0 * std::numbers::pi * frequency * i / rate + phase));
  return samples;
}

TEST(FrequencyAnalysis, DominantFrequencyOfSteadyTones)
{
  for (const double f : { 220.0, 261.63, 330.3, 440.0, 617.0, 880.0 })
  {
    const auto samples = sine(f, 0.5, 4096, 44100);
    const auto measured = dominant_frequency(samples, 44100);
    ASSERT_TRUE(measured) << f;
    EXPECT_NEAR(*measured, f, f * 0.001) << f;
  }
}

TEST(FrequencyAnalysis, StrongestOfTwoTonesAndTheBand)
{
  auto samples = sine(300.0, 0.2, 4096, 48000);
  const auto stronger = sine(700.0, 0.6, 4096, 48000);
  for (std::size_t i = 0; i < samples.size(); ++i)
    samples[i] += stronger[i];
  EXPECT_NEAR(dominant_frequency(samples, 48000).value_or(0.0), 700.0, 0.7);
  // Restricted to a band below the stronger tone, the weaker one is found.
  EXPECT_NEAR(dominant_frequency(samples, 48000, 100.0, 500.0).value_or(0.0), 300.0, 0.3);
}

TEST(FrequencyAnalysis, NoFrequencyInSilenceOrTinyWindows)
{
  EXPECT_FALSE(dominant_frequency(std::vector<float>(4096, 0.0f), 44100));
  EXPECT_FALSE(dominant_frequency(sine(440.0, 0.5, 8, 44100), 44100));
  EXPECT_FALSE(dominant_frequency(sine(440.0, 0.5, 4096, 44100), 0));
  EXPECT_FALSE(dominant_frequency(sine(440.0, 0.5, 4096, 44100), 44100, 500.0, 400.0));
}

TEST(FrequencyAnalysis, AmplitudeAndRms)
{
  const auto samples = sine(440.0, 0.3, 4096, 44100);
  EXPECT_NEAR(amplitude_at(samples, 44100, 440.0), 0.3, 0.006);
  EXPECT_LT(amplitude_at(samples, 44100, 880.0), 1e-3);
  EXPECT_NEAR(rms(samples), 0.3 / std::numbers::sqrt2, 0.002);
  EXPECT_EQ(rms({}), 0.0);
  EXPECT_EQ(amplitude_at({}, 44100, 440.0), 0.0);
}

} // namespace
} // namespace frep::media
