// The models the benchmarks run: every external model under ../shared/hyperfun/models (with the
// box its reference values were computed on) and the generated 200-sphere R-union, as a
// left-fold chain and as a balanced pairwise tree.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace frep::bench
{

struct BenchModel
{
  std::string name;
  std::string text;   ///< HyperFun source
  std::string object; ///< object to evaluate
  std::array<double, 3> lo{}, hi{}; ///< the box the points are drawn from
};

/// All benchmark models; throws std::runtime_error if the shared folder is missing.
std::vector<BenchModel> benchmark_models(const std::string& shared_dir);

/// HyperFun text of the union of `count` spheres of radius 0.6 with pseudo-random centres in
/// [-8,8]^3 (fixed seed), as a chain u = u | s_i or as a balanced tree.
std::string sphere_union_model(int count, bool balanced);

} // namespace frep::bench
