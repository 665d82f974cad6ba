// The per-block kernel of BatchEvaluator: one instruction at a time over all lanes of a block
// (structure of arrays), in loops GCC vectorises. Compiled twice, for the SSE2 baseline and for
// AVX2, and chosen at run time; both perform the same IEEE operations per lane, without FMA
// (-ffp-contract=off), so they give identical bits. Internal to the evaluators.
#pragma once

#include "Compiler/tape.h"
#include "Eval/batch_evaluator.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace frep::eval
{

/// Per-thread state for opaque calls (the functions' scratch and gather/scatter buffers).
struct CallState
{
  std::vector<std::unique_ptr<OpaqueFunction::Scratch>> scratch; ///< per call site
  std::vector<double> in;
  std::vector<double> out;
};

/// One block: lanes [0, n) of a register file of slot_count rows of `stride` lanes.
struct Block
{
  double* regs = nullptr;          ///< row s = slot s, `stride` doubles, 64-byte aligned
  /// Where slot s's lanes currently are: its own row, or for an Input the caller's array (no
  /// copy). slot_count entries, owned by the caller; valid after run_block for the outputs.
  const double** rows = nullptr;
  std::uint32_t* errors = nullptr; ///< per lane, 0 = none (must be zeroed by the caller)
  int n = 0;                       ///< active lanes (<= stride)
  int stride = 0;
  const double* const* inputs = nullptr; ///< inputs[k] + base = input k of lane 0
  std::size_t base = 0;
};

/// Whether the AVX2 kernel may run on this CPU.
bool cpu_has_avx2();
/// Whether the AVX-512 (F, DQ, VL) kernel may run on this CPU.
bool cpu_has_avx512();

struct BatchProgram;

/// Runs `program` (the batch form of `tape`, see batch_program.h) over one block.
/// `simd` is the widest build to use (lowered to what the CPU has).
void run_block(const Tape& tape, const BatchProgram& program, const Block& block,
  CallState& calls, SimdLevel simd);

} // namespace frep::eval
