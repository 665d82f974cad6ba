// A metamorphosis written as HyperFun (Morph/morph_text.h): the paper's Meta5D from its four key
// files, value for value (linear 2 x 2 is the paper's formula); the weights a compiled morph
// evaluates are lattice_weights' for every scheme, its corners the corner keys exactly; the
// pasted form loads without the key files; a fixed cell's tape keeps only the keys it uses; bad
// lattices, keys and names are diagnostics.
#include "Morph/morph_text.h"

#include "Compiler/load_model.h"
#include "Eval/point_evaluator.h"
#include "Morph/key_frame.h"
#include "Morph/lattice_weights.h"

#include "morph_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace
{
using frep::morph::Interpolation;
using frep::morph::KeyPlacement;
using frep::morph::MorphSpec;
using namespace frep::morph::test_support;
} // namespace

TEST(MorphText, LinearTwoByTwoIsThePapersMeta5DBitForBit)
{
  MorphSpec spec;
  for (const char* key : { "cat", "robot", "nihon", "roblet" })
    spec.keys.push_back({ kHomotopic + key + ".hf", "" });
  spec.lattice = { 2, 2 };
  spec.name = "meta";
  frep::LoadOptions meta5d;
  meta5d.object = "meta5d";
  const frep::LoadedModel paper =
    frep::load_model(frep::ModelSource::file(kHomotopic + "meta5d.hf"), meta5d);
  ASSERT_TRUE(paper.ok()) << paper.message();
  for (const KeyPlacement placement : { KeyPlacement::Library, KeyPlacement::Pasted })
  {
    const frep::morph::MorphText morph = frep::morph::write_morph(spec, placement);
    EXPECT_EQ(morph.x_dim, 5);
    EXPECT_EQ(morph.libraries.size(), placement == KeyPlacement::Library ? 4u : 0u);
    const auto model = load(morph); // my_model, which calls meta
    ASSERT_TRUE(model);
    frep::PointEvaluator ours(model->tape()), theirs(paper.model->tape());
    std::mt19937 random(5);
    std::uniform_real_distribution<double> space(-10, 10), time(0, 1);
    for (int i = 0; i < 3000; ++i)
    {
      std::vector<double> x{
        space(random), space(random), space(random), time(random), time(random)
      };
      if (i < 16) // the corners and edges of the lattice, where weights are exactly 0 and 1
      {
        x[3] = (i & 1) ? 1.0 : (i & 4) ? 0.5 : 0.0;
        x[4] = (i & 2) ? 1.0 : (i & 8) ? 0.5 : 0.0;
      }
      double a = 0.0, b = 0.0;
      ASSERT_EQ(ours.evaluate(x, std::span<double>(&a, 1)), 0);
      ASSERT_EQ(theirs.evaluate(x, std::span<double>(&b, 1)), 0);
      ASSERT_EQ(a, b) << "at x4 = " << x[3] << ", x5 = " << x[4];
    }
  }
}

TEST(MorphText, WeightsAreLatticeWeightsAndCornersTheKeys)
{
  const KeyFolder folder;
  for (const Interpolation scheme :
    { Interpolation::Linear, Interpolation::CatmullRom, Interpolation::BSpline })
  {
    for (const std::vector<int>& lattice : { std::vector<int>{ 5 }, std::vector<int>{ 3, 4 } })
    {
      const MorphSpec spec = constant_keys(folder, lattice, scheme);
      const auto model = load(frep::morph::write_morph(spec, KeyPlacement::Library));
      ASSERT_TRUE(model);
      for (int i = 0; i <= 40; ++i)
      {
        std::vector<double> t{ i / 40.0 };
        if (lattice.size() == 2)
          t.push_back(std::fmod(i * 0.37, 1.0));
        const std::vector<double> w = frep::morph::lattice_weights(scheme, lattice, t);
        double expected = 0.0;
        for (std::size_t k = 0; k < w.size(); ++k)
          expected += w[k] * static_cast<double>(k + 1);
        std::vector<double> x{ 0.5, -0.5 };
        x.insert(x.end(), t.begin(), t.end());
        EXPECT_NEAR(value(*model, x), expected, 1e-13)
          << frep::morph::interpolation_name(scheme) << " t = " << t[0];
      }
      // The corners: exactly the corner key (x outside [0, 1] is clamped).
      const double last = static_cast<double>(spec.keys.size());
      std::vector<double> low{ 0, 0 }, high{ 0, 0 };
      for (std::size_t a = 0; a < lattice.size(); ++a)
      {
        low.push_back(-0.5);
        high.push_back(1.5);
      }
      EXPECT_EQ(value(*model, low), 1.0);
      EXPECT_EQ(value(*model, high), last);
    }
  }
}

