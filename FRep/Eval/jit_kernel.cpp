#include "Eval/detail/jit_kernel.h"

#include "Compiler/detail/op_eval.h"
#include "Eval/detail/batch_kernel.h"
#include "Eval/detail/code_memory.h"
#include "Eval/detail/x86_emitter.h"
#include "Semantics/detail/op_semantics.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <numeric>

#if defined(__x86_64__) && defined(__linux__) && defined(__GNUC__)
#define FREP_JIT_X86_64 1
#endif

namespace frep::eval
{

namespace
{

using x86::Cmp;
using x86::Gp;
using x86::Mem;
using x86::PdOp;

// A pass of the code runs one chunk of 4 lanes, or two interleaved instruction by instruction
// when the tape is latency-bound (a 200-sphere R-union: one union feeds the next), so that
// independent work is in flight. Register plan: ymm0..10 hold the most used slots of the tape
// (one chunk: 11 slots; two: 5 slots each, chunk c in ymm 5c..5c+4), the other slots live in a
// 32-byte-aligned stack frame; ymm11..15 are scratch, shared by the chunks (register renaming
// removes the false dependencies).
constexpr int kMaxChunks = 2;
constexpr int kSlotRegisters = 11;
constexpr int kT0 = 11, kT1 = 12, kT2 = 13, kT4 = 14, kT5 = 15;
constexpr int kVector = 32; // bytes of a ymm register: one chunk of 4 lanes
constexpr int kMaxPower = 16; // HfPowInt up to this |exponent| is straight-line multiplication
constexpr std::size_t kMaxFrameBytes = 256 * 1024;

// The arguments (System V: inputs, outputs, errors, lane count (a multiple of 4), constant
// table) are kept in callee-saved registers, so calls out to libm keep them; the count is in the
// frame.
constexpr Gp kInputs = Gp::rbx;
constexpr Gp kOutputs = Gp::r12;
constexpr Gp kErrors = Gp::r13;
constexpr Gp kLane = Gp::r14; // first lane of the chunk
constexpr Gp kConstants = Gp::r15;

// The frame (32-byte aligned, at rsp): the chunk's error ids (as doubles), the lane count,
// the operands and result of a call out, the slot registers saved across it, spilled slots.
constexpr std::int32_t kFrameErrors = 0; // one vector per chunk
constexpr std::int32_t kFrameCount = kMaxChunks * kVector;
constexpr std::int32_t kFrameA = kFrameCount + kVector;
constexpr std::int32_t kFrameB = kFrameA + kVector;
constexpr std::int32_t kFrameResult = kFrameB + kVector;
constexpr std::int32_t kFrameSaved = kFrameResult + kVector;
constexpr std::int32_t kFrameSpilled = kFrameSaved + kSlotRegisters * kVector; // slot-major

// The constant table (each constant four times, a whole ymm operand) starts with these, then
// the tape's immediates and Const values, and the error ids.
enum FixedConstant : int
{
  kAbsMask,
  kSignMask,
  kEpsilon,
  kOne,
  kZero
};

/// The call out: one chunk of an instruction without vector form, by the scalar definition the
/// point evaluator uses (the same libm calls, so the same bits), one instance per opcode.
template<Opcode Op>
void scalar_chunk(const double* a, const double* b, double* out, std::int64_t index)
{
  for (int i = 0; i < 4; ++i)
  {
    out[i] = semantics::evaluate_op(Op, a[i], b[i], 0.0, static_cast<int>(index));
  }
}

using ScalarChunk = void (*)(const double*, const double*, double*, std::int64_t);

ScalarChunk scalar_chunk_of(Opcode op)
{
  switch (op)
  {
#define FREP_CHUNK(name)                                                                       \
  case Opcode::name:                                                                           \
    return &scalar_chunk<Opcode::name>;
    FREP_CHUNK(Exp)
    FREP_CHUNK(Log)
    FREP_CHUNK(Log10)
    FREP_CHUNK(Sin)
    FREP_CHUNK(Cos)
    FREP_CHUNK(Tan)
    FREP_CHUNK(Asin)
    FREP_CHUNK(Acos)
    FREP_CHUNK(Atan)
    FREP_CHUNK(Sinh)
    FREP_CHUNK(Cosh)
    FREP_CHUNK(Tanh)
    FREP_CHUNK(Atan2)
    FREP_CHUNK(Pow)
    FREP_CHUNK(Frac)
    FREP_CHUNK(Fmod)
    FREP_CHUNK(HfPow)
    FREP_CHUNK(HfPowInt)
    FREP_CHUNK(HfMod)
    FREP_CHUNK(HfRound)
#undef FREP_CHUNK
    default:
      return nullptr;
  }
}

/// Whether the instruction is compiled to vector code (else: a call out per chunk).
bool is_native(const Instruction& ins)
{
  if (ins.op == Opcode::HfPowInt)
  {
    return ins.index >= -kMaxPower && ins.index <= kMaxPower;
  }
  return scalar_chunk_of(ins.op) == nullptr;
}

/// The vector instruction of a binary arithmetic opcode. vmaxpd is src1 > src2 ? src1 : src2 and
/// vminpd src1 < src2 ? src1 : src2: exactly hf_max and hf_min, NaN and signed zeros included.
PdOp binary_pd(Opcode op)
{
  switch (op)
  {
    case Opcode::Add:
      return PdOp::Add;
    case Opcode::Sub:
      return PdOp::Sub;
    case Opcode::Mul:
      return PdOp::Mul;
    case Opcode::Div:
      return PdOp::Div;
    case Opcode::Max:
      return PdOp::Max;
    default:
      return PdOp::Min;
  }
}

/// Chunks per pass: two when the tape's critical path (rough latencies in cycles) is longer
/// than its work (rough throughput cost), i.e. when one chunk would leave the core waiting on a
/// dependent chain; one otherwise (two chunks halve the registers per chunk: more spills).
int chunks_for(const Tape& tape, double* calls_share = nullptr)
{
  const auto cost = [](Opcode op, bool latency)
  {
    switch (op)
    {
      case Opcode::Const:
      case Opcode::Input:
        return 0.0;
      case Opcode::Div:
        return latency ? 13.0 : 4.0;
      case Opcode::Sqrt:
        return latency ? 20.0 : 8.0;
      case Opcode::Union:
      case Opcode::Intersect:
      case Opcode::UnionPlain:
      case Opcode::IntersectPlain:
        return latency ? 40.0 : 12.0;
      default:
        return is_native(Instruction{ op }) ? (latency ? 4.0 : 1.0) : 100.0;
    }
  };
  std::vector<double> ready(std::max<std::size_t>(tape.slot_count, 1), 0.0);
  double path = 0.0;
  double work = 0.0;
  double calls = 0.0; // the part of `work` in calls out
  for (const Instruction& ins : tape.code)
  {
    int reads = operand_count(ins.op);
    double start = 0.0;
    for (const std::uint32_t operand : { ins.a, ins.b, ins.c })
    {
      if (reads-- > 0)
      {
        start = std::max(start, ready[operand]);
      }
    }
    const double done = start + cost(ins.op, true);
    work += cost(ins.op, false);
    calls += is_native(ins) ? 0.0 : cost(ins.op, false);
    if (ins.op != Opcode::ErrorIf)
    {
      ready[ins.out] = done;
    }
    path = std::max(path, done);
  }
  if (calls_share != nullptr)
  {
    *calls_share = work > 0.0 ? calls / work : 0.0;
  }
  return path > work ? 2 : 1;
}

/// An operand: a ymm register, or 32 bytes of memory (a frame slot or a constant's 4 copies).
struct Operand
{
  int reg = -1;
  Mem mem{};
};

/// Translates a tape into machine code in two passes: one to count uses (the registers go to
/// the most used slots), one to emit. Const instructions emit nothing: a slot holding a constant
/// is read straight from the constant table as a memory operand, so constants take no register.
class TapeCompiler
{
public:
  TapeCompiler(const Tape& tape, std::vector<double>& constants)
    : tape_(tape)
    , constants_(constants)
  {
  }

