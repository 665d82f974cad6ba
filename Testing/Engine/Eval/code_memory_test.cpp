// Executable memory reused from kernel to kernel (Eval/detail/code_memory.h) and the LazyKernel
// policy that reuses it only when no kernel still runs from it.
#include "Eval/detail/code_memory.h"
#include "Eval/detail/jit_kernel.h"

#include "eval_test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace frep
{
namespace
{

/// mov eax, value; ret
std::array<std::uint8_t, 6> return_constant(std::uint32_t value)
{
  return { 0xB8, static_cast<std::uint8_t>(value), static_cast<std::uint8_t>(value >> 8),
    static_cast<std::uint8_t>(value >> 16), static_cast<std::uint8_t>(value >> 24), 0xC3 };
}

int call(const eval::CodeMemory& memory)
{
  return reinterpret_cast<int (*)()>(const_cast<void*>(memory.entry()))();
}

TEST(CodeMemory, RunsWhatWasLoadedLastAtTheSameAddress)
{
#if !defined(__x86_64__) || !defined(__linux__)
  GTEST_SKIP() << "x86-64 Linux only";
#endif
  const auto memory = eval::CodeMemory::make(10);
  ASSERT_TRUE(memory);
  EXPECT_GE(memory->capacity(), 10u);
  const void* entry = memory->entry();
  ASSERT_TRUE(memory->load(return_constant(42)));
  EXPECT_EQ(call(*memory), 42);
  ASSERT_TRUE(memory->load(return_constant(7)));
  EXPECT_EQ(memory->entry(), entry);
  EXPECT_EQ(call(*memory), 7);
  const std::vector<std::uint8_t> too_long(memory->capacity() + 1, 0xC3);
  EXPECT_FALSE(memory->load(too_long));
  EXPECT_EQ(call(*memory), 7); // unchanged
}

double run(const eval::JitKernel& kernel, double x, double y)
{
  const double xs[4] = { x, x, x, x }, ys[4] = { y, y, y, y };
  const double* inputs[] = { xs, ys };
  double out[4] = {};
  double* outputs[] = { out };
  kernel.run(inputs, outputs, nullptr, 4);
  return out[0];
}

std::shared_ptr<const Tape> binary(Opcode op)
{
  test::TapeBuilder b(2);
  return b.finish({ b.op(op, b.input(0), b.input(1)) });
}

// A runner may still hold its previous tape's kernel while the next one compiles: that kernel
// keeps computing its own tape, and once released its memory serves the next kernels.
TEST(CodeMemory, LazyKernelNeverOverwritesAKernelStillHeld)
{
  if (!eval::jit_available())
  {
    GTEST_SKIP() << "no AVX2: the kernel cannot run here";
  }
  const auto add = binary(Opcode::Add), mul = binary(Opcode::Mul), sub = binary(Opcode::Sub);
  eval::LazyKernel lazy;
  const std::size_t enough = eval::LazyKernel::kWorthSamples;
  std::shared_ptr<const eval::JitKernel> held = lazy.get(*add, enough);
  ASSERT_TRUE(held);
  EXPECT_EQ(run(*held, 3, 4), 7);
  for (int round = 0; round < 4; ++round)
  {
    lazy.reset();
    const auto& next = lazy.get(round % 2 ? *sub : *mul, enough);
    ASSERT_TRUE(next);
    EXPECT_EQ(run(*next, 3, 4), round % 2 ? -1 : 12) << round;
    EXPECT_EQ(run(*held, 3, 4), 7) << round; // the held kernel's code is intact
  }
  held.reset();
  for (int round = 0; round < 4; ++round)
  {
    lazy.reset();
    const auto& next = lazy.get(round % 2 ? *add : *sub, enough);
    ASSERT_TRUE(next);
    EXPECT_EQ(run(*next, 3, 4), round % 2 ? 7 : -1) << round;
  }
  lazy.reset();
  EXPECT_FALSE(lazy.get(*add, enough / 2)); // too few samples to pay yet
}

} // namespace
} // namespace frep