TEST(MorphText, PastedLoadsAloneAndAFixedCellKeepsOnlyItsKeys)
{
  const KeyFolder folder;
  MorphSpec spec = constant_keys(folder, { 5 }, Interpolation::Linear);
  // Keys that depend on x, so the tape has work per key.
  for (std::size_t k = 0; k < spec.keys.size(); ++k)
  {
    const std::string name = "key" + std::to_string(k);
    spec.keys[k].file = folder.write(name + ".hf",
      name + "(x[2], a[1]) { " + name + " = " + std::to_string(k + 1) +
        " - x[1]*x[1] - x[2]*x[2]; }\n");
  }
  const frep::morph::MorphText pasted = frep::morph::write_morph(spec, KeyPlacement::Pasted);
  ASSERT_TRUE(pasted.ok());
  EXPECT_TRUE(pasted.libraries.empty());
  const frep::LoadedModel alone =
    frep::load_model(frep::ModelSource::from_text(pasted.text, "pasted.hf"));
  ASSERT_TRUE(alone.ok()) << alone.message();
  EXPECT_NEAR(value(*alone.model, { 0.5, 0.5, 0.25 + 0.125 }), 2.5 - 0.5, 1e-15);
  frep::Specialisation cell;
  cell.fixed = { std::nullopt, std::nullopt, 0.3 }; // between keys 1 and 2 (nodes 0.25, 0.5)
  const auto full = alone.model->tape();
  const auto fixed = alone.model->specialise(cell);
  EXPECT_LT(fixed->code.size() * 2, full->code.size())
    << "the cell's tape has " << fixed->code.size() << " instructions, the whole "
    << full->code.size();
}

TEST(MorphText, BadRequestsAreDiagnostics)
{
  const KeyFolder folder;
  const std::string ball = folder.write("ball.hf", "ball(x[3], a[1]) { ball = 1 - x[1]^2; }\n");
  const std::string disc = folder.write("disc.hf", "disc(x[2], a[1]) { disc = 1 - x[1]^2; }\n");
  const std::string twice = folder.write("twice.hf", "ball(x[3], a[1]) { ball = 2; }\n");
  const std::string coloured =
    folder.write("colour.hf", "colour(x[3], a[1], s[3]) { s[1] = 1; colour = 1; }\n");
  const auto message = [](const MorphSpec& spec)
  {
    const frep::morph::MorphText m = frep::morph::write_morph(spec, KeyPlacement::Library);
    EXPECT_FALSE(m.ok());
    EXPECT_TRUE(m.text.empty());
    return frep::format_diagnostics(m.diagnostics);
  };
  MorphSpec spec;
  spec.keys = { { ball, "" }, { ball, "" }, { ball, "" } };
  spec.lattice = { 2, 2 };
  EXPECT_NE(
    message(spec).find("the lattice 2 x 2 has 4 nodes, 3 keys were given"), std::string::npos);
  spec.lattice = { 3, 1 };
  EXPECT_NE(message(spec).find("2 to 64 nodes"), std::string::npos);
  spec.keys = { { ball, "" }, { disc, "" } };
  spec.lattice = { 2 };
  EXPECT_NE(message(spec).find("disc.hf:1:1: error: the key disc(x[2], a[1]) and the key "
                               "ball(x[3], a[1])"),
    std::string::npos)
    << message(spec);
  spec.keys = { { ball, "" }, { twice, "" } };
  EXPECT_NE(message(spec).find("the object 'ball' is defined in"), std::string::npos);
  spec.keys = { { ball, "" }, { coloured, "" } };
  EXPECT_NE(message(spec).find("has s[3]"), std::string::npos);
  spec.keys = { { ball, "" }, { ball, "cube" } };
  EXPECT_NE(message(spec).find("cube"), std::string::npos);
  spec.keys = { { ball, "" }, { (folder.dir / "missing.hf").string(), "" } };
  EXPECT_NE(message(spec).find("missing.hf"), std::string::npos);
  spec.keys = { { ball, "" }, { ball, "" } };
  spec.name = "2ball";
  EXPECT_NE(message(spec).find("not a HyperFun object name"), std::string::npos);
  spec.name = "ball";
  EXPECT_NE(message(spec).find("an object the metamorphosis writes"), std::string::npos);
}

