// Cross-checks of the compiled evaluators on every model of the conformance suite and the
// external models (each with the a[] values its reference points use):
//  - BatchEvaluator (1 and 2 threads, SSE2 and the wide build) == PointEvaluator, bit for bit,
//    including NaN and the error id, on the reference points and on random points around them;
//  - IntervalEvaluator: on random boxes, every successfully evaluated sample lies inside the
//    enclosure (unless the enclosure is the whole line), and may_fail is set when a sample
//    failed;
//  - GradientEvaluator's F equals the point value;
//  - tapes simplified for a box (TapeSimplifier, recursively for a sub-box) give the full tape's
//    outputs and error ids bit for bit at every sampled point of the box;
//  - sign-only grid sampling (tiles decided by their enclosure are not evaluated) gives every
//    sample the full tape's failure and side of iso.
#include "conformance_case.h"

#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/detail/jit_kernel.h"
#include "Eval/point_evaluator.h"
#include "Eval/tape_simplifier.h"
#include "Language/parser.h"
#include "Sample/grid_sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <map>
#include <random>

namespace
{

namespace fc = frep::conformance;

bool same_bits(double a, double b)
{
  if (std::isnan(a) && std::isnan(b))
  {
    return true;
  }
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

std::vector<fc::ConformanceCase> all_cases()
{
  const std::filesystem::path shared = FREPKIT_SHARED_DIR;
  std::vector<fc::ConformanceCase> cases =
    fc::load_conformance_suite(shared / "hyperfun" / "conformance");
  std::vector<fc::ConformanceCase> models = fc::load_model_cases(shared / "hyperfun" / "models");
  cases.insert(cases.end(), models.begin(), models.end());
  return cases;
}

/// One tape to check: a case's program with one of its a[] vectors, and its reference points.
struct Subject
{
  std::string id;
  std::shared_ptr<const frep::Tape> tape;
  std::vector<std::vector<double>> points; // point-major
};

std::vector<Subject> subjects()
{
  std::vector<Subject> result;
  for (const fc::ConformanceCase& c : all_cases())
  {
    if (c.parse.outcome != fc::ParseOutcome::Ok || c.points.empty())
    {
      continue;
    }
    frep::ParseOptions options;
    options.accept_carriage_return = false;
    const frep::ParseResult parsed = frep::parse_program(c.source, c.program_path.string(), options);
    if (!parsed.ok() || parsed.program->objects.empty())
    {
      continue;
    }
    const int object =
      frep::ast::select_object(*parsed.program, c.object, frep::ast::NameMatch::Exact);
    const frep::Model::CompileResult compiled = frep::Model::compile(parsed.program, object);
    if (!compiled.model)
    {
      ADD_FAILURE() << c.id() << ": does not compile";
      continue;
    }
    std::map<std::vector<double>, Subject> by_parameters;
    for (const fc::CasePoint& p : c.points)
    {
      Subject& s = by_parameters[p.a];
      if (!s.tape)
      {
        s.id = c.id();
        s.tape = compiled.model->tape(p.a);
      }
      s.points.push_back(p.x);
    }
    for (auto& [a, s] : by_parameters)
    {
      result.push_back(std::move(s));
    }
  }
  return result;
}

const std::vector<Subject>& cached_subjects()
{
  static const std::vector<Subject> all = subjects();
  return all;
}

/// The reference points plus random points in their bounding box grown by 1 on each side.
std::vector<std::vector<double>> probe_points(const Subject& s, int random_count, std::mt19937_64& rng)
{
  std::vector<std::vector<double>> points = s.points;
  const std::size_t n = s.tape->input_count;
  std::vector<double> lo(n, -2), hi(n, 2);
  for (const auto& p : s.points)
  {
    for (std::size_t k = 0; k < n && k < p.size(); ++k)
    {
      if (std::isfinite(p[k]))
      {
        lo[k] = std::min(lo[k], p[k] - 1);
        hi[k] = std::max(hi[k], p[k] + 1);
      }
    }
  }
  for (int i = 0; i < random_count; ++i)
  {
    std::vector<double> p(n);
    for (std::size_t k = 0; k < n; ++k)
    {
      p[k] = std::uniform_real_distribution<double>(lo[k], hi[k])(rng);
    }
    points.push_back(std::move(p));
  }
  return points;
}

TEST(Consistency, EveryModelHasSubjects)
{
  EXPECT_GT(cached_subjects().size(), 200u);
}

TEST(Consistency, BatchEqualsPointBitForBit)
{
  std::mt19937_64 rng(7);
  std::size_t compared = 0;
  std::size_t compiled_subjects = 0;
  for (const Subject& s : cached_subjects())
  {
    const std::vector<std::vector<double>> points = probe_points(s, 300, rng);
    const std::size_t n = s.tape->input_count;
    const std::size_t outputs = s.tape->outputs.size();
    std::vector<std::vector<double>> columns(n, std::vector<double>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      for (std::size_t k = 0; k < n; ++k)
      {
        columns[k][i] = k < points[i].size() ? points[i][k] : 0.0;
      }
    }
    std::vector<const double*> inputs;
    for (const auto& c : columns)
    {
      inputs.push_back(c.data());
    }
    frep::PointEvaluator point(s.tape);
    std::vector<double> expected_value(points.size());
    std::vector<std::uint32_t> expected_error(points.size());
    std::vector<double> out(outputs);
    std::vector<double> x(n);
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      for (std::size_t k = 0; k < n; ++k)
      {
        x[k] = columns[k][i];
      }
      expected_error[i] = static_cast<std::uint32_t>(point.evaluate(x, out));
      expected_value[i] = outputs ? out[0] : std::nan("");
    }
    for (const int threads : { 1, 2 })
    {
      // the interpreter at each SIMD level, then the compiled kernel (where the tape has one)
      for (const auto& [simd, jit] : { std::pair{ frep::SimdLevel::Baseline, false },
             std::pair{ frep::SimdLevel::AVX2, false }, std::pair{ frep::SimdLevel::AVX512, false },
             std::pair{ frep::SimdLevel::Best, true } })
      {
        frep::BatchOptions options;
        options.threads = threads;
        options.simd = simd;
        options.jit = jit;
        options.block_size = 61; // not a multiple of the kernel's 8 lanes: partial chunks too
        frep::BatchEvaluator batch(s.tape, options);
        ASSERT_EQ(batch.compiled(), jit && frep::eval::jit_available() &&
            frep::eval::jit_supports(*s.tape) && frep::eval::jit_pays(*s.tape))
          << s.id;
        compiled_subjects += batch.compiled() && threads == 1 ? 1 : 0;
        std::vector<double> values(points.size());
        std::vector<std::uint32_t> errors(points.size());
        batch.evaluate(inputs, points.size(), values.data(), errors.data());
        for (std::size_t i = 0; i < points.size(); ++i)
        {
          ASSERT_TRUE(same_bits(values[i], expected_value[i]))
            << s.id << " point " << i << " threads " << threads << " simd " << static_cast<int>(simd)
            << " jit " << jit << ": batch "
            << values[i] << " point " << expected_value[i];
          ASSERT_EQ(errors[i], expected_error[i]) << s.id << " point " << i;
        }
        compared += points.size();
      }
    }
  }
  std::printf("[consistency] %zu batch values compared with the point evaluator; %zu of %zu tapes "
              "compiled to machine code\n",
    compared, compiled_subjects, cached_subjects().size());
  if (frep::eval::jit_available())
  {
    EXPECT_GT(compiled_subjects, cached_subjects().size() / 3); // the kernel is really exercised
  }
}

TEST(Consistency, IntervalsEncloseSampledValues)
{
  std::mt19937_64 rng(11);
  std::size_t samples = 0, boxes = 0, decided = 0;
  for (const Subject& s : cached_subjects())
  {
    const std::size_t n = s.tape->input_count;
    frep::IntervalEvaluator interval(s.tape);
    frep::PointEvaluator point(s.tape);
    const std::vector<std::vector<double>> centres = probe_points(s, 10, rng);
    std::vector<double> x(n), out(s.tape->outputs.size());
    for (const auto& centre : centres)
    {
      for (const double size : { 1e-3, 0.1, 1.0, 5.0 })
      {
        std::vector<frep::Interval> box(n);
        for (std::size_t k = 0; k < n; ++k)
        {
          const double c = k < centre.size() ? centre[k] : 0.0;
          const double r = std::uniform_real_distribution<double>(0, size)(rng);
          box[k] = { c - r, c + r };
        }
        const frep::IntervalResult result = interval.evaluate(box);
        ++boxes;
        const bool whole = std::isinf(result.value.lo) && std::isinf(result.value.hi);
        decided += (result.value.lo > 0 || result.value.hi < 0) ? 1 : 0;
        for (int i = 0; i < 40; ++i)
        {
          for (std::size_t k = 0; k < n; ++k)
          {
            // corners are where monotone rules are tight: sample them too
            const double t = i < 2 ? i : std::uniform_real_distribution<double>(0, 1)(rng);
            // clamped: lo + t*(hi-lo) may round past hi
            x[k] = std::clamp(box[k].lo + t * (box[k].hi - box[k].lo), box[k].lo, box[k].hi);
          }
          const int error = point.evaluate(x, out);
          ++samples;
          if (error != 0)
          {
            EXPECT_TRUE(result.may_fail) << s.id << ": a point in the box failed";
            continue;
          }
          if (whole || std::isnan(out[0]))
          {
            continue;
          }
          ASSERT_TRUE(result.value.contains(out[0]))
            << s.id << ": value " << out[0] << " outside [" << result.value.lo << ", "
            << result.value.hi << "]";
        }
      }
    }
  }
  std::printf("[consistency] %zu samples in %zu boxes inside their enclosures; %zu boxes decided\n",
    samples, boxes, decided);
}

TEST(Consistency, GradientValueEqualsPointValue)
{
  std::mt19937_64 rng(13);
  for (const Subject& s : cached_subjects())
  {
    frep::GradientEvaluator gradient(s.tape);
    frep::PointEvaluator point(s.tape);
    std::vector<double> g(s.tape->input_count);
    for (const auto& p : probe_points(s, 20, rng))
    {
      std::vector<double> x(s.tape->input_count, 0.0);
      std::copy_n(p.begin(), std::min(p.size(), x.size()), x.begin());
      const double expected = point.value(x);
      const double value = gradient.evaluate(x, g);
      ASSERT_TRUE(same_bits(value, expected)) << s.id << ": gradient evaluator's F " << value
                                              << " != point " << expected;
    }
  }
}

/// A random box around `centre` with half-widths up to `size`.
std::vector<frep::Interval> random_box(const std::vector<double>& centre, std::size_t n, double size,
  std::mt19937_64& rng)
{
  std::vector<frep::Interval> box(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const double c = k < centre.size() ? centre[k] : 0.0;
    const double r = std::uniform_real_distribution<double>(0, size)(rng);
    box[k] = { c - r, c + r };
  }
  return box;
}

/// A point of the box: corners for i < 2, else uniform (clamped: lo + t*(hi-lo) may round past).
std::vector<double> point_in(const std::vector<frep::Interval>& box, int i, std::mt19937_64& rng)
{
  std::vector<double> x(box.size());
  for (std::size_t k = 0; k < box.size(); ++k)
  {
    const double t = i < 2 ? i : std::uniform_real_distribution<double>(0, 1)(rng);
    x[k] = std::clamp(box[k].lo + t * (box[k].hi - box[k].lo), box[k].lo, box[k].hi);
  }
  return x;
}

/// Every output and the error id of `simplified` equal `full`'s at x, bit for bit.
void expect_same_outputs(frep::PointEvaluator& full, frep::PointEvaluator& simplified,
  const std::vector<double>& x, const std::string& id)
{
  std::vector<double> expected(full.tape().outputs.size()), got(simplified.tape().outputs.size());
  ASSERT_EQ(expected.size(), got.size()) << id;
  const int expected_error = full.evaluate(x, expected);
  const int error = simplified.evaluate(x, got);
  ASSERT_EQ(error, expected_error) << id << ": error ids differ";
  for (std::size_t o = 0; o < expected.size(); ++o)
  {
    ASSERT_TRUE(same_bits(got[o], expected[o]))
      << id << ": output " << o << " simplified " << got[o] << " full " << expected[o];
  }
}

TEST(Consistency, SimplifiedTapesEqualFullTapesBitForBit)
{
  std::mt19937_64 rng(17);
  frep::TapeSimplifier simplifier;
  std::size_t boxes = 0, simplified_boxes = 0, samples = 0;
  std::size_t full_length = 0, simplified_length = 0;
  for (const Subject& s : cached_subjects())
  {
    const std::size_t n = s.tape->input_count;
    frep::IntervalEvaluator interval(s.tape);
    frep::PointEvaluator full(s.tape);
    std::vector<frep::Choice> choices(s.tape->code.size());
    for (const auto& centre : probe_points(s, 10, rng))
    {
      for (const double size : { 1e-3, 0.1, 1.0, 5.0 })
      {
        const std::vector<frep::Interval> box = random_box(centre, n, size, rng);
        interval.evaluate(box, choices);
        ++boxes;
        const std::shared_ptr<const frep::Tape> tape = simplifier.simplify(*s.tape, choices);
        if (!tape)
        {
          continue;
        }
        ++simplified_boxes;
        full_length += s.tape->code.size();
        simplified_length += tape->code.size();
        frep::PointEvaluator simplified(tape);
        for (int i = 0; i < 30; ++i)
        {
          expect_same_outputs(full, simplified, point_in(box, i, rng), s.id);
          ++samples;
        }
        // Again inside a quarter of the box, from the simplified tape (as the mesher recurses).
        std::vector<frep::Interval> inner(n);
        for (std::size_t k = 0; k < n; ++k)
        {
          const double w = (box[k].hi - box[k].lo) / 4;
          inner[k] = { box[k].lo + w, std::min(box[k].hi, box[k].lo + 2 * w) };
        }
        frep::IntervalEvaluator inner_interval(tape);
        std::vector<frep::Choice> inner_choices(tape->code.size());
        inner_interval.evaluate(inner, inner_choices);
        const std::shared_ptr<const frep::Tape> twice = simplifier.simplify(*tape, inner_choices);
        if (!twice)
        {
          continue;
        }
        frep::PointEvaluator simplified_twice(twice);
        for (int i = 0; i < 10; ++i)
        {
          expect_same_outputs(full, simplified_twice, point_in(inner, i, rng), s.id + " (twice)");
          ++samples;
        }
      }
    }
  }
  std::printf("[consistency] %zu of %zu boxes simplified (%zu -> %zu instructions); %zu samples "
              "equal the full tapes'\n",
    simplified_boxes, boxes, full_length, simplified_length, samples);
  // The suite has min/max and conditionals: simplification must happen, or this test tests nothing.
  EXPECT_GT(simplified_boxes, boxes / 20);
  EXPECT_LT(simplified_length, full_length);
}

/// Per sample of `grid`: 0 outside (F < iso), 1 inside, 2 failed, from sample_grid.
std::vector<std::uint8_t> sides(const std::shared_ptr<const frep::Tape>& tape,
  const frep::GridSpec& grid, frep::SampleOptions options, std::size_t& decided)
{
  std::vector<std::uint8_t> out(frep::grid_part_size(grid));
  const frep::SampleResult r = frep::sample_grid(tape, grid, options,
    [&](const frep::SampleBlock& b)
    {
      for (std::size_t p = 0; p < b.count; ++p)
      {
        out[b.first + p] = b.failed[p] ? 2 : (b.values[p] >= options.iso ? 1 : 0);
      }
    });
  EXPECT_TRUE(r.ok()) << r.error;
  decided += r.decided;
  return out;
}

TEST(Consistency, SignOnlySamplingGivesEverySampleTheFullTapesSide)
{
  std::size_t subjects = 0, samples = 0, decided = 0, not_decided = 0;
  for (const Subject& s : cached_subjects())
  {
    const std::size_t n = s.tape->input_count;
    if (n == 0 || s.points.empty())
    {
      continue;
    }
    // The grid over the reference points' bounding box, widened so that tiles lie wholly
    // outside too; fewer samples per axis in more dimensions.
    const std::int64_t per_axis = n == 1 ? 4096 : n == 2 ? 96 : n == 3 ? 24 : 8;
    frep::GridSpec grid;
    for (std::size_t k = 0; k < n; ++k)
    {
      double lo = s.points[0][k], hi = lo;
      for (const auto& p : s.points)
      {
        lo = std::min(lo, p[k]);
        hi = std::max(hi, p[k]);
      }
      const double pad = std::max(1.0, 0.25 * (hi - lo));
      grid.axes.push_back({ lo - pad, hi + pad, per_axis });
    }
    for (const double iso : { 0.0, 0.5 })
    {
      frep::SampleOptions full;
      full.simplify = false;
      full.threads = 1;
      full.iso = iso;
      frep::SampleOptions sign = full;
      sign.sign_only = true;
      sign.threads = 2;
      std::size_t ignored = 0;
      const std::vector<std::uint8_t> expected = sides(s.tape, grid, full, ignored);
      const std::size_t before = decided;
      const std::vector<std::uint8_t> got = sides(s.tape, grid, sign, decided);
      ASSERT_EQ(got.size(), expected.size());
      for (std::size_t p = 0; p < got.size(); ++p)
      {
        ASSERT_EQ(int(got[p]), int(expected[p])) << s.id << " iso " << iso << ": sample " << p;
      }
      samples += got.size();
      not_decided += decided == before ? 1 : 0;
    }
    ++subjects;
  }
  std::printf("[consistency] sign-only sampling: %zu subjects, %zu samples, %zu decided by "
              "tiles, each with the full tape's side\n", subjects, samples, decided);
  // Most grids have tiles wholly inside or outside: deciding must happen, or this tests nothing.
  EXPECT_GT(subjects, 200u);
  EXPECT_GT(decided, samples / 4);
}

} // namespace