  /// Emits the function, for `chunks` (1 or 2) chunks of 4 lanes per pass; false when its frame
  /// would be too large.
  bool compile(x86::Emitter& e, int chunks, std::size_t& spilled);

private:
  static constexpr int kNoConstant = -1;

  void assign_registers();
  Operand value(std::uint32_t s) const; // the slot's current value: register, frame or constant
  Operand constant(double value);
  static Operand fixed(FixedConstant c);
  Operand table(int index) const;
  int in_register(const Operand& o, int scratch);
  /// The physical register of the slot's register in the current chunk.
  int physical(int reg) const { return reg + chunk_ * registers_per_chunk_; }
  int target(std::uint32_t s) const { return reg_[s] >= 0 ? physical(reg_[s]) : kT0; }
  Mem frame(std::size_t index) const;
  void commit(std::uint32_t s, int reg);
  void arithmetic(PdOp op, int dst, int src1, const Operand& src2);
  void compare(int dst, int src1, const Operand& src2, Cmp predicate);
  void instruction(std::size_t k);
  void r_function(const Instruction& ins, int dst);
  void select(const Instruction& ins, int dst);
  void hf_pow_int(const Instruction& ins, int dst);
  void error_if(const Instruction& ins);
  void call_out(std::size_t k);
  void find_live_registers();

