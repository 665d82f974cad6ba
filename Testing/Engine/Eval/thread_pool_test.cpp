#include "Eval/thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace frep
{
namespace
{

TEST(ThreadPool, RunsEveryIndexOnceWithDistinctBusySlots)
{
  for (int threads : { 1, 2, 3, 4 })
  {
    ThreadPool pool(threads);
    ASSERT_EQ(pool.size(), threads);
    std::vector<std::atomic<int>> hits(1001);
    std::vector<std::atomic<int>> busy(static_cast<std::size_t>(threads));
    std::atomic<bool> overlap{ false };
    for (int round = 0; round < 5; ++round)
    {
      pool.parallel_for(hits.size(),
        [&](std::size_t i, int slot)
        {
          ASSERT_GE(slot, 0);
          ASSERT_LT(slot, threads);
          if (busy[static_cast<std::size_t>(slot)].fetch_add(1) != 0)
          {
            overlap = true; // one slot running two bodies at once
          }
          ++hits[i];
          --busy[static_cast<std::size_t>(slot)];
        });
    }
    for (auto& h : hits)
    {
      EXPECT_EQ(h.load(), 5);
    }
    EXPECT_FALSE(overlap.load());
  }
}

TEST(ThreadPool, UsesSeveralThreadsWhenAsked)
{
  ThreadPool pool(2);
  std::atomic<int> slot1{ 0 };
  std::atomic<bool> started{ false };
  // Index 0 waits until the other participant has picked up index 1, which can only happen
  // if the pool really runs two threads.
  pool.parallel_for(2,
    [&](std::size_t i, int slot)
    {
      if (i == 0)
      {
        while (!started.load())
        {
          std::this_thread::yield();
        }
      }
      else
      {
        started = true;
      }
      slot1 += slot;
    });
  EXPECT_EQ(slot1.load(), 1); // slots 0 and 1 each ran one index
}

TEST(ThreadPool, PropagatesTheExceptionAndStaysUsable)
{
  for (int threads : { 1, 2 })
  {
    ThreadPool pool(threads);
    std::atomic<int> ran{ 0 };
    EXPECT_THROW(pool.parallel_for(1000,
                   [&](std::size_t i, int)
                   {
                     ++ran;
                     if (i == 10)
                     {
                       throw std::runtime_error("block 10 failed");
                     }
                   }),
      std::runtime_error);
    EXPECT_LT(ran.load(), 1000); // the remaining indices were skipped
    std::atomic<int> after{ 0 };
    pool.parallel_for(100, [&](std::size_t, int) { ++after; });
    EXPECT_EQ(after.load(), 100);
  }
}

TEST(ThreadPool, NestedCallsRunInlineOnTheSameSlot)
{
  ThreadPool pool(2);
  std::atomic<int> inner{ 0 };
  std::atomic<bool> same_slot{ true };
  pool.parallel_for(8,
    [&](std::size_t, int outer_slot)
    {
      pool.parallel_for(4,
        [&](std::size_t, int slot)
        {
          if (slot != outer_slot)
          {
            same_slot = false;
          }
          ++inner;
        });
    });
  EXPECT_EQ(inner.load(), 32);
  EXPECT_TRUE(same_slot.load());
}

TEST(ThreadPool, ZeroMeansHardwareConcurrency)
{
  ThreadPool pool(0);
  EXPECT_GE(pool.size(), 1);
  pool.parallel_for(0, [](std::size_t, int) { FAIL() << "no index to run"; });
}

} // namespace
} // namespace frep
