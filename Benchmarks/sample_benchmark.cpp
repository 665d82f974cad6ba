// The grid sampler on one model, with and without per-tile tape simplification, and sign only (the
// sides of F = 0, as a sign image needs them): where the time of a sampled image or volume goes
// (parse + compile, specialise, sampling) and the instructions per sample. The model is any file frepkit reads (.hf or .vm: e.g. the Prospero Challenge's
// prospero.vm, which this program does not ship).
//
// Usage: frep_sample_benchmark MODEL [--box x0,y0[,z0],x1,y1[,z1]] [--grid N] [--repeat 5]
//                              [--threads 0] [--only simplified|full|sign] [--jit 1]
// Prints one Markdown row per mode: median wall milliseconds of sample_grid over the repeats.
#include "benchmark_cli.h"

#include "Sample/grid_sampler.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << "usage: frep_sample_benchmark MODEL [--box ...] [--grid N] [--repeat R] [--threads T]\n";
    return 1;
  }
  const std::string path = argv[1];
  std::vector<double> box;
  std::int64_t n = 1024;
  int repeat = 5;
  int threads = 0;
  bool jit = true; // --jit 0: the interpreter only (SampleOptions::jit)
  std::string only;
  for (int i = 2; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    const std::string value = argv[i + 1];
    if (option == "--box")
    {
      box = frep::bench::comma_numbers(value);
    }
    else if (option == "--grid")
    {
      n = std::stoll(value);
    }
    else if (option == "--repeat")
    {
      repeat = std::max(1, std::stoi(value));
    }
    else if (option == "--only")
    {
      only = value;
    }
    else if (option == "--threads")
    {
      threads = std::stoi(value);
    }
    else if (option == "--jit")
    {
      jit = std::stoi(value) != 0;
    }
    else
    {
      std::cerr << "unknown option " << option << "\n";
      return 1;
    }
  }
  auto start = Clock::now();
  const auto model = frep::bench::compile_model_file(path);
  if (!model)
  {
    return 1;
  }
  const double parse_ms = ms_since(start); // (reading the file included)
  start = Clock::now();
  const auto tape = model->tape();
  const double specialise_ms = ms_since(start);
  const std::size_t d = tape->input_count;
  if (box.size() != 2 * d)
  {
    box.assign(2 * d, 0.0);
    for (std::size_t k = 0; k < d; ++k)
    {
      box[k] = -1;
      box[d + k] = 1;
    }
  }
  frep::GridSpec grid;
  for (std::size_t k = 0; k < d; ++k)
  {
    grid.axes.push_back({ box[k], box[d + k], n });
  }
  std::printf("%s: %zu instructions, %zu inputs; parse + compile %.1f ms, specialise %.1f ms\n\n",
    path.c_str(), tape->code.size(), d, parse_ms, specialise_ms);
  std::printf("| mode | grid | sample_grid (ms, median of %d) | instructions per sample | "
              "decided by tiles | inside |\n|---|---|---:|---:|---:|---:|\n", repeat);
  for (const std::string mode : { "simplified", "full", "sign" })
  {
    if (!only.empty() && only != mode)
    {
      continue;
    }
    std::vector<double> times;
    frep::SampleResult last;
    std::size_t inside = 0;
    for (int r = 0; r < repeat; ++r)
    {
      frep::SampleOptions options;
      options.threads = threads;
      options.simplify = mode != "full";
      options.sign_only = mode == "sign";
      options.jit = jit;
      inside = 0;
      start = Clock::now();
      last = frep::sample_grid(tape, grid, options,
        [&](const frep::SampleBlock& b)
        {
          for (std::size_t p = 0; p < b.count; ++p)
          {
            inside += b.values[p] >= 0 ? 1 : 0;
          }
        });
      times.push_back(ms_since(start));
      if (!last.ok())
      {
        std::cerr << last.error << "\n";
        return 1;
      }
    }
    const char* name = mode == "full" ? "full tape"
      : mode == "sign"                 ? "sign only, simplified per tile"
                                       : "simplified per tile";
    std::printf("| %s | %lld^%zu | %.1f | %.1f | %.1f%% | %zu |\n", name,
      static_cast<long long>(n), d, median(times),
      double(last.instructions) / double(last.samples),
      100.0 * double(last.decided) / double(last.samples), inside);
  }
  return 0;
}
