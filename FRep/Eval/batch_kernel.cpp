// Compiled with -fno-math-errno (see CMakeLists.txt): sqrt then becomes the vector instruction,
// which is correctly rounded exactly like the scalar one; nothing else changes value.
#include "Eval/detail/batch_kernel.h"

#include "Eval/detail/batch_program.h"
#include "Eval/detail/batch_scalar_lanes.h"

#include "Semantics/detail/op_semantics.h"
#include "Eval/detail/instruction_value.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <utility>

namespace frep::eval
{

namespace
{

namespace hf = frep::semantics;

// Lane loops: element-wise, so there is no loop-carried dependency even when the output row
// is also an operand row (the register allocator may reuse a slot). `ivdep` states exactly
// that and lets GCC vectorise without run-time alias checks (restrict would promise more).
#define FREP_LANES _Pragma("GCC ivdep") for (int i = 0; i < n; ++i)

#define FREP_ALWAYS_INLINE [[gnu::always_inline]] inline

// b ^ N by repeated multiplication (exactly hf_pow_int's operations), |b| < EPS -> 0 as a blend.
template<int N, bool Negative>
FREP_ALWAYS_INLINE void pow_int_lanes(double* o, const double* x, int n)
{
  FREP_LANES
  {
    const double b = x[i];
    double v = 1.0;
    // Straight-line (a loop here, even of constant count, keeps GCC from vectorising the lanes).
    [&]<std::size_t... K>(std::index_sequence<K...>)
    { ((v *= b, static_cast<void>(K)), ...); }(std::make_index_sequence<N>{});
    if constexpr (Negative)
    {
      v = 1 / v;
    }
    o[i] = std::fabs(b) < hf::kEps ? 0.0 : v;
  }
}

constexpr int kMaxUnrolledPower = 16;

template<int N = 0>
FREP_ALWAYS_INLINE bool pow_int_unrolled(int exponent, double* o, const double* x, int n)
{
  if constexpr (N > kMaxUnrolledPower)
  {
    return false;
  }
  else
  {
    if (exponent == N)
    {
      pow_int_lanes<N, false>(o, x, n);
      return true;
    }
    if (N > 0 && exponent == -N)
    {
      pow_int_lanes<N, true>(o, x, n);
      return true;
    }
    return pow_int_unrolled<N + 1>(exponent, o, x, n);
  }
}

FREP_ALWAYS_INLINE void call_lanes(const Tape& tape,
  const Instruction& ins,
  const Block& blk,
  CallState& calls)
{
  const std::size_t site_index = static_cast<std::size_t>(ins.index);
  const CallSite& site = tape.calls[site_index];
  const std::size_t n_in = site.inputs.size();
  const std::size_t n_out = site.outputs.size();
  OpaqueFunction::Scratch* scratch = calls.scratch[site_index].get();
  // A batch form (a user function's) takes the whole block at once, straight from the rows.
  if (n_in <= 64 && n_out == 1)
  {
    std::array<const double*, 64> in_rows{};
    for (std::size_t k = 0; k < n_in; ++k)
    {
      in_rows[k] = blk.rows[site.inputs[k]];
    }
    double* out_row = blk.regs + static_cast<std::size_t>(site.outputs[0]) * blk.stride;
    if (site.function->evaluate_lanes(scratch, in_rows.data(), blk.n, &out_row, blk.errors))
    {
      blk.rows[site.outputs[0]] = out_row;
      return;
    }
  }
  for (int i = 0; i < blk.n; ++i)
  {
    if (blk.errors[i] != 0)
    {
      continue; // the lane's result is already NaN; do not run a possibly costly function
    }
    for (std::size_t k = 0; k < n_in; ++k)
    {
      calls.in[k] = blk.rows[site.inputs[k]][i];
    }
    const int status = site.function->evaluate(scratch,
      std::span<const double>(calls.in.data(), n_in),
      std::span<double>(calls.out.data(), n_out));
    if (status != 0)
    {
      blk.errors[i] = static_cast<std::uint32_t>(status);
      continue;
    }
    for (std::size_t k = 0; k < n_out; ++k)
    {
      blk.regs[static_cast<std::size_t>(site.outputs[k]) * blk.stride + i] = calls.out[k];
    }
  }
  for (std::uint32_t slot : site.outputs)
  {
    blk.rows[slot] = blk.regs + static_cast<std::size_t>(slot) * blk.stride;
  }
}

// A binary lane loop over two rows, or a row and the instruction's immediate (BatchProgram):
// `expr` is written in terms of the lane values `l` and `r`.
#define FREP_BINARY(expr)                                                                      \
  if (side == Immediate::None)                                                                 \
  {                                                                                            \
    FREP_LANES                                                                                 \
    {                                                                                          \
      const double l = x[i];                                                                   \
      const double r = y[i];                                                                   \
      o[i] = (expr);                                                                           \
    }                                                                                          \
  }                                                                                            \
  else if (side == Immediate::B)                                                               \
  {                                                                                            \
    const double r = ins.imm;                                                                  \
    FREP_LANES                                                                                 \
    {                                                                                          \
      const double l = x[i];                                                                   \
      o[i] = (expr);                                                                           \
    }                                                                                          \
  }                                                                                            \
  else                                                                                         \
  {                                                                                            \
    const double l = ins.imm;                                                                  \
    FREP_LANES                                                                                 \
    {                                                                                          \
      const double r = y[i];                                                                   \
      o[i] = (expr);                                                                           \
    }                                                                                          \
  }

/// The operations of the C library and the HyperFun library (Exp .. Fmod, Hf*): libm one call
/// per lane (no vector libm: it would not give the same bits), the Hf* rules lane by lane.
FREP_ALWAYS_INLINE void library_lanes(
  const Instruction& ins, double* o, const double* x, const double* y, int n)
{
  switch (ins.op)
  {
    case Opcode::Exp:
      for (int i = 0; i < n; ++i)
        o[i] = std::exp(x[i]);
      break;
    case Opcode::Log:
      for (int i = 0; i < n; ++i)
        o[i] = std::log(x[i]);
      break;
    case Opcode::Log10:
      for (int i = 0; i < n; ++i)
        o[i] = std::log10(x[i]);
      break;
    case Opcode::Sin:
      for (int i = 0; i < n; ++i)
        o[i] = std::sin(x[i]);
      break;
    case Opcode::Cos:
      for (int i = 0; i < n; ++i)
        o[i] = std::cos(x[i]);
      break;
    case Opcode::Tan:
      for (int i = 0; i < n; ++i)
        o[i] = std::tan(x[i]);
      break;
    case Opcode::Asin:
      for (int i = 0; i < n; ++i)
        o[i] = std::asin(x[i]);
      break;
    case Opcode::Acos:
      for (int i = 0; i < n; ++i)
        o[i] = std::acos(x[i]);
      break;
    case Opcode::Atan:
      for (int i = 0; i < n; ++i)
        o[i] = std::atan(x[i]);
      break;
    case Opcode::Sinh:
      for (int i = 0; i < n; ++i)
        o[i] = std::sinh(x[i]);
      break;
    case Opcode::Cosh:
      for (int i = 0; i < n; ++i)
        o[i] = std::cosh(x[i]);
      break;
    case Opcode::Tanh:
      for (int i = 0; i < n; ++i)
        o[i] = std::tanh(x[i]);
      break;
    case Opcode::Atan2:
      for (int i = 0; i < n; ++i)
        o[i] = std::atan2(x[i], y[i]);
      break;
    case Opcode::Pow:
      for (int i = 0; i < n; ++i)
        o[i] = std::pow(x[i], y[i]);
      break;
    case Opcode::Frac:
      for (int i = 0; i < n; ++i)
        o[i] = frac(x[i]);
      break;
    case Opcode::Fmod:
      for (int i = 0; i < n; ++i)
        o[i] = std::fmod(x[i], y[i]);
      break;
    case Opcode::HfPow:
      hf_pow_lanes(o, x, y, n);
      break;
    case Opcode::HfPowInt:
      if (!pow_int_unrolled(ins.index, o, x, n))
      {
        hf_pow_int_lanes(o, x, ins.index, n);
      }
      break;
    case Opcode::HfMod:
      hf_mod_lanes(o, x, y, n);
      break;
    case Opcode::HfRound:
      hf_round_lanes(o, x, n);
      break;
    default:
      break; // not a library operation: never called so
  }
}

/// Comparisons (HyperFun's EPS for = and <>), the logical operations on truth values and
/// Select, lane by lane; `side`: which operand of a comparison is the immediate (BatchProgram).
FREP_ALWAYS_INLINE void logic_lanes(const Instruction& ins, Immediate side, double* o,
  const double* x, const double* y, const double* z, int n)
{
  switch (ins.op)
  {
    case Opcode::Eq:
      FREP_LANES o[i] = std::fabs(x[i] - y[i]) < hf::kEps ? 1.0 : 0.0;
      break;
    case Opcode::Ne:
      FREP_LANES o[i] = std::fabs(x[i] - y[i]) >= hf::kEps ? 1.0 : 0.0;
      break;
    case Opcode::Lt:
      FREP_BINARY(l < r ? 1.0 : 0.0)
      break;
    case Opcode::Le:
      FREP_BINARY(l <= r ? 1.0 : 0.0)
      break;
    case Opcode::Gt:
      FREP_BINARY(l > r ? 1.0 : 0.0)
      break;
    case Opcode::Ge:
      FREP_BINARY(l >= r ? 1.0 : 0.0)
      break;
    case Opcode::Truthy:
      FREP_LANES o[i] = std::fabs(x[i]) >= hf::kEps ? 1.0 : 0.0;
      break;
    case Opcode::And:
      FREP_LANES o[i] = (std::fabs(x[i]) >= hf::kEps) & (std::fabs(y[i]) >= hf::kEps) ? 1.0 : 0.0;
      break;
    case Opcode::Or:
      FREP_LANES o[i] = (std::fabs(x[i]) >= hf::kEps) | (std::fabs(y[i]) >= hf::kEps) ? 1.0 : 0.0;
      break;
    case Opcode::Not:
      FREP_LANES o[i] = std::fabs(x[i]) >= hf::kEps ? 0.0 : 1.0;
      break;
    case Opcode::Select:
      FREP_LANES
      {
        // both loads unconditional, so the choice is a blend
        const double t = y[i];
        const double f = z[i];
        o[i] = x[i] != 0.0 ? t : f;
      }
      break;
    default:
      break; // not a logical operation: never called so
  }
}

FREP_ALWAYS_INLINE void run_block_body(
  const Tape& tape, const BatchProgram& program, const Block& blk, CallState& calls)
{
  const int n = blk.n;
  const std::size_t stride = static_cast<std::size_t>(blk.stride);
  const std::uint32_t last = tape.slot_count == 0 ? 0 : tape.slot_count - 1;
  // Operand fields an opcode does not use may hold anything: clamp so the pointer stays valid.
  const auto own_row = [&](std::uint32_t slot) { return blk.regs + std::min(slot, last) * stride; };
  const auto row = [&](std::uint32_t slot) { return blk.rows[std::min(slot, last)]; };
  std::uint32_t* err = blk.errors;
  const std::size_t count = program.code.size();
  for (std::size_t k = 0; k < count; ++k)
  {
    const Instruction& ins = program.code[k];
    const Immediate side = program.immediate[k];
    double* o = own_row(ins.out);
    const double* x = row(ins.a);
    const double* y = row(ins.b);
    const double* z = row(ins.c);
    switch (ins.op)
    {
      case Opcode::Const:
      {
        const double v = ins.imm;
        FREP_LANES o[i] = v;
        break;
      }
      case Opcode::Input:
        // No copy: the slot reads the caller's array directly until it is written again.
        blk.rows[std::min(ins.out, last)] = blk.inputs[ins.index] + blk.base;
        continue;
      case Opcode::Add:
        FREP_BINARY(l + r)
        break;
      case Opcode::Sub:
        FREP_BINARY(l - r)
        break;
      case Opcode::Mul:
        FREP_BINARY(l * r)
        break;
      case Opcode::Div:
        FREP_BINARY(l / r)
        break;
      case Opcode::Neg:
        FREP_LANES o[i] = -x[i];
        break;
      case Opcode::Square:
        FREP_LANES o[i] = x[i] * x[i];
        break;
      case Opcode::Abs:
        FREP_LANES o[i] = std::fabs(x[i]);
        break;
      case Opcode::Sqrt:
        FREP_LANES o[i] = std::sqrt(x[i]);
        break;
      case Opcode::Floor:
        FREP_LANES o[i] = std::floor(x[i]);
        break;
      case Opcode::Ceil:
        FREP_LANES o[i] = std::ceil(x[i]);
        break;
      case Opcode::Trunc:
        FREP_LANES o[i] = std::trunc(x[i]);
        break;
      case Opcode::Exp:
      case Opcode::Log:
      case Opcode::Log10:
      case Opcode::Sin:
      case Opcode::Cos:
      case Opcode::Tan:
      case Opcode::Asin:
      case Opcode::Acos:
      case Opcode::Atan:
      case Opcode::Sinh:
      case Opcode::Cosh:
      case Opcode::Tanh:
      case Opcode::Atan2:
      case Opcode::Pow:
      case Opcode::Frac:
      case Opcode::Fmod:
      case Opcode::HfPow:
      case Opcode::HfPowInt:
      case Opcode::HfMod:
      case Opcode::HfRound:
        library_lanes(ins, o, x, y, n);
        break;
      case Opcode::Max:
        FREP_BINARY(hf::hf_max(l, r))
        break;
      case Opcode::Min:
        FREP_BINARY(hf::hf_min(l, r))
        break;
      case Opcode::Union:
        FREP_BINARY(hf::unite(l, r))
        break;
      case Opcode::Intersect:
        FREP_BINARY(hf::intersect(l, r))
        break;
      case Opcode::UnionPlain:
        FREP_BINARY(hf::unite_plain(l, r))
        break;
      case Opcode::IntersectPlain:
        FREP_BINARY(hf::intersect_plain(l, r))
        break;
      case Opcode::Eq:
      case Opcode::Ne:
      case Opcode::Lt:
      case Opcode::Le:
      case Opcode::Gt:
      case Opcode::Ge:
      case Opcode::Truthy:
      case Opcode::And:
      case Opcode::Or:
      case Opcode::Not:
      case Opcode::Select:
        logic_lanes(ins, side, o, x, y, z, n);
        break;
      case Opcode::ErrorIf:
      {
        const std::uint32_t id = static_cast<std::uint32_t>(ins.index);
        FREP_LANES
        {
          const std::uint32_t e = err[i];
          const bool fires = (e == 0) & (x[i] != 0.0);
          err[i] = fires ? id : e;
        }
        // A block whose every lane has failed has nothing left to compute (its outputs are NaN):
        // the point evaluator stops at the first error too.
        bool all_failed = true;
        for (int i = 0; i < n; ++i)
        {
          all_failed &= err[i] != 0;
        }
        if (all_failed)
        {
          return;
        }
        continue; // writes no slot
      }
      case Opcode::Call:
        call_lanes(tape, ins, blk, calls); // points its output slots at their rows
        continue;
    }
    blk.rows[std::min(ins.out, last)] = o;
  }
}

#undef FREP_BINARY
#undef FREP_LANES

void run_block_baseline(
  const Tape& tape, const BatchProgram& program, const Block& blk, CallState& calls)
{
  run_block_body(tape, program, blk, calls);
}

#if defined(__x86_64__) && defined(__GNUC__)
// AVX2 without FMA: wider lanes, the same operations.
[[gnu::target("avx2")]] void run_block_avx2(
  const Tape& tape, const BatchProgram& program, const Block& blk, CallState& calls)
{
  run_block_body(tape, program, blk, calls);
}

// AVX-512 (8 lanes), again without FMA.
[[gnu::target("avx512f,avx512dq,avx512vl,avx2")]] void run_block_avx512(
  const Tape& tape, const BatchProgram& program, const Block& blk, CallState& calls)
{
  run_block_body(tape, program, blk, calls);
}
#endif

} // namespace

bool cpu_has_avx512()
{
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool has = []
  {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("avx512dq") != 0 &&
      __builtin_cpu_supports("avx512vl") != 0;
  }();
  return has;
#else
  return false;
#endif
}

bool cpu_has_avx2()
{
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool has = []
  {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return has;
#else
  return false;
#endif
}

void run_block(const Tape& tape, const BatchProgram& program, const Block& block,
  CallState& calls, SimdLevel simd)
{
#if defined(__x86_64__) && defined(__GNUC__)
  if (simd >= SimdLevel::AVX512 && cpu_has_avx512())
  {
    run_block_avx512(tape, program, block, calls);
    return;
  }
  if (simd >= SimdLevel::AVX2 && cpu_has_avx2())
  {
    run_block_avx2(tape, program, block, calls);
    return;
  }
#else
  (void)simd;
#endif
  run_block_baseline(tape, program, block, calls);
}

} // namespace frep::eval
