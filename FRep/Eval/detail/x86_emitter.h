// A minimal x86-64 machine-code emitter: exactly the instructions the JIT kernel needs (AVX
// packed-double arithmetic on ymm registers, compares and blends, a few general-purpose moves
// and branches), encoded by hand. Written here rather than taken from asmjit because Debian's
// libasmjit.a is not position-independent and cannot be linked into libFRepKitEngine.so (the
// link fails on its R_X86_64_PC32 relocations), and because a one-pass encoder of ~25
// instructions costs tens of nanoseconds per tape instruction.
// Internal to the evaluators.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace frep::eval::x86
{

/// General-purpose registers by their hardware number.
enum class Gp : std::uint8_t
{
  rax = 0, rcx = 1, rdx = 2, rbx = 3, rsp = 4, rbp = 5, rsi = 6, rdi = 7,
  r8 = 8, r9 = 9, r10 = 10, r11 = 11, r12 = 12, r13 = 13, r14 = 14, r15 = 15
};

/// A memory operand [base + index * scale + disp] (no index when has_index is false).
struct Mem
{
  Gp base = Gp::rax;
  Gp index = Gp::rax;
  bool has_index = false;
  std::uint8_t scale = 1; ///< 1, 2, 4 or 8
  std::int32_t disp = 0;
};

inline Mem ptr(Gp base, std::int32_t disp = 0)
{
  return Mem{ base, Gp::rax, false, 1, disp };
}
inline Mem ptr(Gp base, Gp index, std::uint8_t scale, std::int32_t disp = 0)
{
  return Mem{ base, index, true, scale, disp };
}

/// vcmppd predicates (Intel's _CMP_* numbering).
enum class Cmp : std::uint8_t
{
  EqOQ = 0x00,
  NeqUQ = 0x04, ///< !=, true when unordered (C's x != y)
  LtOQ = 0x11,
  LeOQ = 0x12,
  NgeUQ = 0x19, ///< !(x >= y), true when unordered
  GeOQ = 0x1D,
  GtOQ = 0x1E
};

/// VEX opcodes of the 66.0F map (packed double): dst = src1 op src2 (AndNot: ~src1 & src2).
enum class PdOp : std::uint8_t
{
  Sqrt = 0x51, And = 0x54, AndNot = 0x55, Or = 0x56, Xor = 0x57, Add = 0x58, Mul = 0x59,
  Sub = 0x5C, Min = 0x5D, Div = 0x5E, Max = 0x5F
};

/// Appends encoded instructions to a byte vector. Vector registers are ymm0..15 (xmm for the
/// 128-bit forms). Labels are byte offsets; forward jumps are patched by bind().
class Emitter
{
public:
  std::vector<std::uint8_t>& code() { return code_; }

  // --- AVX, 256-bit, packed double ---
  /// dst = src1 op src2; Sqrt ignores src1.
  void pd(PdOp op, int dst, int src1, int src2);
  void pd(PdOp op, int dst, int src1, const Mem& m);
  /// dst = per lane all ones where cmp(src1, src2) holds, else zero.
  void vcmppd(int dst, int src1, int src2, Cmp predicate);
  void vcmppd(int dst, int src1, const Mem& m, Cmp predicate);
  /// dst = sign of mask's lane ? src2 : src1.
  void vblendvpd(int dst, int src1, int src2, int mask);
  void vblendvpd(int dst, int src1, const Mem& m, int mask);
  /// dst = round(src) with imm8 (9 floor, 10 ceil, 11 trunc, precision exception suppressed).
  void vroundpd(int dst, int src, std::uint8_t imm);
  void vmovupd_load(int dst, const Mem& m);
  void vmovupd_store(const Mem& m, int src);
  /// xmm dst = the four doubles of ymm src converted to int32 with truncation.
  void vcvttpd2dq(int dst, int src);
  /// [m] = xmm src (16 bytes).
  void vmovdqu_store_xmm(const Mem& m, int src);
  /// dst = 0 (vxorpd).
  void zero(int dst);

  // --- general purpose ---
  void push(Gp r);
  void pop(Gp r);
  void mov(Gp dst, Gp src);                 ///< 64-bit
  void mov(Gp dst, const Mem& m);           ///< 64-bit load
  void mov(const Mem& m, Gp src);           ///< 64-bit store
  void mov_imm32(Gp dst, std::uint32_t value); ///< zero-extended
  void mov_imm64(Gp dst, std::uint64_t value);
  void lea(Gp dst, const Mem& m);
  void call(Gp target);                     ///< indirect call through a register
  void add_imm(Gp dst, std::int32_t value); ///< 64-bit
  void sub_imm(Gp dst, std::int32_t value);
  void and_imm(Gp dst, std::int32_t value);
  void cmp(Gp a, Gp b);
  void cmp(Gp a, const Mem& m);
  void cmp_imm(Gp a, std::int32_t value);
  void xor32(Gp dst, Gp src);
  void vzeroupper();
  void ret();

  /// Jumps; the target is a label made by label() and placed by bind().
  int label();
  void bind(int label);
  void jmp(int label);
  void jb(int label); ///< unsigned <
  void jz(int label);

private:
  /// Three-byte VEX prefix, opcode and a register-direct ModRM.
  void vex(std::uint8_t map, std::uint8_t pp, bool w, bool l256, std::uint8_t opcode, int reg,
    int vvvv, int rm);
  void vex_mem(std::uint8_t map, std::uint8_t pp, bool w, bool l256, std::uint8_t opcode, int reg,
    int vvvv, const Mem& m);
  void modrm_mem(int reg, const Mem& m);
  void rex(bool w, int reg, int index, int base);
  void group1(int digit, Gp dst, std::int32_t value);
  void byte(std::uint8_t b)
  {
    // (the caller reserves: code().reserve() before emitting keeps this one store)
    code_.push_back(b);
  }
  void dword(std::uint32_t v);
  void jump(std::uint8_t opcode_first, std::uint8_t opcode_second, int label);

  std::vector<std::uint8_t> code_;
  std::vector<std::int64_t> labels_;                // offset, or -1 while unbound
  std::vector<std::pair<std::size_t, int>> fixups_; // (rel32 position, label)
};

} // namespace frep::eval::x86
