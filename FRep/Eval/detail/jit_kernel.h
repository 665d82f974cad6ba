// The register-resident batch kernel: a tape compiled to x86-64 AVX2 machine code that runs the
// whole tape on a chunk of 4 lanes at a time (two chunks interleaved when the tape is one long
// dependent chain) with the values in ymm registers (the most used slots; the others in a stack
// frame in L1), instead of one instruction at a time over rows of a block in memory (the
// interpreter loads and stores a row per instruction).
//
// Exact: the operations that are one correctly rounded IEEE instruction per lane are compiled to
// vector code (add, sub, mul, div, sqrt, min/max as vminpd/vmaxpd, which compute the original's
// a < b ? a : b and a > b ? a : b including NaN and signed zeros, floor/ceil/trunc as vroundpd,
// comparisons, logic and selects as lane masks, powers up to 16 as repeated multiplication), in
// the tape's order, without FMA. Every other pure instruction (libm, HyperFun's pow, mod and
// round) calls out, per chunk, to the scalar definition the point evaluator uses. So results are
// the point evaluator's bit for bit. A tape with an opaque Call (user functions, whole
// interpreted models) is not compiled: the interpreter runs it.
// Internal to the evaluators.
#pragma once

#include "Compiler/tape.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace frep::eval
{

class CodeMemory;

/// Whether this machine runs JIT kernels: x86-64 Linux with AVX2.
bool jit_available();

/// Whether `tape` can be compiled: it has no opaque Call (see the header comment).
bool jit_supports(const Tape& tape);

/// Whether compiling `tape` pays: not when calls out (libm, HyperFun's pow and mod) are most of
/// its estimated work. The users of the kernel (BatchEvaluator, LazyKernel) ask this.
bool jit_pays(const Tape& tape);

class JitKernel
{
public:
  /// Compiles `tape` (a checked one: slots and operands in range). Null when !jit_available(),
  /// !jit_supports(tape), or its spill frame would be too large for a thread's stack.
  static std::shared_ptr<const JitKernel> compile(const Tape& tape);
  /// The same, with the code in `memory` when it is large enough and no other kernel uses it
  /// (only the caller holds it), else in a new CodeMemory that the caller should keep for next
  /// time: `memory` is replaced by the one the kernel uses.
  static std::shared_ptr<const JitKernel> compile(const Tape& tape,
    std::shared_ptr<CodeMemory>& memory);

  ~JitKernel();
  JitKernel(const JitKernel&) = delete;
  JitKernel& operator=(const JitKernel&) = delete;

  /// Evaluates lanes [0, n): input k of lane i is inputs[k][i]; output j (tape.outputs[j]) goes
  /// to outputs[j][i]; when the tape can fail, errors[i] receives the lane's error id (0 = none;
  /// a failed lane's outputs are meaningless, as in the interpreter). Thread-safe.
  void run(const double* const* inputs, double* const* outputs, std::uint32_t* errors,
    std::size_t n) const;

  /// Bytes of machine code, and tape slots kept in the stack frame rather than in registers.
  std::size_t code_size() const { return code_size_; }
  std::size_t spilled_slots() const { return spilled_; }
  /// Lanes per pass: 4, or 8 for a latency-bound tape (two chunks interleaved).
  std::size_t lanes() const { return lanes_; }

private:
  JitKernel() = default;

  using Function = void (*)(const double* const*, double* const*, std::uint32_t*, std::size_t,
    const double*);

  std::shared_ptr<CodeMemory> memory_; // shared with the LazyKernel that may reuse it
  std::size_t code_size_ = 0;
  std::size_t spilled_ = 0;
  std::size_t inputs_ = 0;
  std::size_t outputs_ = 0;
  static constexpr std::size_t kMaxLanes = 8; // lanes per pass of the code, at most
  std::size_t lanes_ = 4;                      // lanes per pass of this code (1 or 2 chunks)
  Function function_ = nullptr;
  std::vector<double> constants_;
};

/// A tape's kernel, compiled once the tape has been given enough samples to pay for compiling
/// it (about as much as interpreting a thousand samples): the policy every user of a runner
/// shares. Not thread-safe; one per runner.
class LazyKernel
{
public:
  /// Forgets the kernel (the runner moves to another tape).
  void reset();
  /// The kernel of `tape`, about to run `samples` more samples: null while it does not pay
  /// (or cannot be compiled), when the interpreter runs.
  const std::shared_ptr<const JitKernel>& get(const Tape& tape, std::size_t samples);

  /// Samples at which compiling pays (measured with frep_eval_throughput and the samplers).
  static constexpr std::size_t kWorthSamples = 1024;

private:
  std::shared_ptr<const JitKernel> kernel_;
  // Executable memory reused from one tape's kernel to the next (a runner's previous kernel may
  // still be bound while the next one compiles: two suffice, each reused once nothing holds it).
  std::shared_ptr<CodeMemory> memory_[2];
  std::size_t samples_ = 0;
  bool tried_ = false;
};

} // namespace frep::eval