  const Tape& tape_;
  std::vector<double>& constants_;
  x86::Emitter* e_ = nullptr;
  std::vector<int> reg_;   // per slot: ymm register, or -1
  std::vector<int> frame_; // per slot: frame index when not in a register
  std::vector<int> constant_of_; // per instruction: its table index when it is a Const
  std::vector<int> holds_;       // per slot while emitting: the table index of its constant
  std::vector<std::uint32_t> live_at_call_; // per instruction that calls out: registers to keep
  std::vector<std::uint32_t> zero_first_; // slots read before written: 0 at each chunk's start
  std::size_t frame_slots_ = 0;
  int chunk_ = 0; // the chunk being emitted
  int chunks_ = 1; // chunks per pass
  int registers_per_chunk_ = kSlotRegisters;
};

void TapeCompiler::assign_registers()
{
  const std::size_t slots = std::max<std::size_t>(tape_.slot_count, 1);
  std::vector<std::size_t> uses(slots, 0);
  std::vector<unsigned char> written(slots, 0);
  std::vector<unsigned char> constant(slots, 0);
  constant_of_.assign(tape_.code.size(), kNoConstant);
  const auto read = [&](std::uint32_t s)
  {
    if (constant[s])
    {
      return; // read from the table
    }
    ++uses[s];
    if (!written[s])
    {
      written[s] = 1;
      zero_first_.push_back(s);
    }
  };
  for (std::size_t k = 0; k < tape_.code.size(); ++k)
  {
    const Instruction& ins = tape_.code[k];
    const int reads = operand_count(ins.op);
    if (reads >= 1)
    {
      read(ins.a);
    }
    if (reads >= 2)
    {
      read(ins.b);
    }
    if (reads >= 3)
    {
      read(ins.c);
    }
    if (ins.op == Opcode::ErrorIf)
    {
      continue;
    }
    written[ins.out] = 1;
    constant[ins.out] = ins.op == Opcode::Const;
    if (ins.op == Opcode::Const)
    {
      constant_of_[k] = static_cast<int>(constants_.size() / 4);
      constants_.insert(constants_.end(), 4, ins.imm);
    }
    else
    {
      ++uses[ins.out];
    }
  }
  for (std::uint32_t s : tape_.outputs)
  {
    read(s);
  }
  // The most used slots get the registers (the tape's slots are already reused by the
  // compiler's allocator, so a slot's uses span its successive values).
  std::vector<std::uint32_t> order(slots);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y)
    { return uses[x] != uses[y] ? uses[x] > uses[y] : x < y; }); // (no temporary buffer)
  reg_.assign(slots, -1);
  frame_.assign(slots, -1);
  int next = 0;
  for (std::uint32_t s : order)
  {
    if (uses[s] == 0)
    {
      break;
    }
    if (next < registers_per_chunk_)
    {
      reg_[s] = next++;
    }
    else
    {
      frame_[s] = static_cast<int>(frame_slots_++);
    }
  }
  holds_.assign(slots, kNoConstant);
  find_live_registers();
}

// Backward: the slots read after each call out, or by the instruction itself (its other chunks
// run after the first one's call), and its own result (the first chunk's, while the second
// calls out), as a mask of the registers that hold them.
void TapeCompiler::find_live_registers()
{
  live_at_call_.assign(tape_.code.size(), 0);
  std::vector<unsigned char> live(reg_.size(), 0);
  for (std::uint32_t s : tape_.outputs)
  {
    live[s] = 1;
  }
  for (std::size_t k = tape_.code.size(); k-- > 0;)
  {
    const Instruction& ins = tape_.code[k];
    if (ins.op != Opcode::ErrorIf)
    {
      live[ins.out] = 0;
    }
    const int reads = operand_count(ins.op);
    const std::uint32_t operands[3] = { ins.a, ins.b, ins.c };
    for (int r = 0; r < reads; ++r)
    {
      live[operands[r]] = 1;
    }
    if (ins.op != Opcode::ErrorIf && !is_native(ins))
    {
      // With two chunks the first chunk's result is in its register when the second calls out.
      std::uint32_t mask = reg_[ins.out] >= 0 ? 1u << reg_[ins.out] : 0u;
      for (std::size_t s = 0; s < live.size(); ++s)
      {
        if (live[s] && reg_[s] >= 0)
        {
          mask |= 1u << reg_[s];
        }
      }
      live_at_call_[k] = mask;
    }
  }
}

