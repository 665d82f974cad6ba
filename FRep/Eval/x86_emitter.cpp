// Encodings from the Intel SDM, volume 2 (VEX: 2.3.5; ModRM/SIB: 2.1.5). Every memory operand
// uses a 32-bit displacement (mod = 10): one form for all, at a few bytes of code size.
#include "Eval/detail/x86_emitter.h"


namespace frep::eval::x86
{

namespace
{

constexpr std::uint8_t kMap0F = 1;
constexpr std::uint8_t kMap0F3A = 3;
constexpr std::uint8_t kPp66 = 1;
constexpr std::uint8_t kPpF3 = 2;

int code_of(Gp r)
{
  return static_cast<int>(r);
}

std::uint8_t scale_bits(std::uint8_t scale)
{
  // 1, 2, 4, 8 -> 0, 1, 2, 3
  return static_cast<std::uint8_t>(scale >= 8 ? 3 : (scale >= 4 ? 2 : (scale >= 2 ? 1 : 0)));
}

} // namespace

void Emitter::dword(std::uint32_t v)
{
  const std::uint8_t bytes[4] = { static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8),
    static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 24) };
  code_.insert(code_.end(), bytes, bytes + 4);
}

// Three-byte VEX: C4, [R X B m-mmmm] (R, X, B inverted), [W vvvv L pp] (vvvv inverted).
void Emitter::vex(std::uint8_t map, std::uint8_t pp, bool w, bool l256, std::uint8_t opcode, int reg,
  int vvvv, int rm)
{
  byte(0xC4);
  byte(static_cast<std::uint8_t>(((reg & 8) ? 0 : 0x80) | 0x40 | ((rm & 8) ? 0 : 0x20) | map));
  byte(static_cast<std::uint8_t>((w ? 0x80 : 0) | ((~vvvv & 0xF) << 3) | (l256 ? 0x04 : 0) | pp));
  byte(opcode);
  byte(static_cast<std::uint8_t>(0xC0 | ((reg & 7) << 3) | (rm & 7)));
}

void Emitter::modrm_mem(int reg, const Mem& m)
{
  const int base = code_of(m.base);
  if (!m.has_index && (base & 7) != 4)
  {
    byte(static_cast<std::uint8_t>(0x80 | ((reg & 7) << 3) | (base & 7)));
  }
  else
  {
    byte(static_cast<std::uint8_t>(0x80 | ((reg & 7) << 3) | 4));
    const int index = m.has_index ? code_of(m.index) : 4; // 100: no index
    byte(static_cast<std::uint8_t>((scale_bits(m.scale) << 6) | ((index & 7) << 3) | (base & 7)));
  }
  dword(static_cast<std::uint32_t>(m.disp));
}

void Emitter::vex_mem(std::uint8_t map, std::uint8_t pp, bool w, bool l256, std::uint8_t opcode,
  int reg, int vvvv, const Mem& m)
{
  const int base = code_of(m.base);
  const int index = m.has_index ? code_of(m.index) : 0;
  byte(0xC4);
  byte(static_cast<std::uint8_t>(((reg & 8) ? 0 : 0x80) | ((index & 8) ? 0 : 0x40) |
    ((base & 8) ? 0 : 0x20) | map));
  byte(static_cast<std::uint8_t>((w ? 0x80 : 0) | ((~vvvv & 0xF) << 3) | (l256 ? 0x04 : 0) | pp));
  byte(opcode);
  modrm_mem(reg, m);
}

void Emitter::pd(PdOp op, int dst, int src1, int src2)
{
  vex(kMap0F, kPp66, false, true, static_cast<std::uint8_t>(op), dst, op == PdOp::Sqrt ? 0 : src1, src2);
}

void Emitter::pd(PdOp op, int dst, int src1, const Mem& m)
{
  vex_mem(kMap0F, kPp66, false, true, static_cast<std::uint8_t>(op), dst, op == PdOp::Sqrt ? 0 : src1, m);
}

