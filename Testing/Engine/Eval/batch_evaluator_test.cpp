#include "Eval/batch_evaluator.h"
#include "Eval/detail/jit_kernel.h"
#include "Eval/point_evaluator.h"
#include "Eval/thread_pool.h"

#include "eval_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace frep::test
{
namespace
{

/// Random structure-of-arrays points, including every special value in every operand.
struct Points
{
  std::size_t count;
  std::vector<std::vector<double>> columns;
  std::vector<const double*> pointers;

  Points(std::size_t inputs, std::size_t n, std::uint64_t seed)
    : count(n)
    , columns(inputs, std::vector<double>(n))
  {
    std::mt19937_64 rng(seed);
    const auto& s = special_values();
    for (std::size_t i = 0; i < n; ++i)
    {
      for (std::size_t k = 0; k < inputs; ++k)
      {
        // The first points walk through all pairs of special values.
        const std::size_t pair = i / (k == 0 ? 1 : s.size());
        columns[k][i] = i < s.size() * s.size() ? s[pair % s.size()] : random_value(rng);
      }
    }
    for (auto& c : columns)
    {
      pointers.push_back(c.data());
    }
  }
  std::vector<double> point(std::size_t i) const
  {
    std::vector<double> p;
    for (const auto& c : columns)
    {
      p.push_back(c[i]);
    }
    return p;
  }
};

/// Batch against point on every point: values, errors, attributes, failure count.
void expect_batch_equals_point(const std::shared_ptr<const Tape>& tape,
  const Points& pts,
  const BatchOptions& options,
  const std::string& what)
{
  BatchEvaluator batch(tape, options);
  PointEvaluator point(tape);
  const std::size_t attrs = tape->outputs.size() - 1;
  std::vector<double> values(pts.count, 12345.0);
  std::vector<std::uint32_t> errors(pts.count, 77);
  std::vector<std::vector<double>> attr(attrs, std::vector<double>(pts.count));
  std::vector<double*> attr_ptr;
  for (auto& a : attr)
  {
    attr_ptr.push_back(a.data());
  }
  const std::size_t failures =
    batch.evaluate(pts.pointers, pts.count, values.data(), errors.data(), attr_ptr);
  std::size_t expected_failures = 0;
  std::vector<double> out(tape->outputs.size());
  for (std::size_t i = 0; i < pts.count; ++i)
  {
    const auto p = pts.point(i);
    const int error = point.evaluate(p, out);
    expected_failures += error != 0;
    ASSERT_EQ(errors[i], static_cast<std::uint32_t>(error)) << what << " point " << i;
    ASSERT_TRUE(same_bits(values[i], out[0]))
      << what << " point " << i << " (" << p[0] << ", " << p[1] << ", " << p[2] << "): batch "
      << values[i] << " point " << out[0];
    for (std::size_t j = 0; j < attrs; ++j)
    {
      ASSERT_TRUE(same_bits(attr[j][i], out[j + 1])) << what << " attribute " << j;
    }
  }
  EXPECT_EQ(failures, expected_failures) << what;
}

std::vector<BatchOptions> option_sets()
{
  std::vector<BatchOptions> sets;
  for (int threads : { 1, 2 })
  {
    for (SimdLevel simd : { SimdLevel::Baseline, SimdLevel::AVX2, SimdLevel::AVX512 })
    {
      BatchOptions o;
      o.threads = threads;
      o.simd = simd;
      o.jit = false;
      sets.push_back(o);
    }
    BatchOptions compiled; // the machine-code kernel where the CPU and the tape allow it
    compiled.threads = threads;
    sets.push_back(compiled);
  }
  BatchOptions odd;
  odd.threads = 2;
  odd.block_size = 7; // blocks that are not a multiple of any vector width
  sets.push_back(odd);
  return sets;
}

std::string describe(const BatchOptions& o)
{
  return "threads=" + std::to_string(o.threads) + " block=" + std::to_string(o.block_size) +
         " simd=" + std::to_string(static_cast<int>(o.simd)) + " jit=" + std::to_string(o.jit);
}

TEST(BatchEvaluator, EveryOpcodeEqualsPointBitForBit)
{
  const Points pts(3, 3001, 11); // odd count: the last block is partial
  for (const OpInfo& info : value_ops())
  {
    for (const BatchOptions& o : option_sets())
    {
      expect_batch_equals_point(single_op_tape(info.op), pts, o, info.name + (" " + describe(o)));
    }
  }
}

TEST(BatchEvaluator, HfPowIntUnrolledAndGenericExponents)
{
  const Points pts(3, 1001, 12);
  for (int n = -20; n <= 20; ++n)
  {
    for (const BatchOptions& o : option_sets())
    {
      expect_batch_equals_point(
        single_op_tape(Opcode::HfPowInt, n), pts, o, "HfPowInt " + std::to_string(n));
    }
  }
}

// Output slot reused as an operand slot, as a register allocator would do.
TEST(BatchEvaluator, InPlaceInstructions)
{
  TapeBuilder b(3);
  const auto x = b.input(0);
  const auto y = b.input(1);
  b.input(2);
  b.tape.code.push_back({ Opcode::Union, x, x, y, 0, 0, 0 });
  b.tape.code.push_back({ Opcode::HfPowInt, y, y, 0, 0, 3, 0 });
  b.tape.code.push_back({ Opcode::Select, x, y, x, y, 0, 0 });
  b.tape.code.push_back({ Opcode::Mul, x, x, x, 0, 0, 0 });
  const Points pts(3, 999, 13);
  for (const BatchOptions& o : option_sets())
  {
    expect_batch_equals_point(b.finish({ x, y }), pts, o, "in place " + describe(o));
  }
}

// A model with errors, attributes and an opaque call.
std::shared_ptr<const Tape> model_tape(std::shared_ptr<const OpaqueFunction> fn)
{
  TapeBuilder b(3);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const auto z = b.input(2);
  const auto zero = b.constant(0);
  b.error_if(b.op(Opcode::Lt, z, zero)); // id 1
  const auto r2 = b.op(Opcode::Add, b.op(Opcode::Square, x), b.op(Opcode::HfPowInt, y, 0, 0, 2));
  const auto sphere = b.op(Opcode::Sub, b.constant(4), r2);
  b.error_if(b.op(Opcode::Gt, r2, b.constant(100))); // id 2
  const std::uint32_t o0 = b.tape.slot_count++;
  const std::uint32_t o1 = b.tape.slot_count++;
  b.tape.calls.push_back({ std::move(fn), { x, y }, { o0, o1 } }); // error 1 when x > 5
  b.tape.code.push_back({ Opcode::Call, 0, 0, 0, 0, 0, 0 });
  const auto f = b.op(Opcode::Union, sphere, b.op(Opcode::Mul, o1, z));
  const auto s1 = b.op(Opcode::Sqrt, b.op(Opcode::Abs, o0));
  return b.finish({ f, s1, r2 });
}

TEST(BatchEvaluator, ErrorsAttributesAndCallsEqualPoint)
{
  auto fn = std::make_shared<TestFunction>();
  const auto tape = model_tape(fn);
  const Points pts(3, 5003, 14);
  for (const BatchOptions& o : option_sets())
  {
    expect_batch_equals_point(tape, pts, o, "model " + describe(o));
  }
}

// The compiled kernel: more live values than registers (a stack frame), errors, a select, a
// slot read before it is written, and outputs that are inputs, against the point evaluator.
TEST(BatchEvaluator, CompiledKernelSpillsErrorsAndUnwrittenSlots)
{
  TapeBuilder b(3);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const auto z = b.input(2);
  std::vector<std::uint32_t> live;
  for (int i = 0; i < 90; ++i) // 90 values live at once: most of them in the frame
  {
    const auto t = b.op(i % 3 == 0 ? Opcode::Union : (i % 3 == 1 ? Opcode::Max : Opcode::Intersect),
      b.op(Opcode::Mul, x, b.constant(0.25 * i - 7)), i % 2 ? y : z);
    live.push_back(t);
  }
  const auto unwritten = b.tape.slot_count++; // read before anything writes it: 0
  auto sum = b.op(Opcode::Add, live[0], unwritten);
  for (std::size_t i = 1; i < live.size(); ++i)
  {
    sum = b.op(i % 2 ? Opcode::Sub : Opcode::Add, sum, live[i]);
  }
  b.error_if(b.op(Opcode::Gt, sum, b.constant(1e3)));
  const auto chosen = b.op(Opcode::Select, b.op(Opcode::Lt, x, y), sum, b.op(Opcode::Neg, sum));
  b.error_if(b.op(Opcode::Ne, chosen, chosen)); // NaN-ness is not an error here: |NaN - NaN| < eps is false
  const auto tape = b.finish({ chosen, x, live[40] });
  BatchOptions options;
  options.threads = 1;
  EXPECT_EQ(BatchEvaluator(tape, options).compiled(), eval::jit_available());
  const auto kernel = eval::JitKernel::compile(*tape);
  if (kernel)
  {
    EXPECT_GT(kernel->spilled_slots(), 70u);
  }
  const Points pts(3, 4099, 21);
  for (const BatchOptions& o : option_sets())
  {
    expect_batch_equals_point(tape, pts, o, "spills " + describe(o));
  }
}

// Every instruction but opaque calls compiles (libm and the HyperFun rules through a call out
// per chunk); a tape with a Call, or a SIMD level below AVX2, runs on the interpreter.
TEST(BatchEvaluator, CompiledKernelForEveryInstructionButCalls)
{
  for (const OpInfo& info : value_ops())
  {
    EXPECT_TRUE(eval::jit_supports(*single_op_tape(info.op))) << info.name;
  }
  EXPECT_TRUE(eval::jit_supports(*single_op_tape(Opcode::HfPowInt, -16)));
  EXPECT_TRUE(eval::jit_supports(*single_op_tape(Opcode::HfPowInt, 17)));
  EXPECT_FALSE(eval::jit_supports(*model_tape(std::make_shared<TestFunction>()))); // a Call
  BatchOptions options;
  options.threads = 1;
  EXPECT_EQ(BatchEvaluator(single_op_tape(Opcode::Add), options).compiled(), eval::jit_available());
  EXPECT_FALSE(BatchEvaluator(single_op_tape(Opcode::Exp), options).compiled()); // all libm: no pay
  EXPECT_FALSE(BatchEvaluator(model_tape(std::make_shared<TestFunction>()), options).compiled());
  options.simd = SimdLevel::Baseline;
  EXPECT_FALSE(BatchEvaluator(single_op_tape(Opcode::Add), options).compiled());
  options.simd = SimdLevel::Best;
  options.jit = false;
  EXPECT_FALSE(BatchEvaluator(single_op_tape(Opcode::Add), options).compiled());
}

// Every opcode through the kernel itself (BatchEvaluator leaves libm-only tapes to the
// interpreter): the calls out, on every pair of special values, with a partial last pass.
TEST(BatchEvaluator, CompiledKernelRunsEveryOpcodeLikeThePointEvaluator)
{
  if (!eval::jit_available())
  {
    GTEST_SKIP() << "no AVX2: the kernel cannot run here";
  }
  const Points pts(3, 3001, 31);
  for (const OpInfo& info : value_ops())
  {
    const auto tape = single_op_tape(info.op);
    const auto kernel = eval::JitKernel::compile(*tape);
    ASSERT_TRUE(kernel) << info.name;
    std::vector<double> values(pts.count);
    double* outputs[] = { values.data() };
    kernel->run(pts.pointers.data(), outputs, nullptr, pts.count);
    PointEvaluator point(tape);
    std::vector<double> out(1);
    for (std::size_t i = 0; i < pts.count; ++i)
    {
      point.evaluate(pts.point(i), out);
      ASSERT_TRUE(same_bits(values[i], out[0])) << info.name << " point " << i;
    }
  }
}

// A latency-bound tape (a chain of R-unions) runs two chunks per pass; calls out between them must
// keep both chunks' values, the result of the first chunk's copy included.
TEST(BatchEvaluator, CompiledKernelCallsOutInTwoChunkPasses)
{
  TapeBuilder b(3);
  const auto x = b.input(0);
  const auto y = b.input(1);
  const auto z = b.input(2);
  auto u = b.op(Opcode::Tanh, x);
  const auto side = b.op(Opcode::HfPowInt, y, 0, 0, 24); // a call out, read at the end
  for (int i = 0; i < 30; ++i)
  {
    u = b.op(i % 2 ? Opcode::Union : Opcode::Intersect, u, i % 3 ? z : y);
  }
  u = b.op(Opcode::Atan, u); // a call out in the chain
  const auto tape = b.finish({ b.op(Opcode::Add, u, side) });
  // Skip only for the CPU; a null kernel on an AVX2 machine (a frame too large, code memory
  // refused) is the failure this test exists to catch.
  if (!eval::jit_available())
  {
    GTEST_SKIP() << "no AVX2: the kernel cannot run here";
  }
  const auto kernel = eval::JitKernel::compile(*tape);
  ASSERT_TRUE(kernel) << "JitKernel::compile returned null on a machine with AVX2";
  EXPECT_EQ(kernel->lanes(), 8u);
  EXPECT_TRUE(eval::jit_pays(*tape));
  const Points pts(3, 1003, 41);
  for (const BatchOptions& o : option_sets())
  {
    expect_batch_equals_point(tape, pts, o, "two chunks " + describe(o));
  }
}

TEST(BatchEvaluator, ScratchIsPerThreadNotPerPoint)
{
  auto fn = std::make_shared<TestFunction>();
  BatchOptions o;
  o.threads = 2;
  BatchEvaluator batch(model_tape(fn), o);
  const Points pts(3, 4000, 15);
  std::vector<double> v(pts.count);
  batch.evaluate(pts.pointers, pts.count, v.data());
  batch.evaluate(pts.pointers, pts.count, v.data());
  EXPECT_GE(fn->scratches.load(), 1);
  EXPECT_LE(fn->scratches.load(), 2);
}

TEST(BatchEvaluator, FailureCountAndNaN)
{
  TapeBuilder b(1);
  const auto x = b.input(0);
  b.error_if(b.op(Opcode::Lt, x, b.constant(0)));
  const auto f = b.op(Opcode::Sqrt, x);
  BatchOptions o;
  o.threads = 2;
  o.block_size = 16;
  BatchEvaluator batch(b.finish({ f }), o);
  std::vector<double> in(1001);
  for (std::size_t i = 0; i < in.size(); ++i)
  {
    in[i] = (i % 3 == 0) ? -1.0 : static_cast<double>(i);
  }
  const double* cols[1] = { in.data() };
  std::vector<double> v(in.size());
  std::vector<std::uint32_t> e(in.size());
  EXPECT_EQ(batch.evaluate(cols, in.size(), v.data(), e.data()), 334u);
  for (std::size_t i = 0; i < in.size(); ++i)
  {
    if (i % 3 == 0)
    {
      EXPECT_EQ(e[i], 1u);
      EXPECT_TRUE(std::isnan(v[i]));
    }
    else
    {
      EXPECT_EQ(e[i], 0u);
      EXPECT_EQ(v[i], std::sqrt(static_cast<double>(i)));
    }
  }
  EXPECT_EQ(batch.evaluate(cols, 0, v.data()), 0u);
}

TEST(BatchEvaluator, SharedPoolAndOptions)
{
  auto pool = std::make_shared<ThreadPool>(2);
  BatchOptions o;
  o.pool = pool;
  o.threads = 7; // ignored: the pool decides
  BatchEvaluator a(single_op_tape(Opcode::Add), o);
  BatchEvaluator c(single_op_tape(Opcode::Mul), o);
  EXPECT_EQ(a.threads(), 2);
  const Points pts(3, 700, 16);
  std::vector<double> va(pts.count);
  std::vector<double> vc(pts.count);
  a.evaluate(pts.pointers, pts.count, va.data());
  c.evaluate(pts.pointers, pts.count, vc.data());
  for (std::size_t i = 0; i < pts.count; ++i)
  {
    ASSERT_TRUE(same_bits(va[i], pts.columns[0][i] + pts.columns[1][i]));
    ASSERT_TRUE(same_bits(vc[i], pts.columns[0][i] * pts.columns[1][i]));
  }
  BatchOptions bad;
  bad.block_size = 0;
  EXPECT_THROW(BatchEvaluator(single_op_tape(Opcode::Add), bad), std::invalid_argument);
  BatchOptions single;
  single.threads = 1;
  BatchEvaluator one(single_op_tape(Opcode::Add), single);
  EXPECT_EQ(one.threads(), 1);
}

// An exception thrown by an opaque function inside a worker reaches the caller.
class ThrowingFunction : public OpaqueFunction
{
public:
  int evaluate(Scratch*, std::span<const double> in, std::span<double> out) const override
  {
    if (in[0] > 900)
    {
      throw std::runtime_error("opaque failure");
    }
    out[0] = in[0];
    return 0;
  }
};

TEST(BatchEvaluator, ExceptionsFromWorkersPropagate)
{
  TapeBuilder b(1);
  const auto x = b.input(0);
  const std::uint32_t o = b.tape.slot_count++;
  b.tape.calls.push_back({ std::make_shared<ThrowingFunction>(), { x }, { o } });
  b.tape.code.push_back({ Opcode::Call, 0, 0, 0, 0, 0, 0 });
  BatchOptions opt;
  opt.threads = 2;
  opt.block_size = 8;
  BatchEvaluator batch(b.finish({ o }), opt);
  std::vector<double> in(1000);
  for (std::size_t i = 0; i < in.size(); ++i)
  {
    in[i] = static_cast<double>(i);
  }
  const double* cols[1] = { in.data() };
  std::vector<double> v(in.size());
  EXPECT_THROW(batch.evaluate(cols, in.size(), v.data()), std::runtime_error);
  EXPECT_EQ(batch.evaluate(cols, 900, v.data()), 0u); // still usable
  EXPECT_EQ(v[899], 899.0);
}

} // namespace
} // namespace frep::test

