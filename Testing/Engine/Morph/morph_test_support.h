// Shared by the metamorphosis tests: a scratch folder of key files, a written morph loaded as a
// model, a point value, and keys whose values are constants (so the morph's value is its weights'
// sum of those constants).
#pragma once

#include "Compiler/load_model.h"
#include "Eval/point_evaluator.h"
#include "Morph/morph_text.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace frep::morph::test_support
{

namespace fs = std::filesystem;
using frep::morph::Interpolation;
using frep::morph::KeyPlacement;
using frep::morph::MorphSpec;

const std::string kHomotopic = std::string(FREPKIT_SOURCE_DIR) + "/Examples/homotopic/";

// A scratch folder of key files, removed at the end.
struct KeyFolder
{
  fs::path dir =
    fs::temp_directory_path() / ("frep_morph_test_" + std::to_string(std::random_device{}()));
  KeyFolder() { fs::create_directories(dir); }
  ~KeyFolder() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) const
  {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
};

inline std::shared_ptr<const frep::Model> load(const frep::morph::MorphText& morph,
  const std::string& object = "")
{
  EXPECT_TRUE(morph.ok()) << frep::format_diagnostics(morph.diagnostics);
  frep::LoadOptions options;
  options.libraries = morph.libraries;
  options.functions = morph.functions; // the keys' distances, when normalised
  options.object = object;
  const frep::LoadedModel loaded =
    frep::load_model(frep::ModelSource::from_text(morph.text, "morph.hf"), options);
  EXPECT_TRUE(loaded.ok()) << loaded.message() << "\n" << morph.text;
  return loaded.model;
}

inline double value(const frep::Model& model, const std::vector<double>& x)
{
  frep::PointEvaluator point(model.tape());
  double out = 0.0;
  EXPECT_EQ(point.evaluate(x, std::span<double>(&out, 1)), 0);
  return out;
}

// Keys whose values are constants c_k = k + 1 in x[1..2]: the morph's value is sum w_k c_k.
inline MorphSpec constant_keys(const KeyFolder& folder, const std::vector<int>& lattice, Interpolation s)
{
  MorphSpec spec;
  spec.lattice = lattice;
  spec.scheme = s;
  std::size_t count = 1;
  for (const int n : lattice)
    count *= static_cast<std::size_t>(n);
  for (std::size_t k = 0; k < count; ++k)
  {
    const std::string name = "key" + std::to_string(k);
    spec.keys.push_back(
      { folder.write(
          name + ".hf", name + "(x[2], a[1]) { " + name + " = " + std::to_string(k + 1) + "; }\n"),
        "" });
  }
  return spec;
}

} // namespace frep::morph::test_support