void Emitter::vcmppd(int dst, int src1, int src2, Cmp predicate)
{
  vex(kMap0F, kPp66, false, true, 0xC2, dst, src1, src2);
  byte(static_cast<std::uint8_t>(predicate));
}

void Emitter::vcmppd(int dst, int src1, const Mem& m, Cmp predicate)
{
  vex_mem(kMap0F, kPp66, false, true, 0xC2, dst, src1, m);
  byte(static_cast<std::uint8_t>(predicate));
}

void Emitter::vblendvpd(int dst, int src1, int src2, int mask)
{
  vex(kMap0F3A, kPp66, false, true, 0x4B, dst, src1, src2);
  byte(static_cast<std::uint8_t>(mask << 4)); // is4: the mask register in bits 7:4
}

void Emitter::vblendvpd(int dst, int src1, const Mem& m, int mask)
{
  vex_mem(kMap0F3A, kPp66, false, true, 0x4B, dst, src1, m);
  byte(static_cast<std::uint8_t>(mask << 4));
}

void Emitter::vroundpd(int dst, int src, std::uint8_t imm)
{
  vex(kMap0F3A, kPp66, false, true, 0x09, dst, 0, src);
  byte(imm);
}

void Emitter::vmovupd_load(int dst, const Mem& m)
{
  vex_mem(kMap0F, kPp66, false, true, 0x10, dst, 0, m);
}

void Emitter::vmovupd_store(const Mem& m, int src)
{
  vex_mem(kMap0F, kPp66, false, true, 0x11, src, 0, m);
}

void Emitter::vcvttpd2dq(int dst, int src)
{
  vex(kMap0F, kPp66, false, true, 0xE6, dst, 0, src);
}

void Emitter::vmovdqu_store_xmm(const Mem& m, int src)
{
  vex_mem(kMap0F, kPpF3, false, false, 0x7F, src, 0, m);
}

void Emitter::zero(int dst)
{
  pd(PdOp::Xor, dst, dst, dst);
}

void Emitter::rex(bool w, int reg, int index, int base)
{
  const std::uint8_t r = static_cast<std::uint8_t>(0x40 | (w ? 8 : 0) | ((reg & 8) ? 4 : 0) |
    ((index & 8) ? 2 : 0) | ((base & 8) ? 1 : 0));
  if (r != 0x40)
  {
    byte(r);
  }
}

void Emitter::push(Gp r)
{
  rex(false, 0, 0, code_of(r));
  byte(static_cast<std::uint8_t>(0x50 | (code_of(r) & 7)));
}

void Emitter::pop(Gp r)
{
  rex(false, 0, 0, code_of(r));
  byte(static_cast<std::uint8_t>(0x58 | (code_of(r) & 7)));
}

void Emitter::mov(Gp dst, Gp src)
{
  rex(true, code_of(src), 0, code_of(dst));
  byte(0x89);
  byte(static_cast<std::uint8_t>(0xC0 | ((code_of(src) & 7) << 3) | (code_of(dst) & 7)));
}

void Emitter::mov(Gp dst, const Mem& m)
{
  rex(true, code_of(dst), m.has_index ? code_of(m.index) : 0, code_of(m.base));
  byte(0x8B);
  modrm_mem(code_of(dst), m);
}

void Emitter::mov(const Mem& m, Gp src)
{
  rex(true, code_of(src), m.has_index ? code_of(m.index) : 0, code_of(m.base));
  byte(0x89);
  modrm_mem(code_of(src), m);
}

void Emitter::mov_imm32(Gp dst, std::uint32_t value)
{
  rex(false, 0, 0, code_of(dst));
  byte(static_cast<std::uint8_t>(0xB8 | (code_of(dst) & 7)));
  dword(value);
}

void Emitter::mov_imm64(Gp dst, std::uint64_t value)
{
  rex(true, 0, 0, code_of(dst));
  byte(static_cast<std::uint8_t>(0xB8 | (code_of(dst) & 7)));
  dword(static_cast<std::uint32_t>(value));
  dword(static_cast<std::uint32_t>(value >> 32));
}

