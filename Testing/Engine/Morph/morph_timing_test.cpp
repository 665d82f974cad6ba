// A metamorphosis's timing and its keys' own weights (issue 29, item 3; Morph/timing.h,
// MorphSpec::key_weights): every curve keeps the nodes; a timed morph's weights are the lattice
// weights at the timed parameter (every scheme, 1-D and 2-D lattices); key weights move the
// blend toward the heavier key, vary in space, still sum to 1 and keep every node's key exactly;
// bad key weights are diagnostics at the expression's own column.
#include "Morph/morph_text.h"
#include "Morph/timing.h"

#include "morph_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace
{
using frep::morph::Interpolation;
using frep::morph::Key;
using frep::morph::KeyPlacement;
using frep::morph::MorphSpec;
using frep::morph::Timing;
using frep::morph::TimingCurve;
using namespace frep::morph::test_support;

std::vector<Timing> curves()
{
  return { { TimingCurve::Ease, 0 },
    { TimingCurve::EaseIn, 0 },
    { TimingCurve::EaseOut, 0 },
    { TimingCurve::Hold, 0.4 } };
}

} // namespace

TEST(MorphTiming, CurvesKeepTheNodesAndOnlyChangeTheSpeed)
{
  for (const Timing& timing : curves())
  {
    const std::string name = frep::morph::timing_name(timing);
    EXPECT_EQ(frep::morph::timing_curve(timing, 0.0), 0.0) << name;
    EXPECT_EQ(frep::morph::timing_curve(timing, 1.0), 1.0) << name;
    double previous = 0.0;
    for (int i = 1; i <= 100; ++i) // never backwards
    {
      const double now = frep::morph::timing_curve(timing, i / 100.0);
      EXPECT_GE(now, previous) << name << " at " << i / 100.0;
      previous = now;
    }
    const auto back = frep::morph::timing_from_name(name);
    ASSERT_TRUE(back) << name;
    EXPECT_EQ(back->curve, timing.curve);
    EXPECT_EQ(back->hold, timing.hold);
    // Three nodes: the middle one is still t = 0.5, the ends 0 and 1.
    EXPECT_EQ(frep::morph::timed_parameter(timing, 3, 0.5), 0.5) << name;
    EXPECT_EQ(frep::morph::timed_parameter(timing, 3, 0.0), 0.0) << name;
    EXPECT_EQ(frep::morph::timed_parameter(timing, 3, 1.0), 1.0) << name;
  }
  const Timing ease{ TimingCurve::Ease, 0 }, hold{ TimingCurve::Hold, 0.4 };
  EXPECT_DOUBLE_EQ(frep::morph::timing_curve(ease, 0.25), 0.15625); // 1/16 (3 - 1/2)
  EXPECT_EQ(frep::morph::timed_parameter(hold, 2, 0.15), 0.0);       // held at the first key
  EXPECT_EQ(frep::morph::timed_parameter(hold, 2, 0.85), 1.0);       // and at the second
  EXPECT_DOUBLE_EQ(frep::morph::timed_parameter(hold, 2, 0.5), 0.5);
  EXPECT_NEAR(frep::morph::timed_parameter(hold, 3, 0.3), (0.4 / 0.6) / 2, 1e-15); // u = 0.6
  EXPECT_TRUE(std::isnan(frep::morph::timed_parameter(ease, 3, std::nan(""))));
  EXPECT_EQ(frep::morph::timing_from_name("hold")->hold, 0.5);
  for (const char* bad : { "", "slow", "hold:1", "hold:-0.1", "hold:x", "hold:0.5s", "Ease" })
    EXPECT_FALSE(frep::morph::timing_from_name(bad)) << bad;
}

// The text's timing is timed_parameter operation for operation: a timed morph of constant keys
// is the lattice weights at the timed parameters, for every scheme, curve and lattice.
TEST(MorphTiming, TimedMorphWeighsTheKeysAtTheTimedParameter)
{
  const KeyFolder folder;
  for (const Interpolation scheme :
    { Interpolation::Linear, Interpolation::CatmullRom, Interpolation::BSpline })
  {
    for (const std::vector<int>& lattice : { std::vector<int>{ 5 }, std::vector<int>{ 3, 4 } })
    {
      for (const Timing& timing : curves())
      {
        MorphSpec spec = constant_keys(folder, lattice, scheme);
        spec.timing = timing;
        const auto model = load(frep::morph::write_morph(spec, KeyPlacement::Library));
        ASSERT_TRUE(model);
        for (int i = 0; i <= 40; ++i)
        {
          std::vector<double> t{ i / 40.0 };
          if (lattice.size() == 2)
            t.push_back(std::fmod(i * 0.37, 1.0));
          std::vector<double> timed;
          for (std::size_t a = 0; a < t.size(); ++a)
            timed.push_back(frep::morph::timed_parameter(timing, lattice[a], t[a]));
          const std::vector<double> w = frep::morph::lattice_weights(scheme, lattice, timed);
          double expected = 0.0;
          for (std::size_t k = 0; k < w.size(); ++k)
            expected += w[k] * static_cast<double>(k + 1);
          std::vector<double> x{ 0.5, -0.5 };
          x.insert(x.end(), t.begin(), t.end());
          EXPECT_NEAR(value(*model, x), expected, 1e-13)
            << frep::morph::interpolation_name(scheme) << ", " << frep::morph::timing_name(timing)
            << ", t = " << t[0];
        }
        std::vector<double> high{ 0, 0 };
        high.insert(high.end(), lattice.size(), 1.0);
        EXPECT_EQ(value(*model, high), static_cast<double>(spec.keys.size()));
      }
    }
  }
}

