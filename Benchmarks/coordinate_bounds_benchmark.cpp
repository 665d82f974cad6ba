// What finding a model's default intervals costs (frep::mesh::find_coordinate_bounds, the
// solid's bounds that vtkHyperFunSource, ParaView, Python's load and FRepStudio use when no range
// is given): wall time, the rule that applied and the intervals, for one model file.
//
// Usage: frep_coordinate_bounds_benchmark MODEL [--given lo,hi,lo,hi,...] [--repeat 5]
// --given: intervals of x1.., two numbers each; nan,nan leaves a coordinate to be bounded (e.g.
// nan,nan,nan,nan,nan,nan,0,1,0,1 for Meta5D with x4, x5 in [0, 1]). Prints the median time.
#include "benchmark_cli.h"

#include "Mesh/coordinate_bounds.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << "usage: frep_coordinate_bounds_benchmark MODEL [--given lo,hi,...] [--repeat N]\n";
    return 1;
  }
  std::vector<std::optional<frep::Interval>> given;
  int repeat = 5;
  for (int i = 2; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    if (option == "--repeat")
    {
      repeat = std::max(1, std::stoi(argv[i + 1]));
    }
    else if (option == "--given")
    {
      const std::vector<double> v = frep::bench::comma_numbers(argv[i + 1]);
      for (std::size_t k = 0; k + 1 < v.size(); k += 2)
      {
        given.push_back(
          std::isnan(v[k]) ? std::nullopt : std::optional<frep::Interval>({ v[k], v[k + 1] }));
      }
    }
    else
    {
      std::cerr << "unknown option " << option << "\n";
      return 1;
    }
  }
  const auto model = frep::bench::compile_model_file(argv[1]);
  if (!model)
  {
    return 1;
  }
  std::vector<double> seconds;
  frep::mesh::CoordinateBounds result;
  for (int r = 0; r < repeat; ++r)
  {
    const auto t0 = std::chrono::steady_clock::now();
    result = frep::mesh::find_coordinate_bounds(*model, {}, given, frep::Interval{ -10, 10 });
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(seconds.begin(), seconds.end());
  static const char* const kRules[] = { "none", "whole", "sections" };
  std::printf("%s: %.4f s median of %d (rule %s)\n",
    argv[1],
    seconds[seconds.size() / 2],
    repeat,
    kRules[static_cast<int>(result.rule)]);
  for (std::size_t i = 0; i < result.ranges.size(); ++i)
  {
    std::printf("  x%zu [%g, %g]%s\n",
      i + 1,
      result.ranges[i].lo,
      result.ranges[i].hi,
      result.found[i] ? "" : " (given or fallback)");
  }
  if (!result.note.empty())
  {
    std::printf("  note: %s\n", result.note.c_str());
  }
  return 0;
}