// Aligned by centroids and sizes, two balls of radii 1 and 2 centred at x = -3 and 3 blend into
// a ball of the blended radius at the blended centre (F scales with the size, so each key's
// zero set travels and grows into the same sphere); the ends stay the keys bit for bit.
TEST(MorphText, AlignedBallsTravelAndGrowIntoOneBall)
{
  const KeyFolder folder;
  MorphSpec spec;
  spec.keys = { { folder.write("small.hf",
                    "small(x[3], a[1]) { small = 1 - (x[1] + 3)^2 - x[2]^2 - x[3]^2; }\n"),
                  "" },
    { folder.write(
        "large.hf", "large(x[3], a[1]) { large = 4 - (x[1] - 3)^2 - x[2]^2 - x[3]^2; }\n"),
      "" } };
  spec.lattice = { 2 };
  spec.alignment = frep::morph::Alignment::CentroidAndSize;
  const frep::morph::MorphText morph = frep::morph::write_morph(spec, KeyPlacement::Pasted);
  const auto model = load(morph);
  ASSERT_TRUE(model);
  const auto small = frep::load_model(frep::ModelSource::file(spec.keys[0].file)).model;
  const auto large = frep::load_model(frep::ModelSource::file(spec.keys[1].file)).model;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> space(-6, 6);
  for (int i = 0; i < 200; ++i)
  {
    const double x = space(random), y = space(random), z = space(random);
    EXPECT_EQ(value(*model, { x, y, z, 0.0 }), value(*small, { x, y, z }));
    EXPECT_EQ(value(*model, { x, y, z, 1.0 }), value(*large, { x, y, z }));
  }
  // Halfway: a ball of radius 1.5 about x = 0 (the measured centroids and sizes are within a
  // grid step of the true ones).
  for (const double r : { 1.35, -1.35 })
  {
    EXPECT_GT(value(*model, { r, 0, 0, 0.5 }), 0.0) << r;
    EXPECT_GT(value(*model, { 0, r, 0, 0.5 }), 0.0) << r;
  }
  for (const double r : { 1.65, -1.65 })
  {
    EXPECT_LT(value(*model, { r, 0, 0, 0.5 }), 0.0) << r;
    EXPECT_LT(value(*model, { 0, 0, r, 0.5 }), 0.0) << r;
  }
  // Unaligned, the same two balls halfway are nothing near the origin.
  spec.alignment = frep::morph::Alignment::None;
  const auto in_place = load(frep::morph::write_morph(spec, KeyPlacement::Pasted));
  ASSERT_TRUE(in_place);
  EXPECT_LT(value(*in_place, { 0, 0, 0, 0.5 }), 0.0);
}

TEST(MorphText, KeyFrameIsTheSolidsCentroidAndSize)
{
  const auto ball = frep::load_model(
    frep::ModelSource::from_text("b(x[3], a[1]) { b = 4 - (x[1] - 1)^2 - (x[2] + 2)^2 - x[3]^2; }"))
                      .model;
  const frep::morph::KeyFrame frame = frep::morph::measure_key_frame(ball->tape(), 64);
  ASSERT_TRUE(frame.ok()) << frame.error;
  EXPECT_NEAR(frame.centroid[0], 1.0, 0.01);
  EXPECT_NEAR(frame.centroid[1], -2.0, 0.01);
  EXPECT_NEAR(frame.centroid[2], 0.0, 0.01);
  EXPECT_NEAR(frame.size, std::cbrt(4.0 / 3.0 * M_PI * 8.0), 0.05); // volume^(1/3) of radius 2
  const auto half_space =
    frep::load_model(frep::ModelSource::from_text("h(x[3], a[1]) { h = x[1]; }")).model;
  EXPECT_NE(frep::morph::measure_key_frame(half_space->tape()).error.find("not bounded"),
    std::string::npos);
}

