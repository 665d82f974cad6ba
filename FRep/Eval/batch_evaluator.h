// Evaluates a tape over many points: blocks of lanes processed instruction by instruction
// (loops the compiler vectorises), blocks distributed over worker threads. Results are
// bit-identical to PointEvaluator.
#pragma once

#include "Compiler/tape.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

namespace frep
{

class ThreadPool;

/// Kernel builds of the batch evaluator (x86-64; elsewhere only Baseline exists).
enum class SimdLevel
{
  Baseline, ///< SSE2 (the x86-64 baseline): 2 lanes per instruction
  AVX2,     ///< 4 lanes, if the CPU has AVX2 (else Baseline)
  AVX512,   ///< 8 lanes, if the CPU has AVX-512 F/DQ/VL (else the best lower level)
  Best = AVX512
};

struct BatchOptions
{
  /// Worker threads; 0 = std::thread::hardware_concurrency(). 1 = evaluate on the caller.
  int threads = 0;
  /// Points per block (lanes); the register file of one block stays in cache.
  int block_size = 256;
  /// A pool to run on instead of one of the evaluator's own (then `threads` is ignored). Several
  /// evaluators may share a pool; their evaluate() calls are then serialised by it.
  std::shared_ptr<ThreadPool> pool;
  /// The widest kernel build to use: the best the CPU has by default. Every level gives
  /// identical results (no FMA anywhere); lower levels exist for tests and measurements.
  SimdLevel simd = SimdLevel::Best;
  /// Compile the tape to machine code (the register-resident kernel, Eval/detail/jit_kernel.h) when
  /// the CPU has AVX2, `simd` is at least AVX2 and every instruction has an exact compiled form;
  /// otherwise, or when false, the interpreter runs. Both give identical results.
  bool jit = true;
};

class BatchEvaluator
{
public:
  explicit BatchEvaluator(std::shared_ptr<const Tape> tape, const BatchOptions& options = {});
  ~BatchEvaluator();
  BatchEvaluator(const BatchEvaluator&) = delete;
  BatchEvaluator& operator=(const BatchEvaluator&) = delete;

  const Tape& tape() const;

  /// Threads that evaluate blocks (the pool's participants, 1 = the caller only).
  int threads() const;

  /// Whether the tape runs as compiled machine code (see BatchOptions::jit).
  bool compiled() const;

  /// Structure-of-arrays evaluation of `count` points: inputs[k][i] is input k of point i
  /// (inputs.size() == tape().input_count). values[i] = F, or NaN where the point raised a
  /// run-time error; errors (optional) receive the error id per point (0 = none);
  /// attributes (optional) receive s[j] of point i at attributes[j][i] (j < outputs-1).
  /// Returns the number of points that raised an error.
  std::size_t evaluate(std::span<const double* const> inputs,
    std::size_t count,
    double* values,
    std::uint32_t* errors = nullptr,
    std::span<double* const> attributes = {});

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace frep
