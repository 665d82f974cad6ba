// The region walker: an octree walk as its clients write one. Leaves evaluated with their
// region's tape give the full tape's values bit for bit; culled boxes are on the side their
// enclosure says; a tape whose regions decide min/max is simplified and one that never pays
// stops being tried after 16 tries; freezes and tasks handed between walkers keep the values.
#include "eval_test_support.h"

#include "Eval/point_evaluator.h"
#include "Eval/region_walker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace frep
{
namespace
{

/// 24 balls on a ring of radius 6 (Max: regions decide it; Union: they never do).
std::shared_ptr<const Tape> ring(Opcode join)
{
  return test::ring_of_balls(join, 24, 6.0);
}

bool same_bits(double a, double b)
{
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// An octree walk of [-8, 8]^3 down to boxes of side 1, each leaf sampled at 3^3 points, as a
/// client of the walker writes it; checks every value against the full tape.
struct OctreeCheck
{
  RegionWalker& walker;
  PointEvaluator full;
  std::size_t leaves = 0, culled = 0, shorter_leaves = 0, mismatches = 0, wrong_side = 0;

  void visit(const RegionWalker::Region& region, const std::vector<Interval>& box)
  {
    const IntervalResult r = walker.enclose(region, box);
    if (r.value.hi < 0.0 || r.value.lo >= 0.0)
    {
      ++culled;
      check_side(box, r.value.lo >= 0.0);
      return;
    }
    const RegionWalker::Region inner = walker.descend(region);
    EXPECT_EQ(inner.depth(), region.depth() + 1);
    if (box[0].hi - box[0].lo <= 1.0)
    {
      leaf(inner, box);
      return;
    }
    for (int c = 0; c < 8; ++c)
    {
      std::vector<Interval> child = box;
      for (int a = 0; a < 3; ++a)
      {
        const double mid = 0.5 * (box[a].lo + box[a].hi);
        child[a] = (c >> a) & 1 ? Interval{ mid, box[a].hi } : Interval{ box[a].lo, mid };
      }
      visit(inner, child);
    }
  }

  void leaf(const RegionWalker::Region& region, const std::vector<Interval>& box)
  {
    ++leaves;
    shorter_leaves += walker.tape(region)->code.size() < full.tape().code.size() ? 1 : 0;
    std::vector<double> xs, ys, zs;
    for (int k = 0; k < 27; ++k)
    {
      xs.push_back(box[0].lo + 0.5 * (k % 3) * (box[0].hi - box[0].lo));
      ys.push_back(box[1].lo + 0.5 * (k / 3 % 3) * (box[1].hi - box[1].lo));
      zs.push_back(box[2].lo + 0.5 * (k / 9) * (box[2].hi - box[2].lo));
    }
    const double* inputs[3] = { xs.data(), ys.data(), zs.data() };
    std::vector<double> values(27);
    walker.evaluate(region, inputs, 27, values.data());
    for (int k = 0; k < 27; ++k)
    {
      std::vector<double> at{ xs[k], ys[k], zs[k] }, out(1);
      full.evaluate(at, out);
      mismatches += same_bits(out[0], values[static_cast<std::size_t>(k)]) ? 0 : 1;
    }
  }

  void check_side(const std::vector<Interval>& box, bool inside)
  {
    std::vector<double> at{ 0.5 * (box[0].lo + box[0].hi), 0.5 * (box[1].lo + box[1].hi),
      0.5 * (box[2].lo + box[2].hi) };
    std::vector<double> out(1);
    full.evaluate(at, out);
    wrong_side += (out[0] >= 0.0) == inside ? 0 : 1;
  }
};

const std::vector<Interval> kWhole{ { -8, 8 }, { -8, 8 }, { -8, 8 } };

/// The octree walk of kWhole with `walker`, checked against `tape`.
OctreeCheck walk_whole(RegionWalker& walker, const std::shared_ptr<const Tape>& tape)
{
  OctreeCheck check{ walker, PointEvaluator(tape) };
  check.visit(walker.root(), kWhole);
  return check;
}

TEST(RegionWalker, LeavesOfASimplifiedWalkHaveTheFullTapesValues)
{
  for (const bool freeze : { false, true })
  {
    const auto tape = ring(Opcode::Max);
    RegionWalkerOptions options;
    options.freeze = freeze;
    RegionWalker walker(tape, options);
    const OctreeCheck check = walk_whole(walker, tape);
    EXPECT_GT(check.leaves, 100u);
    EXPECT_GT(check.culled, 100u);
    EXPECT_EQ(check.mismatches, 0u) << "freeze " << freeze;
    EXPECT_EQ(check.wrong_side, 0u);
    // Near one ball the other 23 are decided: the leaves run a short tape.
    EXPECT_EQ(check.shorter_leaves, check.leaves);
    EXPECT_GT(walker.statistics().simplified, 0u);
    EXPECT_EQ(walker.statistics().points, 27 * check.leaves);
    EXPECT_LT(walker.statistics().instructions, 27 * check.leaves * tape->code.size() / 2);
  }
}

TEST(RegionWalker, WithoutSimplificationEveryRegionRunsTheWalkersTape)
{
  const auto tape = ring(Opcode::Max);
  RegionWalkerOptions options;
  options.simplify = false;
  RegionWalker walker(tape, options);
  const OctreeCheck check = walk_whole(walker, tape);
  EXPECT_EQ(check.mismatches, 0u);
  EXPECT_EQ(check.shorter_leaves, 0u);
  EXPECT_EQ(walker.statistics().simplify_tries, 0u);
}

// An R-union's regions decide nothing that shortens it (only its error check): the walker tries
// 16 times on the root's tape, then stops paying for a copy per region.
TEST(RegionWalker, ATapeThatNeverPaysIsTriedSixteenTimes)
{
  const auto tape = ring(Opcode::Union);
  RegionWalker walker(tape);
  const OctreeCheck check = walk_whole(walker, tape);
  EXPECT_EQ(check.mismatches, 0u);
  EXPECT_GT(walker.statistics().enclosures, 100u);
  EXPECT_EQ(walker.statistics().simplified, 0u);
  EXPECT_EQ(walker.statistics().simplify_tries, 16u);
}

// The tiled sampler's hand-over: one walker simplifies for a region, another starts its walk
// from that tape (root(tape)) and gets the same values.
TEST(RegionWalker, AWalkStartsFromAnotherWalkersTape)
{
  const auto tape = ring(Opcode::Max);
  RegionWalker first(tape), second(tape);
  const std::vector<Interval> near_one_ball{ { 5, 7 }, { -1, 1 }, { -1, 1 } };
  first.enclose(first.root(), near_one_ball);
  const RegionWalker::Region inner = first.descend(first.root());
  const std::shared_ptr<const Tape> handed = first.tape(inner);
  ASSERT_LT(handed->code.size(), tape->code.size());
  const RegionWalker::Region start = second.root(handed);
  EXPECT_EQ(second.tape(start), handed);
  EXPECT_EQ(second.tape(second.root(tape)), tape);
  OctreeCheck check{ second, PointEvaluator(tape) };
  check.visit(start, near_one_ball);
  EXPECT_EQ(check.mismatches, 0u);
  EXPECT_GT(check.leaves, 0u);
}

TEST(RegionWalker, DescendWithoutEncloseKeepsTheTape)
{
  const auto tape = ring(Opcode::Max);
  RegionWalker walker(tape);
  const RegionWalker::Region inner = walker.descend(walker.root());
  EXPECT_EQ(walker.tape(inner), tape);
  EXPECT_EQ(inner.depth(), 1u);
}

TEST(RegionWalker, RefusesBadArguments)
{
  EXPECT_THROW(RegionWalker(nullptr), std::invalid_argument);
  RegionWalkerOptions options;
  options.block = 0;
  EXPECT_THROW(RegionWalker(ring(Opcode::Max), options), std::invalid_argument);
  options.block = 64;
  options.freeze_every = 0;
  EXPECT_THROW(RegionWalker(ring(Opcode::Max), options), std::invalid_argument);
}

} // namespace
} // namespace frep