Mem TapeCompiler::frame(std::size_t index) const
{
  return x86::ptr(Gp::rsp,
    kFrameSpilled + static_cast<std::int32_t>(index * static_cast<std::size_t>(chunks_) +
      static_cast<std::size_t>(chunk_)) * kVector);
}

// A call clobbers every ymm register: the slot registers are saved around it, and the
// operands and the result pass through the frame (a spilled or constant operand in place).
void TapeCompiler::call_out(std::size_t k)
{
  const Instruction& ins = tape_.code[k];
  x86::Emitter& e = *e_;
  const auto address_of = [&](std::uint32_t s, std::int32_t scratch, Gp to)
  {
    const Operand o = value(s);
    if (o.reg >= 0)
    {
      e.vmovupd_store(x86::ptr(Gp::rsp, scratch), o.reg);
      e.lea(to, x86::ptr(Gp::rsp, scratch));
    }
    else
    {
      e.lea(to, o.mem);
    }
  };
  const int reads = operand_count(ins.op);
  address_of(ins.a, kFrameA, Gp::rdi);
  address_of(reads >= 2 ? ins.b : ins.a, kFrameB, Gp::rsi);
  const bool into_frame = reg_[ins.out] < 0;
  e.lea(Gp::rdx, into_frame ? frame(static_cast<std::size_t>(frame_[ins.out])) : x86::ptr(Gp::rsp, kFrameResult));
  // Only the registers whose slots are read later (by this instruction's other chunks, or
  // after it) are saved.
  const std::uint32_t live = live_at_call_[k];
  const auto each_live = [&](auto&& f)
  {
    for (int chunk = 0; chunk < chunks_; ++chunk)
    {
      for (int r = 0; r < registers_per_chunk_; ++r)
      {
        if ((live >> r) & 1u)
        {
          f(r + chunk * registers_per_chunk_);
        }
      }
    }
  };
  each_live([&](int r) { e.vmovupd_store(x86::ptr(Gp::rsp, kFrameSaved + r * kVector), r); });
  e.mov_imm64(Gp::rcx, static_cast<std::uint64_t>(static_cast<std::int64_t>(ins.index)));
  e.mov_imm64(Gp::rax, reinterpret_cast<std::uint64_t>(scalar_chunk_of(ins.op)));
  e.vzeroupper(); // no AVX-SSE transition penalty inside libm
  e.call(Gp::rax);
  each_live([&](int r) { e.vmovupd_load(r, x86::ptr(Gp::rsp, kFrameSaved + r * kVector)); });
  if (!into_frame)
  {
    e.vmovupd_load(physical(reg_[ins.out]), x86::ptr(Gp::rsp, kFrameResult));
  }
}

Operand TapeCompiler::value(std::uint32_t s) const
{
  if (holds_[s] != kNoConstant)
  {
    return table(holds_[s]);
  }
  Operand o;
  if (reg_[s] >= 0)
  {
    o.reg = physical(reg_[s]);
  }
  else
  {
    o.mem = frame(static_cast<std::size_t>(frame_[s]));
  }
  return o;
}

Operand TapeCompiler::table(int index) const
{
  Operand o;
  o.mem = x86::ptr(kConstants, index * kVector);
  return o;
}

Operand TapeCompiler::fixed(FixedConstant c)
{
  Operand o;
  o.mem = x86::ptr(kConstants, static_cast<std::int32_t>(c) * kVector);
  return o;
}

Operand TapeCompiler::constant(double value)
{
  const std::size_t index = constants_.size() / 4;
  constants_.insert(constants_.end(), 4, value);
  return table(static_cast<int>(index));
}

int TapeCompiler::in_register(const Operand& o, int scratch)
{
  if (o.reg >= 0)
  {
    return o.reg;
  }
  e_->vmovupd_load(scratch, o.mem);
  return scratch;
}

void TapeCompiler::commit(std::uint32_t s, int reg)
{
  if (reg_[s] < 0)
  {
    e_->vmovupd_store(frame(static_cast<std::size_t>(frame_[s])), reg);
  }
}

void TapeCompiler::arithmetic(PdOp op, int dst, int src1, const Operand& src2)
{
  if (src2.reg >= 0)
  {
    e_->pd(op, dst, src1, src2.reg);
  }
  else
  {
    e_->pd(op, dst, src1, src2.mem);
  }
}

