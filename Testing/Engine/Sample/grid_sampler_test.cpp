// The engine's grid sampler and its one position formula and size limit: positions exact at the
// first sample and within rounding at the last, values bit for bit those of the point and
// gradient evaluators, the limit refused before anything is allocated, cancel, progress and the
// two failure policies; tile-by-tile simplification changes nothing but the work; sign-only
// sampling keeps every sample's side.
#include "Compiler/model.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Eval/thread_pool.h"
#include "Language/parser.h"
#include "Mesh/surface.h"
#include "Sample/grid.h"
#include "Sample/grid_sampler.h"

#include <gtest/gtest.h>

#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <optional>
#include <sstream>
#include <vector>

// The largest single allocation while `tracking` is set: the sampler must never ask for memory
// in proportion to the grid (only to its blocks). GCC takes the free() of the replaced delete for
// a mismatch with the (replaced) new, which is malloc: a false positive.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
namespace
{
std::atomic<bool> tracking{ false };
std::atomic<std::size_t> largest{ 0 };
} // namespace

void* operator new(std::size_t size)
{
  if (tracking.load(std::memory_order_relaxed))
  {
    std::size_t seen = largest.load(std::memory_order_relaxed);
    while (size > seen && !largest.compare_exchange_weak(seen, size))
    {
    }
  }
  if (void* p = std::malloc(size == 0 ? 1 : size))
  {
    return p;
  }
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace frep
{
namespace
{

std::shared_ptr<const Tape> compile(const std::string& text)
{
  const ParseResult parsed = parse_program(text, "<test>");
  EXPECT_TRUE(parsed.ok()) << (parsed.diagnostics.empty() ? "" : parsed.diagnostics[0].message);
  if (!parsed.ok())
  {
    return nullptr;
  }
  auto compiled = Model::compile(parsed.program, ast::select_object(*parsed.program, "my_model"));
  EXPECT_TRUE(compiled.model);
  return compiled.model->specialise(Specialisation{});
}

bool same_bits(double a, double b)
{
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

GridSpec cube(int dimension, double lo, double hi, std::int64_t n)
{
  GridSpec grid;
  for (int k = 0; k < dimension; ++k)
  {
    grid.axes.push_back({ lo, hi, n });
  }
  return grid;
}

// Everything a run produced, stored whole (the sink's job in a real caller).
struct Stored
{
  std::vector<double> values;
  std::vector<std::vector<double>> attributes;
  std::vector<double> gradients;
  std::vector<std::uint8_t> failed;
  std::vector<std::vector<double>> coordinates;
  std::size_t blocks = 0;
  SampleResult result;
};

Stored sample(std::shared_ptr<const Tape> tape, const GridSpec& grid, SampleOptions options = {})
{
  Stored s;
  const std::size_t n = grid_part_size(grid);
  const std::size_t d = grid.axes.size();
  s.values.assign(n, -1.0);
  s.failed.assign(n, 9);
  s.coordinates.assign(d, std::vector<double>(n));
  s.result = sample_grid(tape, grid, options,
    [&](const SampleBlock& b)
    {
      EXPECT_LE(b.first + b.count, n);
      s.attributes.resize(b.attributes.size(), std::vector<double>(n));
      for (std::size_t p = 0; p < b.count; ++p)
      {
        s.values[b.first + p] = b.values[p];
        s.failed[b.first + p] = b.failed[p];
        for (std::size_t k = 0; k < d; ++k)
        {
          s.coordinates[k][b.first + p] = b.coordinates[k][p];
        }
        for (std::size_t j = 0; j < b.attributes.size(); ++j)
        {
          s.attributes[j][b.first + p] = b.attributes[j][p];
        }
      }
      if (b.gradients)
      {
        s.gradients.resize(n * d);
        std::copy_n(b.gradients, b.count * d, s.gradients.begin() + b.first * d);
      }
      ++s.blocks;
    });
  return s;
}

// Index on every axis of sample `id` of the part (axis 0 fastest), as global indices.
std::vector<std::int64_t> indices(const GridSpec& grid, std::size_t id)
{
  std::vector<std::int64_t> ijk;
  for (const GridAxis& a : grid.axes)
  {
    const std::int64_t count = (a.end == 0 ? a.samples : a.end) - a.begin;
    ijk.push_back(a.begin + static_cast<std::int64_t>(id % static_cast<std::size_t>(count)));
    id /= static_cast<std::size_t>(count);
  }
  return ijk;
}

TEST(GridCoordinate, FirstSampleIsExactlyTheMinimum)
{
  for (const double lo : { -10.0, -6.0, -1.2, 0.0, 0.1, 3.0, -1e6 })
  {
    for (std::int64_t n = 1; n <= 1024; ++n)
    {
      EXPECT_TRUE(same_bits(grid_coordinate(lo, lo + 7.3, 0, n), lo)) << lo << " " << n;
    }
  }
}

TEST(GridCoordinate, LastSampleIsTheMaximumUpToTheStepsRounding)
{
  const double eps = std::numeric_limits<double>::epsilon();
  const double boxes[][2] = { { -10, 10 }, { -6, 6 }, { -7, 5 }, { -1, 1 }, { 0, 1 },
    { -1.2, 1.2 }, { -1e6, 1 }, { 0.1, 0.3 } };
  for (const auto& box : boxes)
  {
    const double lo = box[0];
    const double hi = box[1];
    for (std::int64_t n = 2; n <= 1024; ++n)
    {
      const double last = grid_coordinate(lo, hi, n - 1, n);
      EXPECT_LE(std::abs(last - hi), 2 * eps * (hi - lo) + eps * std::abs(hi)) << lo << " " << n;
    }
  }
  // Exactly at both ends whenever the step is: the usual grids over the default box.
  for (std::int64_t n = 2; n < 78; ++n)
  {
    EXPECT_EQ(grid_coordinate(-10.0, 10.0, n - 1, n), 10.0) << n;
  }
  for (const std::int64_t n : { 2, 3, 5, 9, 17, 33, 65, 129, 257, 4097 })
  {
    EXPECT_EQ(grid_coordinate(-1.0, 1.0, n - 1, n), 1.0) << n;
    EXPECT_EQ(grid_coordinate(-6.0, 6.0, n - 1, n), 6.0) << n;
  }
}

TEST(GridCoordinate, IsOriginPlusIndexTimesSpacing)
{
  // The geometry of an image given by origin and spacing (vtkImageData::GetPoint, .vti): every
  // sample, the last included, is lo + i * ((hi - lo) / (n - 1)), bit for bit.
  for (std::int64_t n = 1; n <= 300; ++n)
  {
    const double step = n > 1 ? (-3.0 - -7.7) / static_cast<double>(n - 1) : 1.0;
    EXPECT_TRUE(same_bits(grid_step(-7.7, -3.0, n), step));
    for (std::int64_t i = 0; i < n; ++i)
    {
      EXPECT_TRUE(same_bits(grid_coordinate(-7.7, -3.0, i, n), -7.7 + static_cast<double>(i) * step));
      EXPECT_TRUE(same_bits(grid_coordinate(-7.7, step, i), grid_coordinate(-7.7, -3.0, i, n)));
    }
  }
}

TEST(GridLimit, IsTheMeshersLimitToo)
{
  EXPECT_EQ(max_grid_samples, 4096.0 * 4096.0 * 4096.0);
  EXPECT_EQ(SampleOptions{}.max_samples, max_grid_samples);
  EXPECT_EQ(mesh::ExtractOptions{}.max_samples, max_grid_samples);
  const std::int64_t ok[] = { 4096, 4096, 4096 };
  EXPECT_EQ(check_grid_size(ok, max_grid_samples, "X"), "");
  const std::int64_t big[] = { 4097, 4096, 4096 };
  EXPECT_EQ(check_grid_size(big, max_grid_samples, "X"),
    "grid: 4097 x 4096 x 4096 = 6.87363e+10 samples is more than the limit of 6.87195e+10 (X)");
  // No overflow whatever the counts.
  const std::int64_t huge[] = { std::int64_t(1) << 62, std::int64_t(1) << 62 };
  EXPECT_NE(check_grid_size(huge, 1e300, "X"), "");
}

TEST(GridSampler, EqualsPointEvaluationBitForBitInEveryDimension)
{
  const char* models[] = {
    "my_model(x[1], a[1]) { my_model = sin(3 * x[1]) - 0.25 * x[1]; }",
    "my_model(x[2], a[1], s[1]) { s[1] = x[1] * x[2]; my_model = 9 - x[1]^2 - 4 * x[2]^2; }",
    "my_model(x[3], a[1], s[2]) { s[1] = x[1]; s[2] = cos(x[2] * x[3]);"
    " my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2 + 0.3 * sin(5 * x[1]); }",
    "my_model(x[4], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2 / 3; }",
  };
  const std::int64_t sizes[] = { 70001, 301, 41, 13 }; // more than one block in 1-D and 2-D
  for (int d = 1; d <= 4; ++d)
  {
    SCOPED_TRACE(d);
    auto tape = compile(models[d - 1]);
    ASSERT_TRUE(tape);
    GridSpec grid = cube(d, -3.1, 2.9, sizes[d - 1]);
    SampleOptions options;
    options.attribute_count = -1;
    options.threads = 2;
    const Stored s = sample(tape, grid, options);
    ASSERT_TRUE(s.result.ok()) << s.result.error;
    const std::size_t n = grid_part_size(grid);
    EXPECT_EQ(s.result.samples, n);
    EXPECT_EQ(s.result.failed, 0u);
    EXPECT_EQ(s.attributes.size(), tape->outputs.size() - 1);
    EXPECT_GE(s.blocks, d <= 2 ? 2u : 1u);
    PointEvaluator point(tape);
    std::vector<double> x(static_cast<std::size_t>(d));
    std::vector<double> outputs(tape->outputs.size());
    std::size_t wrong = 0;
    for (std::size_t id = 0; id < n; ++id)
    {
      const auto ijk = indices(grid, id);
      for (int k = 0; k < d; ++k)
      {
        x[k] = grid_coordinate(grid.axes[k].lo, grid.axes[k].hi, ijk[k], grid.axes[k].samples);
        wrong += same_bits(s.coordinates[k][id], x[k]) ? 0 : 1;
      }
      EXPECT_EQ(point.evaluate(x, outputs), 0);
      wrong += same_bits(s.values[id], outputs[0]) ? 0 : 1;
      for (std::size_t j = 0; j + 1 < outputs.size(); ++j)
      {
        wrong += same_bits(s.attributes[j][id], outputs[j + 1]) ? 0 : 1;
      }
    }
    EXPECT_EQ(wrong, 0u);
  }
}

/// Samples with and without per-tile simplification and expects every output bit for bit.
/// Returns the instructions run with and without.
std::pair<std::size_t, std::size_t> expect_simplification_changes_nothing(
  const std::shared_ptr<const Tape>& tape, const GridSpec& grid, SampleOptions options)
{
  options.simplify = true;
  options.jit = true;
  const Stored a = sample(tape, grid, options);
  options.simplify = false;
  options.jit = false; // the reference: the full tape on the interpreter
  const Stored b = sample(tape, grid, options);
  EXPECT_TRUE(a.result.ok() && b.result.ok()) << a.result.error << b.result.error;
  const auto bits = [](const std::vector<double>& v)
  {
    std::vector<std::uint64_t> out(v.size());
    std::transform(v.begin(), v.end(), out.begin(), [](double x) { return std::bit_cast<std::uint64_t>(x); });
    return out;
  };
  EXPECT_EQ(bits(a.values), bits(b.values));
  EXPECT_EQ(a.failed, b.failed);
  EXPECT_EQ(a.attributes.size(), b.attributes.size());
  for (std::size_t j = 0; j < a.attributes.size() && j < b.attributes.size(); ++j)
  {
    EXPECT_EQ(bits(a.attributes[j]), bits(b.attributes[j])) << "s[" << j + 1 << "]";
  }
  EXPECT_EQ(bits(a.gradients), bits(b.gradients));
  EXPECT_EQ(a.result.failed, b.result.failed);
  EXPECT_EQ(a.result.errors, b.result.errors);
  EXPECT_EQ(a.result.first_failed, b.result.first_failed);
  EXPECT_EQ(a.result.first_error, b.result.first_error);
  return { a.result.instructions, b.result.instructions };
}

TEST(GridSampler, TileSimplificationChangesNothingInEveryDimension)
{
  // Maxima of bumps (decided far from each), a conditional, a check failing in part of the box.
  const auto model = [](int d)
  {
    std::ostringstream m;
    m << "my_model(x[" << d << "], a[1], s[1]) { u = -50;";
    for (int i = 0; i < 12; ++i)
    {
      m << " r" << i << " = 0.04 - (x[1] - (" << (-3 + 0.5 * i) << "))^2";
      for (int k = 2; k <= d; ++k)
      {
        m << " - (x[" << k << "] - (" << ((i * (k + 1)) % 5 - 2) * 0.6 << "))^2";
      }
      m << "; u = max(u, r" << i << ");";
    }
    m << " if x[1] > 1.3 then w = min(u, 0.05); else w = u; endif;"
         " q = sqrt(x[" << d << "] + 2.5); s[1] = q * x[1]; my_model = min(w, q); }";
    return m.str();
  };
  const std::int64_t sizes[] = { 70001, 301, 81, 13 };
  for (int d = 1; d <= 4; ++d)
  {
    SCOPED_TRACE(d);
    auto tape = compile(model(d));
    ASSERT_TRUE(tape);
    GridSpec grid = cube(d, -3.1, 2.9, sizes[d - 1]);
    SampleOptions options;
    options.attribute_count = -1;
    options.threads = 2;
    const auto [with, without] = expect_simplification_changes_nothing(tape, grid, options);
    // Tiles of 32 x 32 samples are a tenth of the box's side in 2-D, more than a third at 81^3
    // and the whole x axis at 13^4: a quarter saved is certain in 1-D and 2-D, some in 3-D. If
    // simplification stopped, this fails.
    if (d <= 2)
    {
      EXPECT_LT(with * 4, without * 3) << "instructions: " << with << " vs " << without;
    }
    if (d == 3)
    {
      EXPECT_LT(with, without) << "instructions: " << with << " vs " << without;
    }
    EXPECT_LE(with, without);
    options.failures = FailurePolicy::Previous;
    options.threads = 1;
    options.gradients = d <= 2;
    expect_simplification_changes_nothing(tape, grid, options);
    // A part whose rows start and end inside the grid.
    GridSpec part = grid;
    part.axes[0].begin = 3;
    part.axes[0].end = sizes[d - 1] - 5;
    if (d >= 2)
    {
      part.axes[1].begin = 2;
    }
    expect_simplification_changes_nothing(tape, part, options);
  }
}

TEST(GridSampler, SignOnlyDecidesTilesAndKeepsEverySide)
{
  // A sphere of radius 1 in [-3, 3]^2: tiles far inside or outside are decided, the ones on the
  // circle evaluated. Decided samples hold a bound of F on F's side; the others hold F itself.
  auto tape = compile("my_model(x[2], a[1]) { my_model = 1 - x[1]^2 - x[2]^2; }");
  ASSERT_TRUE(tape);
  const GridSpec grid = cube(2, -3, 3, 512);
  std::vector<double> exact(grid_part_size(grid)), sign(exact.size());
  SampleOptions options;
  options.threads = 2;
  ASSERT_TRUE(sample_grid(tape, grid, options,
    [&](const SampleBlock& b) { std::copy_n(b.values, b.count, exact.data() + b.first); }).ok());
  for (const double iso : { 0.0, 0.75 })
  {
    SCOPED_TRACE(iso);
    options.sign_only = true;
    options.iso = iso;
    const SampleResult r = sample_grid(tape, grid, options,
      [&](const SampleBlock& b) { std::copy_n(b.values, b.count, sign.data() + b.first); });
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_GT(r.decided, exact.size() / 2);
    EXPECT_LT(r.decided, exact.size());
    std::size_t same = 0;
    for (std::size_t p = 0; p < exact.size(); ++p)
    {
      ASSERT_EQ(sign[p] >= iso, exact[p] >= iso) << p;
      // A bound: at or below F inside, at or above it outside.
      EXPECT_TRUE(exact[p] >= iso ? sign[p] <= exact[p] : sign[p] >= exact[p]) << p;
      same += std::bit_cast<std::uint64_t>(sign[p]) == std::bit_cast<std::uint64_t>(exact[p]);
    }
    EXPECT_GE(same, exact.size() - r.decided); // every evaluated sample is F bit for bit
  }
  // Attributes and gradients cannot come from a sign-only run.
  options.attribute_count = -1;
  EXPECT_NE(sample_grid(tape, grid, options, {}).error.find("sign_only"), std::string::npos);
  options.attribute_count = 0;
  options.gradients = true;
  EXPECT_NE(sample_grid(tape, grid, options, {}).error.find("sign_only"), std::string::npos);
}

TEST(GridSampler, APartHasTheValuesOfTheWhole)
{
  auto tape = compile("my_model(x[3], a[1]) { my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2; }");
  const GridSpec whole = cube(3, -6, 6, 47);
  const Stored all = sample(tape, whole);
  GridSpec part = whole;
  part.axes[0].begin = 5;
  part.axes[0].end = 47;
  part.axes[1].begin = 46;
  part.axes[2].begin = 10;
  part.axes[2].end = 20;
  SampleOptions one_thread;
  one_thread.threads = 1;
  const Stored piece = sample(tape, part, one_thread);
  ASSERT_TRUE(piece.result.ok()) << piece.result.error;
  ASSERT_EQ(piece.values.size(), 42u * 1u * 10u);
  EXPECT_EQ(piece.result.threads, 1);
  std::size_t wrong = 0;
  for (std::size_t id = 0; id < piece.values.size(); ++id)
  {
    const auto ijk = indices(part, id);
    const std::size_t whole_id = static_cast<std::size_t>(ijk[0] + 47 * (ijk[1] + 47 * ijk[2]));
    wrong += same_bits(piece.values[id], all.values[whole_id]) ? 0 : 1;
  }
  EXPECT_EQ(wrong, 0u);
}

TEST(GridSampler, GradientsAreTheGradientEvaluatorsBitForBit)
{
  auto tape = compile("my_model(x[3], a[1]) { my_model = 4 - x[1]^2 - 2 * x[2]^2 - sin(x[3]); }");
  const GridSpec grid = cube(3, -2, 2, 45); // 91125 samples: two blocks
  SampleOptions options;
  options.gradients = true;
  const Stored s = sample(tape, grid, options);
  ASSERT_TRUE(s.result.ok()) << s.result.error;
  ASSERT_EQ(s.gradients.size(), 3 * s.values.size());
  GradientEvaluator reference(tape);
  std::size_t wrong = 0;
  for (std::size_t id = 0; id < s.values.size(); ++id)
  {
    const double x[3] = { s.coordinates[0][id], s.coordinates[1][id], s.coordinates[2][id] };
    double g[3];
    const double f = reference.evaluate(x, g);
    wrong += same_bits(f, s.values[id]) ? 0 : 1;
    for (int k = 0; k < 3; ++k)
    {
      wrong += same_bits(g[k], s.gradients[3 * id + k]) ? 0 : 1;
    }
  }
  EXPECT_EQ(wrong, 0u);
}

TEST(GridSampler, SizeLimitIsRefusedBeforeAnythingIsAllocated)
{
  auto tape = compile("my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }");
  GridSpec grid = cube(3, -1, 1, 100000);
  bool called = false;
  largest = 0;
  tracking = true;
  const auto start = std::chrono::steady_clock::now();
  const SampleResult r =
    sample_grid(tape, grid, {}, [&](const SampleBlock&) { called = true; });
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  tracking = false;
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(called);
  EXPECT_EQ(r.samples, 0u);
  EXPECT_EQ(r.error,
    "grid: 100000 x 100000 x 100000 = 1e+15 samples is more than the limit of 6.87195e+10 "
    "(SampleOptions::max_samples); refused before allocating anything");
  EXPECT_LT(largest.load(), std::size_t(1) << 12);
  EXPECT_LT(seconds, 1.0);

  // A caller's own, lower limit: 11^3 = 1331.
  SampleOptions options;
  options.max_samples = 1330;
  grid = cube(3, -1, 1, 11);
  EXPECT_NE(check_grid(grid, 3, options).find("1331 samples is more than the limit of 1330"),
    std::string::npos);
  EXPECT_FALSE(sample_grid(tape, grid, options, {}).ok());
  options.max_samples = 1331;
  EXPECT_EQ(check_grid(grid, 3, options), "");
  EXPECT_TRUE(sample_grid(tape, grid, options, {}).ok());
}

TEST(GridSampler, TheLargestGridAllocatesOnlyBlocks)
{
  auto tape = compile("my_model(x[3], a[1], s[2]) { s[1] = x[1]; s[2] = x[2];"
                      " my_model = 1 - x[1]^2; }");
  const GridSpec grid = cube(3, -1, 1, 4096); // the limit exactly: accepted
  SampleOptions options;
  options.attribute_count = -1;
  options.gradients = true;
  options.threads = 2;
  int reports = 0;
  options.progress = [&](double) { return ++reports < 3; }; // two blocks, then cancel
  largest = 0;
  tracking = true;
  const SampleResult r = sample_grid(tape, grid, options, {});
  tracking = false;
  EXPECT_TRUE(r.cancelled);
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.samples, 2u << 16);
  EXPECT_LE(largest.load(), (std::size_t(1) << 16) * 3 * sizeof(double)); // one block's gradients
}

TEST(GridSampler, CancelStopsEarly)
{
  auto tape = compile("my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }");
  const GridSpec grid = cube(3, -1, 1, 100); // 10^6 samples: 16 blocks
  std::atomic<bool> cancel{ false };
  SampleOptions options;
  options.cancel = [&cancel] { return cancel.load(); };
  std::size_t blocks = 0;
  SampleResult r = sample_grid(tape, grid, options,
    [&](const SampleBlock&)
    {
      if (++blocks == 2)
      {
        cancel = true; // from the sink here; any thread may set it
      }
    });
  EXPECT_TRUE(r.cancelled);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(blocks, 2u);
  EXPECT_EQ(r.samples, 2u << 16);

  // Cancelled through the progress callback before the first block: nothing evaluated.
  cancel = false;
  options.progress = [](double) { return false; };
  blocks = 0;
  r = sample_grid(tape, grid, options, [&](const SampleBlock&) { ++blocks; });
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(blocks, 0u);
  EXPECT_EQ(r.samples, 0u);

  // A cancel request after the last block changes nothing: the work is complete.
  options.progress = [](double fraction) { return fraction < 1.0; };
  r = sample_grid(tape, grid, options, {});
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.samples, 1000000u);
}

TEST(GridSampler, ProgressRisesMonotonicallyToOne)
{
  auto tape = compile("my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }");
  SampleOptions options;
  std::vector<double> seen;
  options.progress = [&](double f)
  {
    seen.push_back(f);
    return true;
  };
  ASSERT_TRUE(sample_grid(tape, cube(3, -1, 1, 77), options, {}).ok());
  ASSERT_GE(seen.size(), 3u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  for (std::size_t i = 1; i < seen.size(); ++i)
  {
    EXPECT_LT(seen[i - 1], seen[i]);
  }
}

// sqrt of a negative number is a run-time error: x[1] < 0 fails. 300 x 300 samples: the rows
// cross a block boundary, so "previous" carries over from one block to the next.
constexpr const char* failing =
  "my_model(x[2], a[1], s[1]) { s[1] = x[2]; my_model = sqrt(x[1]) - x[2] * 0.5; }";

TEST(GridSampler, NaNPolicyMakesEveryOutputOfAFailedSampleNaN)
{
  auto tape = compile(failing);
  const GridSpec grid = cube(2, -1, 1, 300);
  SampleOptions options;
  options.attribute_count = -1;
  options.gradients = true;
  const Stored s = sample(tape, grid, options);
  ASSERT_TRUE(s.result.ok()) << s.result.error;
  PointEvaluator point(tape);
  std::size_t expected_failures = 0;
  std::size_t wrong = 0;
  for (std::size_t id = 0; id < s.values.size(); ++id)
  {
    const double x[2] = { s.coordinates[0][id], s.coordinates[1][id] };
    double out[2];
    const bool fails = point.evaluate(x, out) != 0;
    expected_failures += fails ? 1 : 0;
    wrong += (s.failed[id] != 0) != fails ? 1 : 0;
    if (fails)
    {
      wrong += std::isnan(s.values[id]) && std::isnan(s.attributes[0][id]) &&
          std::isnan(s.gradients[2 * id]) && std::isnan(s.gradients[2 * id + 1])
        ? 0
        : 1;
    }
    else
    {
      wrong += same_bits(s.values[id], out[0]) && same_bits(s.attributes[0][id], out[1]) ? 0 : 1;
    }
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(expected_failures, 150u * 300u);
  EXPECT_EQ(s.result.failed, expected_failures);
  EXPECT_EQ(s.result.errors, expected_failures);
  EXPECT_EQ(s.result.first_failed, 0);
  EXPECT_NE(s.result.first_error, 0u);
  ASSERT_EQ(s.result.first_failed_at.size(), 2u);
  EXPECT_EQ(s.result.first_failed_at[0], -1.0);
  EXPECT_EQ(s.result.first_failed_at[1], -1.0);
}

TEST(GridSampler, PreviousPolicyIsHfpsPreviousSample)
{
  auto tape = compile(failing);
  const GridSpec grid = cube(2, -1, 1, 300);
  SampleOptions options;
  options.attribute_count = -1;
  options.gradients = true;
  options.failures = FailurePolicy::Previous;
  const Stored s = sample(tape, grid, options);
  ASSERT_TRUE(s.result.ok()) << s.result.error;
  ASSERT_GE(s.blocks, 2u);
  // The reference: point by point in order, a failure takes the previous sample's outputs (0
  // at the first sample), as hfp reuses the interpreter's last value.
  PointEvaluator point(tape);
  GradientEvaluator gradient(tape);
  double previous[2] = { 0, 0 };
  double previous_gradient[2] = { 0, 0 };
  std::size_t wrong = 0;
  std::size_t failures = 0;
  for (std::size_t id = 0; id < s.values.size(); ++id)
  {
    const double x[2] = { s.coordinates[0][id], s.coordinates[1][id] };
    double out[2];
    double g[2];
    if (point.evaluate(x, out) == 0)
    {
      gradient.evaluate(x, g);
      std::copy_n(out, 2, previous);
      std::copy_n(g, 2, previous_gradient);
    }
    else
    {
      ++failures;
    }
    wrong += same_bits(s.values[id], previous[0]) && same_bits(s.attributes[0][id], previous[1]) &&
        same_bits(s.gradients[2 * id], previous_gradient[0]) &&
        same_bits(s.gradients[2 * id + 1], previous_gradient[1])
      ? 0
      : 1;
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(s.result.failed, failures);
  EXPECT_EQ(s.values[0], 0.0); // the first sample failed: 0
  // A row's failures take the last sample of the row before (x = 1).
  EXPECT_TRUE(same_bits(s.values[300], s.values[299]));
  EXPECT_GT(s.values[299], 0.0);
}

TEST(GridSampler, BadRequestsAreErrorsNotExceptions)
{
  auto tape = compile("my_model(x[2], a[1]) { my_model = 1 - x[1]^2 - x[2]^2; }");
  const auto error = [&](const GridSpec& grid, SampleOptions options = {})
  {
    const SampleResult r = sample_grid(tape, grid, options, {});
    EXPECT_EQ(r.samples, 0u);
    return r.error;
  };
  EXPECT_NE(error(cube(3, -1, 1, 4)).find("the grid has 3 axes; the object has 2 free"),
    std::string::npos);
  EXPECT_NE(error(GridSpec{}).find("the grid has 0 axes"), std::string::npos);
  EXPECT_NE(error(cube(2, -1, 1, 0)).find("at least 1"), std::string::npos);
  EXPECT_NE(error(cube(2, 1, 1, 4)).find("cannot place 4 samples in [1, 1]"), std::string::npos);
  EXPECT_NE(error(cube(2, 1, -1, 4)).find("cannot place"), std::string::npos);
  EXPECT_NE(error(cube(2, -1, std::numeric_limits<double>::infinity(), 4)).find("cannot place"),
    std::string::npos);
  GridSpec part = cube(2, -1, 1, 4);
  part.axes[1].begin = 4;
  EXPECT_NE(error(part).find("the part [4, 4)"), std::string::npos);
  SampleOptions negative;
  negative.attribute_count = -2;
  EXPECT_NE(error(cube(2, -1, 1, 4), negative), "");
  EXPECT_EQ(sample_grid(nullptr, cube(2, -1, 1, 4), {}, {}).error, "no model to sample");
  // A sink that throws: an error value, not an exception through the API.
  const SampleResult r = sample_grid(tape, cube(2, -1, 1, 4), {},
    [](const SampleBlock&) { throw std::runtime_error("disk full"); });
  EXPECT_EQ(r.error, "sampling failed: disk full");
  // A single sample per axis lies at lo (step 1), as vtkFRepSampler's one-sample axes.
  const Stored one = sample(tape, cube(2, 0.5, 0.5, 1));
  ASSERT_TRUE(one.result.ok()) << one.result.error;
  EXPECT_EQ(one.values, std::vector<double>{ 0.5 });
}

TEST(GridSampler, SharesACallersPool)
{
  auto tape = compile("my_model(x[2], a[1]) { my_model = 1 - x[1]^2 - x[2]^2; }");
  SampleOptions options;
  options.pool = std::make_shared<ThreadPool>(2);
  options.gradients = true;
  const Stored a = sample(tape, cube(2, -1, 1, 300), options);
  options.pool = std::make_shared<ThreadPool>(1);
  const Stored b = sample(tape, cube(2, -1, 1, 300), options);
  EXPECT_EQ(a.result.threads, 2);
  EXPECT_EQ(b.result.threads, 1);
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.gradients, b.gradients);
}

} // namespace
} // namespace frep
