// The work one box costs the tiled sampler, the mesher and the ray caster, per instruction of
// the box's tape: interval evaluation with choices recorded, simplification, and both on the
// simplified tape of a sub-box (what a quadtree does next). The model is any file frepkit reads.
//
// Usage: frep_interval_benchmark MODEL [--box x0,y0[,z0..],x1,y1[,z1..]] [--boxes 2000]
//                                [--size 0.05]
// Boxes: --boxes random boxes of side --size (relative to the model box) inside the box.
#include "benchmark_cli.h"

#include "Eval/interval_evaluator.h"
#include "Eval/tape_simplifier.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using Clock = std::chrono::steady_clock;

double ns_since(Clock::time_point t)
{
  return std::chrono::duration<double, std::nano>(Clock::now() - t).count();
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << "usage: frep_interval_benchmark MODEL [--box ...] [--boxes N] [--size S]\n";
    return 1;
  }
  const std::string path = argv[1];
  std::vector<double> box;
  int boxes = 2000;
  double size = 0.05;
  for (int i = 2; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    const std::string value = argv[i + 1];
    if (option == "--box")
    {
      box = frep::bench::comma_numbers(value);
    }
    else if (option == "--boxes")
    {
      boxes = std::max(1, std::stoi(value));
    }
    else if (option == "--size")
    {
      size = std::stod(value);
    }
    else
    {
      std::cerr << "unknown option " << option << "\n";
      return 1;
    }
  }
  const auto model = frep::bench::compile_model_file(path);
  if (!model)
  {
    return 1;
  }
  const auto tape = model->tape();
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
  std::mt19937_64 rng(7);
  std::vector<std::vector<frep::Interval>> regions;
  for (int b = 0; b < boxes; ++b)
  {
    std::vector<frep::Interval> r(d);
    for (std::size_t k = 0; k < d; ++k)
    {
      const double w = (box[d + k] - box[k]) * size;
      const double lo = std::uniform_real_distribution<double>(box[k], box[d + k] - w)(rng);
      r[k] = { lo, lo + w };
    }
    regions.push_back(std::move(r));
  }

  frep::IntervalEvaluator interval(tape);
  frep::TapeSimplifier simplifier;
  std::vector<frep::Choice> choices(tape->code.size());
  double interval_ns = 0, simplify_ns = 0, inner_interval_ns = 0, inner_simplify_ns = 0;
  std::size_t simplified_length = 0, inner_length = 0, inner_instructions = 0;
  frep::IntervalEvaluator inner(tape);
  std::vector<frep::Choice> inner_choices;
  for (const auto& r : regions)
  {
    auto t = Clock::now();
    interval.evaluate(r, choices);
    interval_ns += ns_since(t);
    t = Clock::now();
    const auto simplified = simplifier.simplify(*tape, choices);
    simplify_ns += ns_since(t);
    const auto below = simplified ? simplified : tape;
    simplified_length += below->code.size();
    // A quarter of the box, from the simplified tape.
    std::vector<frep::Interval> q = r;
    for (auto& iv : q)
    {
      iv.hi = iv.lo + (iv.hi - iv.lo) / 2;
    }
    inner.rebind(below, simplified != nullptr);
    inner_choices.resize(below->code.size());
    t = Clock::now();
    inner.evaluate(q, inner_choices);
    inner_interval_ns += ns_since(t);
    t = Clock::now();
    const auto twice = simplifier.simplify(*below, inner_choices);
    inner_simplify_ns += ns_since(t);
    inner_instructions += below->code.size();
    inner_length += twice ? twice->code.size() : below->code.size();
  }
  // Freezing (IntervalFreeze): the sub-box of each box evaluated on the full tape with and
  // without what the box dominates; how much is skipped, the time, and how much looser it is.
  double frozen_ns = 0, unfrozen_ns = 0, width_ratio = 0;
  std::size_t skipped = 0, frozen_count = 0, widths = 0, unsound = 0, undecided = 0;
  frep::IntervalFreeze freeze, scratch;
  frep::IntervalEvaluator whole(tape);
  for (const auto& r : regions)
  {
    whole.evaluate(r, {}, nullptr, &freeze);
    if (!whole.make_freeze(nullptr, freeze))
    {
      break;
    }
    skipped += freeze.skipped;
    frozen_count += freeze.frozen;
    std::vector<frep::Interval> q = r;
    for (auto& iv : q)
    {
      iv.hi = iv.lo + (iv.hi - iv.lo) / 2;
    }
    auto t = Clock::now();
    const frep::IntervalResult plain = whole.evaluate(q);
    unfrozen_ns += ns_since(t);
    t = Clock::now();
    const frep::IntervalResult fast = whole.evaluate(q, {}, &freeze, &scratch);
    frozen_ns += ns_since(t);
    unsound += fast.value.lo > plain.value.lo || fast.value.hi < plain.value.hi ? 1 : 0;
    const bool decided = plain.value.lo >= 0 || plain.value.hi < 0;
    const bool still = fast.value.lo >= 0 || fast.value.hi < 0;
    undecided += decided && !still ? 1 : 0;
    const double w0 = plain.value.hi - plain.value.lo, w1 = fast.value.hi - fast.value.lo;
    if (std::isfinite(w0) && std::isfinite(w1) && w0 > 0)
    {
      width_ratio += w1 / w0;
      ++widths;
    }
  }
  std::printf("freeze: %.1f%% of the instructions skipped, %.1f frozen per box; sub-box interval "
              "%.0f -> %.0f ns; width x%.3f on average; %zu of %d decided sub-boxes no longer "
              "decided; %zu not enclosing the full evaluation (must be 0)\n",
    100.0 * double(skipped) / (double(boxes) * double(tape->code.size())),
    double(frozen_count) / boxes, unfrozen_ns / boxes, frozen_ns / boxes,
    widths ? width_ratio / double(widths) : 0.0, undecided, boxes, unsound);

  // What the tape is made of (the opcodes' mix decides the cost per instruction).
  std::map<std::string, int> mix;
  for (const frep::Instruction& ins : tape->code)
  {
    ++mix[frep::opcode_name(ins.op)];
  }
  std::vector<std::pair<int, std::string>> ranked;
  for (const auto& [name, count] : mix)
  {
    ranked.emplace_back(count, name);
  }
  std::sort(ranked.rbegin(), ranked.rend());
  std::printf("opcodes:");
  for (const auto& [count, name] : ranked)
  {
    std::printf(" %s %d", name.c_str(), count);
  }
  std::printf("\n");
  const double n = double(boxes) * double(tape->code.size());
  std::printf("%s: %zu instructions, %d boxes of relative side %g\n", path.c_str(),
    tape->code.size(), boxes, size);
  std::printf("| step | ns per box | ns per instruction | tape after (mean instructions) |\n"
              "|---|---:|---:|---:|\n");
  std::printf("| interval, full tape | %.0f | %.2f | |\n", interval_ns / boxes, interval_ns / n);
  std::printf("| simplify, full tape | %.0f | %.2f | %.1f |\n", simplify_ns / boxes, simplify_ns / n,
    double(simplified_length) / boxes);
  std::printf("| interval, sub-box | %.0f | %.2f | |\n", inner_interval_ns / boxes,
    inner_interval_ns / double(inner_instructions));
  std::printf("| simplify, sub-box | %.0f | %.2f | %.1f |\n", inner_simplify_ns / boxes,
    inner_simplify_ns / double(inner_instructions), double(inner_length) / boxes);
  return 0;
}