void TapeCompiler::compare(int dst, int src1, const Operand& src2, Cmp predicate)
{
  if (src2.reg >= 0)
  {
    e_->vcmppd(dst, src1, src2.reg, predicate);
  }
  else
  {
    e_->vcmppd(dst, src1, src2.mem, predicate);
  }
}

// Each case writes its destination register only with its last machine instruction, so a
// destination that is also an operand's register is read before it is overwritten.
// The longer cases of instruction(), each writing `dst` only with its last machine instruction.

/// The R-functions.
void TapeCompiler::r_function(const Instruction& ins, int dst)
{
  x86::Emitter& e = *e_;
  // (l + r) ± sqrt(|l*l + r*r - 0*r*l|) in the original's order; the plain forms have no
  // 0*r*l term and no fabs; the R-functions' final 1.0 * (...) is the identity on doubles.
  const bool plain = ins.op == Opcode::UnionPlain || ins.op == Opcode::IntersectPlain;
  const bool unite = ins.op == Opcode::Union || ins.op == Opcode::UnionPlain;
  const int l = in_register(value(ins.a), kT4);
  const int r = in_register(value(ins.b), kT5);
  e.pd(PdOp::Add, kT0, l, r);
  e.pd(PdOp::Mul, kT1, l, l);
  e.pd(PdOp::Mul, kT2, r, r);
  e.pd(PdOp::Add, kT1, kT1, kT2);
  if (!plain)
  {
    arithmetic(PdOp::Mul, kT2, r, fixed(kZero)); // 0.0 * r (exact either way round)
    e.pd(PdOp::Mul, kT2, kT2, l);
    e.pd(PdOp::Sub, kT1, kT1, kT2);
    arithmetic(PdOp::And, kT1, kT1, fixed(kAbsMask));
  }
  e.pd(PdOp::Sqrt, kT1, 0, kT1);
  e.pd(unite ? PdOp::Add : PdOp::Sub, dst, kT0, kT1);
}

/// a != 0 ? b : c, true for NaN as in C.
void TapeCompiler::select(const Instruction& ins, int dst)
{
  x86::Emitter& e = *e_;
  compare(kT0, in_register(value(ins.a), kT4), fixed(kZero), Cmp::NeqUQ);
  const int otherwise = in_register(value(ins.c), kT5);
  const Operand chosen = value(ins.b);
  if (chosen.reg >= 0)
  {
    e.vblendvpd(dst, otherwise, chosen.reg, kT0);
  }
  else
  {
    e.vblendvpd(dst, otherwise, chosen.mem, kT0);
  }
}

/// hf_pow_int: v = 1.0, v *= b |n| times, 1 / v for n < 0; 0 where |b| < EPS.
void TapeCompiler::hf_pow_int(const Instruction& ins, int dst)
{
  x86::Emitter& e = *e_;
  const int base = in_register(value(ins.a), kT4);
  e.vmovupd_load(kT0, fixed(kOne).mem);
  const int n = ins.index < 0 ? -ins.index : ins.index;
  for (int i = 0; i < n; ++i)
  {
    e.pd(PdOp::Mul, kT0, kT0, base);
  }
  if (ins.index < 0)
  {
    e.vmovupd_load(kT1, fixed(kOne).mem);
    e.pd(PdOp::Div, kT0, kT1, kT0);
  }
  arithmetic(PdOp::And, kT2, base, fixed(kAbsMask));
  compare(kT2, kT2, fixed(kEpsilon), Cmp::LtOQ);
  e.pd(PdOp::AndNot, dst, kT2, kT0); // +0.0 where |b| < EPS
}

/// ErrorIf: lanes where a != 0 and no error yet take this error id (held as a double); writes no
/// slot.
void TapeCompiler::error_if(const Instruction& ins)
{
  x86::Emitter& e = *e_;
  compare(kT0, in_register(value(ins.a), kT4), fixed(kZero), Cmp::NeqUQ);
  const Mem errors = x86::ptr(Gp::rsp, kFrameErrors + chunk_ * kVector);
  e.vmovupd_load(kT1, errors);
  compare(kT2, kT1, fixed(kZero), Cmp::EqOQ);
  e.pd(PdOp::And, kT0, kT0, kT2);
  e.vblendvpd(kT1, kT1, constant(static_cast<double>(ins.index)).mem, kT0);
  e.vmovupd_store(errors, kT1);
}