namespace frep::test
{
namespace
{

// A tape that cannot fail, compiled, writes its outputs straight into the caller's arrays: every
// combination of asked-for outputs gets the point evaluator's values, the errors are zero, and
// outputs not asked for are not written anywhere the caller sees.
TEST(BatchEvaluator, CompiledKernelWritesOutputsInPlaceWhenNothingCanFail)
{
  TapeBuilder b(3);
  const auto x = b.input(0), y = b.input(1), z = b.input(2);
  const auto f = b.op(Opcode::Sub, b.op(Opcode::Mul, x, y), b.op(Opcode::Sqrt, b.op(Opcode::Abs, z)));
  const auto s1 = b.op(Opcode::Add, x, b.constant(0.5));
  const auto s2 = b.op(Opcode::Max, y, z);
  const auto tape = b.finish({ f, s1, s2 });
  ASSERT_FALSE(tape->can_fail);
  BatchOptions options;
  options.threads = 2;
  BatchEvaluator batch(tape, options);
  EXPECT_EQ(batch.compiled(), eval::jit_available());
  const Points pts(3, 5003, 57);
  PointEvaluator point(tape);
  for (int mask = 0; mask < 8; ++mask) // which of values, attribute 0, attribute 1 are asked for
  {
    std::vector<double> values(pts.count, 1.5), a0(pts.count, 2.5), a1(pts.count, 3.5);
    std::vector<std::uint32_t> errors(pts.count, 9);
    double* attributes[] = { mask & 2 ? a0.data() : nullptr, mask & 4 ? a1.data() : nullptr };
    EXPECT_EQ(batch.evaluate(pts.pointers, pts.count, mask & 1 ? values.data() : nullptr,
                errors.data(), attributes),
      0u);
    std::vector<double> out(3);
    for (std::size_t i = 0; i < pts.count; ++i)
    {
      point.evaluate(pts.point(i), out);
      ASSERT_EQ(errors[i], 0u) << mask;
      ASSERT_TRUE(same_bits(values[i], mask & 1 ? out[0] : 1.5)) << mask << " point " << i;
      ASSERT_TRUE(same_bits(a0[i], mask & 2 ? out[1] : 2.5)) << mask << " point " << i;
      ASSERT_TRUE(same_bits(a1[i], mask & 4 ? out[2] : 3.5)) << mask << " point " << i;
    }
  }
}

} // namespace
} // namespace frep::test