// Keys of values 1, 2, 3 on a line of 3 nodes: the middle key weighing 3 pulls the blend to it
// (at t = 0.25 the weights 1/2, 1/2 become 1/4, 3/4); a weight that grows with x[1] does so only
// where x[1] is large; equal keys give 1 (the weights sum to 1); every node is its key exactly.
TEST(MorphTiming, KeyWeightsPullTheBlendAndKeepEveryNode)
{
  const KeyFolder folder;
  for (const Interpolation scheme : { Interpolation::Linear, Interpolation::BSpline })
  {
    MorphSpec spec = constant_keys(folder, { 3 }, scheme);
    spec.key_weights = { { "KEY1", "3" } };
    const auto global = load(frep::morph::write_morph(spec, KeyPlacement::Pasted));
    spec.key_weights = { { "key1", "exp(x[1])" }, { "key2", "1 + 0*x[3]" } };
    const auto local = load(frep::morph::write_morph(spec, KeyPlacement::Library));
    ASSERT_TRUE(global && local);
    for (int i = 0; i <= 20; ++i)
    {
      const double t = i / 20.0;
      const std::vector<double> w = frep::morph::lattice_weights(scheme, std::vector<int>{ 3 },
        std::vector<double>{ t });
      for (const double x1 : { -2.0, 0.0, 2.0 })
      {
        const double g1 = std::exp(x1);
        const double expected =
          (w[0] * 1 + w[1] * g1 * 2 + w[2] * 3) / (w[0] + w[1] * g1 + w[2]);
        EXPECT_NEAR(value(*local, { x1, 0.0, t }), expected, 1e-13) << "t = " << t;
      }
      const double pulled = (w[0] * 1 + w[1] * 3 * 2 + w[2] * 3) / (w[0] + 3 * w[1] + w[2]);
      EXPECT_NEAR(value(*global, { 0.0, 0.0, t }), pulled, 1e-13) << "t = " << t;
    }
    EXPECT_EQ(value(*global, { 0.3, 0.1, 0.0 }), 1.0);
    EXPECT_EQ(value(*global, { 0.3, 0.1, 1.0 }), 3.0);
    if (scheme == Interpolation::Linear)
    {
      EXPECT_EQ(value(*global, { 0.3, 0.1, 0.5 }), 2.0);
      EXPECT_NEAR(value(*global, { 0.0, 0.0, 0.25 }), 0.25 * 1 + 0.75 * 2, 1e-15);
    }
  }
  // Equal keys: whatever the weights, the blend is 1 (the normalised weights sum to 1).
  MorphSpec same = constant_keys(folder, { 2, 2 }, Interpolation::Linear);
  for (const Key& key : same.keys)
    std::ofstream(key.file) << std::filesystem::path(key.file).stem().string() << "(x[2], a[1]) { "
                            << std::filesystem::path(key.file).stem().string() << " = 1; }\n";
  same.key_weights = { { "key0", "5" }, { "key3", "0.5 + x[2]*x[2]" } };
  const auto one = load(frep::morph::write_morph(same, KeyPlacement::Library));
  ASSERT_TRUE(one);
  for (int i = 0; i < 50; ++i)
    EXPECT_NEAR(value(*one, { 0.1 * i - 2, 0.07 * i, 0.02 * i, 1 - 0.02 * i }), 1.0, 1e-14);
}

TEST(MorphTiming, BadKeyWeightsAreDiagnostics)
{
  const KeyFolder folder;
  const auto message = [](const MorphSpec& spec)
  {
    const frep::morph::MorphText m = frep::morph::write_morph(spec, KeyPlacement::Library);
    EXPECT_FALSE(m.ok());
    EXPECT_TRUE(m.text.empty());
    return frep::format_diagnostics(m.diagnostics);
  };
  MorphSpec spec = constant_keys(folder, { 2 }, Interpolation::Linear);
  spec.key_weights = { { "dog", "2" } };
  EXPECT_NE(message(spec).find("a weight for 'dog', which is not one of the keys' objects"),
    std::string::npos);
  spec.key_weights = { { "key0", "2" }, { "Key0", "3" } };
  EXPECT_NE(message(spec).find("the key 'Key0' is given two weights"), std::string::npos);
  spec.key_weights = { { "key1", "2 +* x[1]" } };
  EXPECT_NE(message(spec).find("key weight 'key1':1:"), std::string::npos) << message(spec);
  spec.key_weights = { { "key1", "unknown_field(mx)" } };
  EXPECT_NE(message(spec).find("unknown_field"), std::string::npos) << message(spec);
  spec.key_weights = { { "key1", "1; key1 = 2" } };
  EXPECT_NE(message(spec).find("one expression"), std::string::npos);
  spec.key_weights = { { "key1", "2" } };
  spec.scheme = Interpolation::CatmullRom;
  EXPECT_NE(message(spec).find("never negative"), std::string::npos);
}
