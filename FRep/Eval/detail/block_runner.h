// Internal to the evaluators: one thread's batch evaluation of a tape, block by block, with its
// register file, error lanes and call scratch kept between calls and between tapes. BatchEvaluator
// holds one per pool participant; the tiled sampler holds one per participant and rebinds it to
// each tile's simplified tape, so a tile pays for its program only, not for a new evaluator (a new
// register file zero-filled, the checks, the call scratch: a tenth of Prospero's sampling time).
#pragma once

#include "Compiler/tape.h"
#include "Eval/batch_evaluator.h"
#include "Eval/detail/batch_kernel.h"
#include "Eval/detail/batch_program.h"
#include "Eval/detail/jit_kernel.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace frep::eval
{

class BlockRunner
{
public:
  /// `block`: lanes per block (> 0); `simd`: the widest kernel build to use.
  explicit BlockRunner(int block = 256, SimdLevel simd = SimdLevel::Best);
  ~BlockRunner();
  BlockRunner(const BlockRunner&) = delete;
  BlockRunner& operator=(const BlockRunner&) = delete;

  /// Evaluates `tape` from now on (checked unless `trusted`: a tape the engine made itself, such
  /// as a simplified one). Keeps the buffers; rebinding the same tape costs nothing. `jit`: the
  /// tape compiled to machine code (JitKernel::compile of the same tape), run instead of the
  /// interpreter; null for the interpreter.
  void bind(std::shared_ptr<const Tape> tape, bool trusted = false,
    std::shared_ptr<const JitKernel> jit = nullptr);
  const Tape& tape() const { return *tape_; }
  int block() const { return block_; }

  /// BatchEvaluator::evaluate's contract for the points [base, base + n) (n <= block()): their
  /// values, errors and attributes go to values + base, errors + base, attributes[j] + base.
  /// Returns the number of points that raised an error.
  std::size_t run(std::span<const double* const> inputs, std::size_t base, int n, double* values,
    std::uint32_t* errors, std::span<double* const> attributes);

  /// All `count` points, block after block, on the calling thread.
  std::size_t evaluate(std::span<const double* const> inputs, std::size_t count, double* values,
    std::uint32_t* errors, std::span<double* const> attributes);

private:
  void run_jit(std::span<const double* const> inputs, std::size_t base, int n);
  /// The kernel's input pointers at lane `base`, and room for its output pointers.
  void point_jit_inputs(std::span<const double* const> inputs, std::size_t base);
  /// The register row of tape output j.
  double* output_row(std::size_t j) const;
  /// run() with the kernel for a tape that cannot fail: outputs written in place.
  std::size_t run_jit_direct(std::span<const double* const> inputs, std::size_t base, int n,
    double* values, std::uint32_t* errors, std::span<double* const> attributes);

  struct AlignedFree
  {
    void operator()(double* p) const;
  };

  int block_;
  SimdLevel simd_;
  std::shared_ptr<const Tape> tape_;
  std::shared_ptr<const Tape> checked_; // the last untrusted tape bound, checked
  bool checked_reads_unwritten_ = false; // ... and whether it reads a slot before writing it
  BatchProgram program_;
  std::shared_ptr<const JitKernel> jit_;
  std::vector<const double*> jit_inputs_;
  std::vector<double*> jit_outputs_;
  std::unique_ptr<double[], AlignedFree> regs_;
  std::size_t reg_capacity_ = 0; // doubles
  std::vector<const double*> rows_;
  std::vector<std::uint32_t> lane_errors_;
  CallState calls_;
};

} // namespace frep::eval