TEST(MorphText, DistanceKeepsEveryKeysSignAndAddsDepth)
{
  // Two of the Homotopic Fun keys (bounded values, thin whiskers and strokes) on one axis.
  MorphSpec spec;
  spec.keys = { { kHomotopic + "cat.hf", "cat" }, { kHomotopic + "nihon.hf", "nihon" } };
  spec.lattice = { 2 };
  spec.normalisation = frep::morph::Normalisation::Distance;
  spec.distance_samples = 64;
  const frep::morph::MorphText morph = frep::morph::write_morph(spec, KeyPlacement::Pasted);
  ASSERT_EQ(morph.distances.size(), 2u);
  EXPECT_EQ(morph.distances[0].function, "mdist_cat");
  const auto model = load(morph);
  ASSERT_TRUE(model);
  const auto cat = frep::load_model(frep::ModelSource::file(spec.keys[0].file)).model;
  const auto nihon = frep::load_model(frep::ModelSource::file(spec.keys[1].file)).model;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> space(-10, 10);
  int deeper = 0, farther = 0;
  for (int i = 0; i < 3000; ++i)
  {
    const double x = space(random), y = space(random), z = space(random);
    const double c = value(*cat, { x, y, z }), n = value(*nihon, { x, y, z });
    const double m0 = value(*model, { x, y, z, 0.0 }), m1 = value(*model, { x, y, z, 1.0 });
    ASSERT_EQ(m0 >= 0, c >= 0) << x << " " << y << " " << z; // the zero set, exactly
    ASSERT_EQ(m1 >= 0, n >= 0) << x << " " << y << " " << z;
    ASSERT_TRUE(c >= 0 ? m0 >= c : m0 <= c); // the distance only ever adds on F's side
    deeper += m0 > c + 0.5;
    farther += m1 < n - 2.0;
    EXPECT_TRUE(std::isfinite(value(*model, { x, y, z, 0.5 })));
  }
  // The bounded keys saturate at 0.3 inside and -0.15 outside; normalised, values grow with
  // the depth and the distance.
  EXPECT_GT(deeper, 10);
  EXPECT_GT(farther, 1000);
}

TEST(MorphText, KeyDistanceIsTheBallsDistanceWithinACell)
{
  const auto ball = frep::load_model(
    frep::ModelSource::from_text("b(x[3], a[1]) { b = 3 - sqrt((x[1] - 1)^2 + x[2]^2 + x[3]^2); }"))
                      .model;
  const frep::morph::KeyDistance distance = frep::morph::measure_key_distance(ball->tape(), 48);
  ASSERT_TRUE(distance.ok()) << distance.error;
  const auto& g = distance.grid;
  double cell = 0.0;
  for (std::size_t k = 0; k < 3; ++k)
  {
    EXPECT_EQ(g.dims[k], 48);
    EXPECT_EQ(g.origin[k] * 1024, std::floor(g.origin[k] * 1024)); // dyadic: exact in a file
    EXPECT_EQ(g.spacing[k] * 1024, std::floor(g.spacing[k] * 1024));
    cell = std::max(cell, g.spacing[k]);
  }
  EXPECT_EQ(distance.band, 2 * cell);
  EXPECT_LT(g.origin[0], 1 - 3.5); // the solid's bounds padded
  double worst = 0.0;
  for (int k = 0; k < 48; ++k)
    for (int j = 0; j < 48; ++j)
      for (int i = 0; i < 48; ++i)
      {
        const double x = g.origin[0] + i * g.spacing[0], y = g.origin[1] + j * g.spacing[1],
                     z = g.origin[2] + k * g.spacing[2];
        const double exact = 3 - std::sqrt((x - 1) * (x - 1) + y * y + z * z);
        worst = std::max(
          worst, std::abs(g.values[static_cast<std::size_t>(i + 48 * (j + 48 * k))] - exact));
      }
  EXPECT_LT(worst, cell);
  const auto flat =
    frep::load_model(frep::ModelSource::from_text("d(x[2], a[1]) { d = 1 - x[1]^2 - x[2]^2; }"))
      .model;
  EXPECT_NE(frep::morph::measure_key_distance(flat->tape()).error.find("3-D"), std::string::npos);
  const auto none =
    frep::load_model(frep::ModelSource::from_text("e(x[3], a[1]) { e = -1 - x[1]^2; }")).model;
  EXPECT_NE(frep::morph::measure_key_distance(none->tape()).error.find("empty"), std::string::npos);
}
