// Tape simplification for a box: what each decided instruction becomes, NaN and signed-zero
// rules of max/min, kept and dropped checks, the compact register file, and the batch evaluator
// on simplified tapes. (Every real model is covered by the consistency tests.)
#include "eval_test_support.h"

#include "Eval/batch_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Eval/tape_simplifier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace frep
{
namespace
{

using test::TapeBuilder;

/// Choices for the box and the simplified tape (null: nothing decided).
struct Simplified
{
  std::vector<Choice> choices;
  std::shared_ptr<const Tape> tape;
};

Simplified simplify_for(const std::shared_ptr<const Tape>& tape, std::vector<Interval> box)
{
  IntervalEvaluator interval(tape);
  Simplified s;
  s.choices.resize(tape->code.size());
  interval.evaluate(box, s.choices);
  TapeSimplifier simplifier;
  s.tape = simplifier.simplify(*tape, s.choices);
  return s;
}

bool has_op(const Tape& tape, Opcode op)
{
  return std::any_of(tape.code.begin(), tape.code.end(), [&](const Instruction& i) { return i.op == op; });
}

bool same_bits(double a, double b)
{
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void expect_same_at(const std::shared_ptr<const Tape>& full, const std::shared_ptr<const Tape>& simplified,
  std::vector<double> x)
{
  PointEvaluator a(full), b(simplified);
  std::vector<double> out_a(full->outputs.size()), out_b(simplified->outputs.size());
  EXPECT_EQ(a.evaluate(x, out_a), b.evaluate(x, out_b));
  for (std::size_t k = 0; k < out_a.size(); ++k)
  {
    EXPECT_TRUE(same_bits(out_a[k], out_b[k])) << out_a[k] << " vs " << out_b[k];
  }
}

TEST(TapeSimplifier, SeparatedMaxKeepsTheLargerOperandOnly)
{
  TapeBuilder t(2);
  const auto x = t.input(0);
  const auto y = t.input(1);
  const auto y10 = t.op(Opcode::Add, y, t.constant(10));
  const auto x2 = t.op(Opcode::Square, x);
  const auto m = t.op(Opcode::Max, x2, y10);
  const auto tape = t.finish({ m });
  const Simplified s = simplify_for(tape, { { 0, 1 }, { 0, 1 } });
  ASSERT_TRUE(s.tape);
  EXPECT_EQ(s.choices[5], Choice::TakeB);
  EXPECT_FALSE(has_op(*s.tape, Opcode::Max));
  EXPECT_FALSE(has_op(*s.tape, Opcode::Square)); // x^2 is read by nothing else: removed
  EXPECT_EQ(s.tape->code.size(), 3u);            // y, 10, y + 10
  expect_same_at(tape, s.tape, { 0.5, 0.25 });
  // Overlapping ranges decide nothing.
  EXPECT_FALSE(simplify_for(tape, { { 0, 5 }, { 0, 1 } }).tape);
}

TEST(TapeSimplifier, MaxAndMinFollowTheComparisonWithNaNAndSignedZeros)
{
  // s = sqrt(x) is NaN for x < 0: (s > y) and (s < y) are false, the result is y.
  TapeBuilder t(2);
  const auto x = t.input(0);
  const auto y = t.input(1);
  const auto s = t.op(Opcode::Sqrt, x);
  const auto big = t.op(Opcode::Max, s, y);
  const auto small = t.op(Opcode::Min, y, s);
  const auto tape = t.finish({ big, small });
  // s in [0, 1] or NaN; y in [10, 11]: max -> y for every point (TakeB, NaN included); min(y, s)
  // cannot take s (NaN s gives s: the result is s either way, TakeB).
  const Simplified s1 = simplify_for(tape, { { -1, 1 }, { 10, 11 } });
  ASSERT_TRUE(s1.tape);
  EXPECT_EQ(s1.choices[3], Choice::TakeB);
  EXPECT_EQ(s1.choices[4], Choice::TakeB);
  for (double xv : { -0.5, 0.0, 0.9 })
  {
    expect_same_at(tape, s1.tape, { xv, 10.5 });
  }
  // s in [0, 1] or NaN and y in [-2, -1]: max(s, y) is s only where s is not NaN: undecided.
  const Simplified s2 = simplify_for(tape, { { -1, 1 }, { -2, -1 } });
  EXPECT_EQ(s2.choices[3], Choice::Keep);
  // Signed zeros: max(-0, +0) is +0 (b), min(+0, -0) is -0 (b): equal ranges decide b.
  TapeBuilder z(2);
  const auto a0 = z.input(0);
  const auto b0 = z.input(1);
  const auto zmax = z.op(Opcode::Max, a0, b0);
  const auto zmin = z.op(Opcode::Min, a0, b0);
  const auto ztape = z.finish({ zmax, zmin });
  const Simplified s3 = simplify_for(ztape, { { -0.0, -0.0 }, { 0.0, 0.0 } });
  ASSERT_TRUE(s3.tape);
  expect_same_at(ztape, s3.tape, { -0.0, 0.0 });
  expect_same_at(ztape, s3.tape, { 0.0, -0.0 });
}

TEST(TapeSimplifier, DecidedSelectsComparisonsAndChecks)
{
  TapeBuilder t(1);
  const auto x = t.input(0);
  const auto zero = t.constant(0);
  const auto positive = t.op(Opcode::Gt, x, zero);
  const auto negative = t.op(Opcode::Lt, x, zero);
  const int error = t.error_if(negative); // "x < 0" fails
  const auto root = t.op(Opcode::Sqrt, x);
  const auto other = t.op(Opcode::Neg, x);
  const auto sel = t.op(Opcode::Select, positive, root, other);
  const auto far = t.op(Opcode::Max, x, t.constant(100));
  const auto tape = t.finish({ sel, positive, far });
  // x in [1, 2]: x > 0 everywhere (True), x < 0 nowhere (the check is dropped), Select -> b.
  const Simplified s = simplify_for(tape, { { 1, 2 } });
  ASSERT_TRUE(s.tape);
  EXPECT_EQ(s.choices[2], Choice::True);
  EXPECT_EQ(s.choices[3], Choice::False);
  EXPECT_EQ(s.choices[4], Choice::Drop);
  EXPECT_EQ(s.choices[7], Choice::TakeB);
  EXPECT_FALSE(has_op(*s.tape, Opcode::ErrorIf));
  EXPECT_FALSE(has_op(*s.tape, Opcode::Select));
  EXPECT_FALSE(s.tape->can_fail);
  expect_same_at(tape, s.tape, { 1.5 });
  // x in [-1, 2]: only the max is decided; the check can fire: kept, with the same error id
  // where it fires.
  const Simplified k = simplify_for(tape, { { -1, 2 } });
  ASSERT_TRUE(k.tape);
  EXPECT_EQ(k.choices[4], Choice::Keep);
  EXPECT_TRUE(has_op(*k.tape, Opcode::ErrorIf));
  PointEvaluator p(k.tape);
  std::vector<double> out(3);
  const std::vector<double> at{ -0.5 };
  EXPECT_EQ(p.evaluate(at, out), error);
  expect_same_at(tape, k.tape, { -0.5 });
  expect_same_at(tape, k.tape, { 1.0 });
}

TEST(TapeSimplifier, RegistersAreReusedAndBatchResultsMatch)
{
  // A chain of maxima of shifted squares: most terms are decided in a small box.
  TapeBuilder t(1);
  const auto x = t.input(0);
  auto acc = t.op(Opcode::Neg, t.op(Opcode::Square, x));
  for (int i = 1; i <= 40; ++i)
  {
    const auto d = t.op(Opcode::Sub, x, t.constant(i));
    acc = t.op(Opcode::Max, acc, t.op(Opcode::Neg, t.op(Opcode::Square, d)));
  }
  const auto tape = t.finish({ acc });
  const Simplified s = simplify_for(tape, { { 19.9, 20.1 } });
  ASSERT_TRUE(s.tape);
  EXPECT_LT(s.tape->code.size() * 10, tape->code.size());
  EXPECT_LE(s.tape->slot_count, 4u);
  EXPECT_TRUE(worth_switching(*s.tape, *tape));
  EXPECT_FALSE(worth_switching(*tape, *tape));
  std::vector<double> xs(1000);
  for (std::size_t i = 0; i < xs.size(); ++i)
  {
    xs[i] = 19.9 + 0.2 * double(i) / double(xs.size() - 1);
  }
  std::vector<double> full(xs.size()), simplified(xs.size());
  BatchOptions one;
  one.threads = 1;
  BatchEvaluator a(tape, one), b(s.tape, one);
  const double* in[] = { xs.data() };
  a.evaluate(in, xs.size(), full.data());
  b.evaluate(in, xs.size(), simplified.data());
  for (std::size_t i = 0; i < xs.size(); ++i)
  {
    ASSERT_TRUE(same_bits(full[i], simplified[i])) << xs[i];
  }
}

TEST(TapeSimplifier, WhatCannotBeDecidedAndBadCalls)
{
  TapeBuilder t(2);
  const auto u = t.op(Opcode::Union, t.input(0), t.input(1));
  const auto tape = t.finish({ u });
  EXPECT_FALSE(may_simplify(*tape)); // an R-function is never replaced by an operand
  const Simplified s = simplify_for(tape, { { 5, 6 }, { -9, -8 } });
  EXPECT_FALSE(s.tape);
  TapeSimplifier simplifier;
  const std::vector<Choice> wrong(1, Choice::Keep);
  EXPECT_THROW(simplifier.simplify(*tape, wrong), std::invalid_argument);
  IntervalEvaluator interval(tape);
  std::vector<Choice> short_choices(1);
  const std::vector<Interval> box{ { 0, 1 }, { 0, 1 } };
  EXPECT_THROW(interval.evaluate(box, short_choices), std::invalid_argument);
}

} // namespace
} // namespace frep
