// The models the benchmarks run: every external model under ../shared/hyperfun/models (with the
// box its reference values were computed on), the generated 200-sphere R-union, as a left-fold
// chain and as a balanced pairwise tree, and the same spheres joined by max (a chain).
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
/// [-8,8]^3 (fixed seed), as a chain u = u | s_i or as a balanced tree; with `by_max`, joined by
/// max(u, s_i) instead of the R-union (the chain only).
std::string sphere_union_model(int count, bool balanced, bool by_max = false);

} // namespace frep::bench