void TapeCompiler::instruction(std::size_t k)
{
  x86::Emitter& e = *e_;
  const Instruction& ins = tape_.code[k];
  if (ins.op == Opcode::Const)
  {
    return; // no code: readers take it from the table (holds_)
  }
  if (!is_native(ins))
  {
    call_out(k);
    return;
  }
  const int dst = target(ins.out);
  const auto operand = [&](int which)
  { return value(which == 0 ? ins.a : (which == 1 ? ins.b : ins.c)); };
  const auto a = [&](int scratch) { return in_register(operand(0), scratch); };
  const auto b = [&](int scratch) { return in_register(operand(1), scratch); };
  // mask (all ones / zero per lane) -> 1.0 / 0.0
  const auto boolean = [&](int mask) { arithmetic(PdOp::And, dst, mask, fixed(kOne)); };
  switch (ins.op)
  {
    case Opcode::Input:
      e.mov(Gp::rax, x86::ptr(kInputs, ins.index * 8));
      e.vmovupd_load(dst, x86::ptr(Gp::rax, kLane, 8, chunk_ * kVector));
      break;
    case Opcode::Add:
    case Opcode::Sub:
    case Opcode::Mul:
    case Opcode::Div:
    case Opcode::Max:
    case Opcode::Min:
      arithmetic(binary_pd(ins.op), dst, a(kT4), operand(1));
      break;
    case Opcode::Neg:
      arithmetic(PdOp::Xor, dst, a(kT4), fixed(kSignMask));
      break;
    case Opcode::Abs:
      arithmetic(PdOp::And, dst, a(kT4), fixed(kAbsMask));
      break;
    case Opcode::Square:
    {
      const int x = a(kT4);
      e.pd(PdOp::Mul, dst, x, x);
      break;
    }
    case Opcode::Sqrt:
      e.pd(PdOp::Sqrt, dst, 0, a(kT4));
      break;
    case Opcode::Floor:
      e.vroundpd(dst, a(kT4), 0x09); // toward -inf, precision exception suppressed
      break;
    case Opcode::Ceil:
      e.vroundpd(dst, a(kT4), 0x0A);
      break;
    case Opcode::Trunc:
      e.vroundpd(dst, a(kT4), 0x0B);
      break;
    case Opcode::Union:
    case Opcode::Intersect:
    case Opcode::UnionPlain:
    case Opcode::IntersectPlain:
      r_function(ins, dst);
      break;
    case Opcode::Eq:
    case Opcode::Ne:
      arithmetic(PdOp::Sub, kT0, a(kT4), operand(1));
      arithmetic(PdOp::And, kT0, kT0, fixed(kAbsMask));
      compare(kT0, kT0, fixed(kEpsilon), ins.op == Opcode::Eq ? Cmp::LtOQ : Cmp::GeOQ);
      boolean(kT0);
      break;
    case Opcode::Lt:
    case Opcode::Le:
    case Opcode::Gt:
    case Opcode::Ge:
    {
      const Cmp predicate = ins.op == Opcode::Lt ? Cmp::LtOQ
        : ins.op == Opcode::Le                   ? Cmp::LeOQ
        : ins.op == Opcode::Gt                   ? Cmp::GtOQ
                                                 : Cmp::GeOQ;
      compare(kT0, a(kT4), operand(1), predicate);
      boolean(kT0);
      break;
    }
    case Opcode::Truthy:
    case Opcode::Not:
      arithmetic(PdOp::And, kT0, a(kT4), fixed(kAbsMask));
      compare(kT0, kT0, fixed(kEpsilon), ins.op == Opcode::Truthy ? Cmp::GeOQ : Cmp::NgeUQ);
      boolean(kT0);
      break;
    case Opcode::And:
    case Opcode::Or:
      arithmetic(PdOp::And, kT0, a(kT4), fixed(kAbsMask));
      compare(kT0, kT0, fixed(kEpsilon), Cmp::GeOQ);
      arithmetic(PdOp::And, kT1, b(kT5), fixed(kAbsMask));
      compare(kT1, kT1, fixed(kEpsilon), Cmp::GeOQ);
      e.pd(ins.op == Opcode::And ? PdOp::And : PdOp::Or, kT0, kT0, kT1);
      boolean(kT0);
      break;
    case Opcode::Select:
      select(ins, dst);
      break;
    case Opcode::HfPowInt:
      hf_pow_int(ins, dst);
      break;
    case Opcode::ErrorIf:
      error_if(ins);
      return; // writes no slot
    default:
      return; // not reached: jit_supports() refused the tape
  }
  commit(ins.out, dst);
}