void Emitter::lea(Gp dst, const Mem& m)
{
  rex(true, code_of(dst), m.has_index ? code_of(m.index) : 0, code_of(m.base));
  byte(0x8D);
  modrm_mem(code_of(dst), m);
}

void Emitter::call(Gp target)
{
  rex(false, 0, 0, code_of(target));
  byte(0xFF);
  byte(static_cast<std::uint8_t>(0xD0 | (code_of(target) & 7))); // FF /2
}

void Emitter::cmp(Gp a, const Mem& m)
{
  rex(true, code_of(a), m.has_index ? code_of(m.index) : 0, code_of(m.base));
  byte(0x3B);
  modrm_mem(code_of(a), m);
}

// REX.W 81 /digit id
void Emitter::group1(int digit, Gp dst, std::int32_t value)
{
  rex(true, 0, 0, code_of(dst));
  byte(0x81);
  byte(static_cast<std::uint8_t>(0xC0 | (digit << 3) | (code_of(dst) & 7)));
  dword(static_cast<std::uint32_t>(value));
}

void Emitter::add_imm(Gp dst, std::int32_t value)
{
  group1(0, dst, value);
}

void Emitter::sub_imm(Gp dst, std::int32_t value)
{
  group1(5, dst, value);
}

void Emitter::and_imm(Gp dst, std::int32_t value)
{
  group1(4, dst, value);
}

void Emitter::cmp_imm(Gp a, std::int32_t value)
{
  group1(7, a, value);
}

void Emitter::cmp(Gp a, Gp b)
{
  rex(true, code_of(b), 0, code_of(a));
  byte(0x39);
  byte(static_cast<std::uint8_t>(0xC0 | ((code_of(b) & 7) << 3) | (code_of(a) & 7)));
}

void Emitter::xor32(Gp dst, Gp src)
{
  rex(false, code_of(src), 0, code_of(dst));
  byte(0x31);
  byte(static_cast<std::uint8_t>(0xC0 | ((code_of(src) & 7) << 3) | (code_of(dst) & 7)));
}

void Emitter::vzeroupper()
{
  byte(0xC5);
  byte(0xF8);
  byte(0x77);
}

void Emitter::ret()
{
  byte(0xC3);
}

int Emitter::label()
{
  labels_.push_back(-1);
  return static_cast<int>(labels_.size() - 1);
}

void Emitter::bind(int label)
{
  labels_[static_cast<std::size_t>(label)] = static_cast<std::int64_t>(code_.size());
  for (const auto& [at, target] : fixups_)
  {
    if (target == label)
    {
      const std::int64_t rel = static_cast<std::int64_t>(code_.size()) - static_cast<std::int64_t>(at + 4);
      for (int i = 0; i < 4; ++i)
      {
        code_[at + static_cast<std::size_t>(i)] =
          static_cast<std::uint8_t>(static_cast<std::uint32_t>(rel) >> (8 * i));
      }
    }
  }
}

void Emitter::jump(std::uint8_t opcode_first, std::uint8_t opcode_second, int label)
{
  byte(opcode_first);
  if (opcode_second != 0)
  {
    byte(opcode_second);
  }
  const std::int64_t target = labels_[static_cast<std::size_t>(label)];
  if (target >= 0)
  {
    dword(static_cast<std::uint32_t>(target - static_cast<std::int64_t>(code_.size() + 4)));
  }
  else
  {
    fixups_.emplace_back(code_.size(), label);
    dword(0);
  }
}

void Emitter::jmp(int label)
{
  jump(0xE9, 0, label);
}

void Emitter::jb(int label)
{
  jump(0x0F, 0x82, label);
}

void Emitter::jz(int label)
{
  jump(0x0F, 0x84, label);
}

} // namespace frep::eval::x86