bool TapeCompiler::compile(x86::Emitter& e, int chunks, std::size_t& spilled)
{
  e_ = &e;
  chunks_ = chunks;
  registers_per_chunk_ = kSlotRegisters / chunks;
  e.code().reserve(tape_.code.size() * 16 + 256);
  assign_registers();
  spilled = frame_slots_;
  const std::size_t frame_bytes =
    static_cast<std::size_t>(kFrameSpilled) + frame_slots_ * static_cast<std::size_t>(chunks_) * kVector;
  if (frame_bytes > kMaxFrameBytes)
  {
    return false;
  }
  // prologue: the callee-saved registers, the arguments moved into them, a 32-byte-aligned
  // frame under rbp
  e.push(Gp::rbp);
  e.mov(Gp::rbp, Gp::rsp);
  for (const Gp r : { Gp::rbx, Gp::r12, Gp::r13, Gp::r14, Gp::r15 })
  {
    e.push(r);
  }
  e.and_imm(Gp::rsp, -kVector);
  e.sub_imm(Gp::rsp, static_cast<std::int32_t>(frame_bytes));
  e.mov(kInputs, Gp::rdi);
  e.mov(kOutputs, Gp::rsi);
  e.mov(kErrors, Gp::rdx);
  e.mov(x86::ptr(Gp::rsp, kFrameCount), Gp::rcx);
  e.mov(kConstants, Gp::r8);
  const int done = e.label();
  e.cmp_imm(Gp::rcx, 0);
  e.jz(done);
  e.xor32(kLane, kLane);
  const int chunk = e.label();
  e.bind(chunk);
  for (chunk_ = 0; chunk_ < chunks_; ++chunk_)
  {
    if (tape_.can_fail)
    {
      e.zero(kT0);
      e.vmovupd_store(x86::ptr(Gp::rsp, kFrameErrors + chunk_ * kVector), kT0);
    }
    for (std::uint32_t s : zero_first_)
    {
      // a slot read before any instruction writes it reads 0, as in the interpreters
      e.zero(target(s));
      commit(s, target(s));
    }
  }
  std::fill(holds_.begin(), holds_.end(), kNoConstant);
  for (std::size_t k = 0; k < tape_.code.size(); ++k)
  {
    for (chunk_ = 0; chunk_ < chunks_; ++chunk_)
    {
      instruction(k);
    }
    // after every chunk's copy: an instruction may overwrite a constant slot it reads
    const Instruction& ins = tape_.code[k];
    if (ins.op != Opcode::ErrorIf)
    {
      holds_[ins.out] = ins.op == Opcode::Const ? constant_of_[k] : kNoConstant;
    }
  }
  for (chunk_ = 0; chunk_ < chunks_; ++chunk_)
  {
    for (std::size_t j = 0; j < tape_.outputs.size(); ++j)
    {
      const int value = in_register(this->value(tape_.outputs[j]), kT0);
      e.mov(Gp::rax, x86::ptr(kOutputs, static_cast<std::int32_t>(j * 8)));
      e.vmovupd_store(x86::ptr(Gp::rax, kLane, 8, chunk_ * kVector), value);
    }
    if (tape_.can_fail)
    {
      e.vmovupd_load(kT0, x86::ptr(Gp::rsp, kFrameErrors + chunk_ * kVector));
      e.vcvttpd2dq(kT0, kT0); // error ids are small integers: exact
      e.vmovdqu_store_xmm(x86::ptr(kErrors, kLane, 4, chunk_ * 16), kT0);
    }
  }
  chunk_ = 0;
  e.add_imm(kLane, 4 * chunks_);
  e.cmp(kLane, x86::ptr(Gp::rsp, kFrameCount));
  e.jb(chunk);
  e.bind(done);
  e.lea(Gp::rsp, x86::ptr(Gp::rbp, -5 * 8));
  for (const Gp r : { Gp::r15, Gp::r14, Gp::r13, Gp::r12, Gp::rbx })
  {
    e.pop(r);
  }
  e.pop(Gp::rbp);
  e.vzeroupper();
  e.ret();
  return true;
}

} // namespace

bool jit_available()
{
#if defined(FREP_JIT_X86_64)
  return cpu_has_avx2(); // the interpreter's own CPU check
#else
  return false;
#endif
}

bool jit_pays(const Tape& tape)
{
  // Mostly libm: the interpreter calls it in tight loops over whole blocks, which beats a call
  // out per chunk (measured: s4_gyroid 9.0 vs 7.8 M points/s, hello_world 0.70 vs 0.34).
  double calls_share = 0.0;
  chunks_for(tape, &calls_share);
  return calls_share <= 0.5;
}

bool jit_supports(const Tape& tape)
{
  return tape.calls.empty(); // an opaque function may keep state per evaluator
}

std::shared_ptr<const JitKernel> JitKernel::compile(const Tape& tape)
{
  std::shared_ptr<CodeMemory> memory;
  return compile(tape, memory);
}

std::shared_ptr<const JitKernel> JitKernel::compile(const Tape& tape,
  std::shared_ptr<CodeMemory>& memory)
{
#if defined(FREP_JIT_X86_64)
  if (!jit_available() || !jit_supports(tape))
  {
    return nullptr;
  }
  std::shared_ptr<JitKernel> kernel(new JitKernel());
  std::vector<double>& table = kernel->constants_;
  for (const double v : { std::bit_cast<double>(~(std::uint64_t{ 1 } << 63)),
         std::bit_cast<double>(std::uint64_t{ 1 } << 63), semantics::kEps, 1.0, 0.0 })
  {
    table.insert(table.end(), 4, v); // kAbsMask, kSignMask, kEpsilon, kOne, kZero
  }
  x86::Emitter emitter;
  TapeCompiler compiler(tape, kernel->constants_);
  const int chunks = chunks_for(tape);
  kernel->lanes_ = 4 * static_cast<std::size_t>(chunks);
  if (!compiler.compile(emitter, chunks, kernel->spilled_))
  {
    return nullptr;
  }
  const std::vector<std::uint8_t>& code = emitter.code();
  // (use_count 1: only the caller holds it, so no kernel runs from it any more)
  if (!memory || memory.use_count() != 1 || memory->capacity() < code.size())
  {
    memory = CodeMemory::make(code.size());
  }
  if (!memory || !memory->load(code))
  {
    return nullptr;
  }
  kernel->inputs_ = tape.input_count;
  kernel->outputs_ = tape.outputs.size();
  kernel->memory_ = memory;
  kernel->code_size_ = code.size();
  kernel->function_ = reinterpret_cast<Function>(const_cast<void*>(memory->entry()));
  return kernel;
#else
  (void)tape;
  (void)memory;
  return nullptr;
#endif
}

JitKernel::~JitKernel() = default;

void JitKernel::run(const double* const* inputs, double* const* outputs, std::uint32_t* errors,
  std::size_t n) const
{
  const std::size_t full = n / lanes_ * lanes_;
  if (full > 0)
  {
    function_(inputs, outputs, errors, full, constants_.data());
  }
  const std::size_t rest = n - full;
  if (rest == 0)
  {
    return;
  }
  // The last lanes go through one chunk of buffers: the code reads and writes whole chunks.
  std::vector<double> in(inputs_ * kMaxLanes, 0.0);
  std::vector<double> out(outputs_ * kMaxLanes, 0.0);
  std::vector<const double*> in_rows(inputs_);
  std::vector<double*> out_rows(outputs_);
  std::uint32_t tail_errors[kMaxLanes] = {};
  for (std::size_t k = 0; k < inputs_; ++k)
  {
    std::copy(inputs[k] + full, inputs[k] + n, in.begin() + static_cast<std::ptrdiff_t>(k * kMaxLanes));
    in_rows[k] = in.data() + k * kMaxLanes;
  }
  for (std::size_t j = 0; j < outputs_; ++j)
  {
    out_rows[j] = out.data() + j * kMaxLanes;
  }
  function_(in_rows.data(), out_rows.data(), tail_errors, lanes_, constants_.data());
  for (std::size_t j = 0; j < outputs_; ++j)
  {
    std::copy(out_rows[j], out_rows[j] + rest, outputs[j] + full);
  }
  if (errors != nullptr)
  {
    std::copy(tail_errors, tail_errors + rest, errors + full);
  }
}

void LazyKernel::reset()
{
  kernel_.reset(); // (its memory is reused by the next kernel once nothing else holds it)
  samples_ = 0;
  tried_ = false;
}

const std::shared_ptr<const JitKernel>& LazyKernel::get(const Tape& tape, std::size_t samples)
{
  samples_ += samples;
  if (!tried_ && samples_ >= kWorthSamples)
  {
    tried_ = true;
    if (jit_pays(tape))
    {
      // Whichever memory only this object holds now (the other may be a runner's old kernel's).
      std::shared_ptr<CodeMemory>& memory =
        memory_[0] && memory_[0].use_count() != 1 ? memory_[1] : memory_[0];
      kernel_ = JitKernel::compile(tape, memory);
    }
  }
  return kernel_;
}

} // namespace frep::eval
