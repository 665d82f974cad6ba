// The x86 encoder against golden encodings: each row's bytes were checked by disassembling them
// with GNU objdump (binutils 2.40, `objdump -D -b binary -mi386:x86-64 -M intel`), which printed
// the row's name. Covers every operand form the JIT uses: high registers (REX/VEX extension
// bits), rsp/r12 bases (SIB), rbp/r13 bases, index registers, immediates, is4 operands.
#include "Eval/detail/x86_emitter.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

namespace frep::eval::x86
{
namespace
{

std::string hex(const std::vector<std::uint8_t>& bytes)
{
  std::string out;
  char b[4];
  for (std::size_t i = 0; i < bytes.size(); ++i)
  {
    std::snprintf(b, sizeof b, i ? " %02x" : "%02x", bytes[i]);
    out += b;
  }
  return out;
}

struct Golden
{
  const char* instruction;
  std::function<void(Emitter&)> emit;
  const char* bytes;
};

TEST(X86Emitter, EncodesLikeObjdumpDecodes)
{
  const Golden rows[] = {
    { "vaddpd ymm0,ymm1,ymm2", [](Emitter& e) { e.pd(PdOp::Add, 0, 1, 2); }, "c4 e1 75 58 c2" },
    { "vsubpd ymm9,ymm15,ymm3", [](Emitter& e) { e.pd(PdOp::Sub, 9, 15, 3); }, "c4 61 05 5c cb" },
    { "vsqrtpd ymm11,ymm12", [](Emitter& e) { e.pd(PdOp::Sqrt, 11, 0, 12); }, "c4 41 7d 51 dc" },
    { "vmulpd ymm8,ymm14,[r8+0x20]", [](Emitter& e) { e.pd(PdOp::Mul, 8, 14, ptr(Gp::r8, 32)); }, "c4 41 0d 59 80 20 00 00 00" },
    { "vdivpd ymm10,ymm3,[rsp+0x80]", [](Emitter& e) { e.pd(PdOp::Div, 10, 3, ptr(Gp::rsp, 128)); }, "c4 61 65 5e 94 24 80 00 00 00" },
    { "vmaxpd ymm1,ymm10,[r13+0x40]", [](Emitter& e) { e.pd(PdOp::Max, 1, 10, ptr(Gp::r13, 64)); }, "c4 c1 2d 5f 8d 40 00 00 00" },
    { "vcmplt_oqpd ymm2,ymm3,ymm4", [](Emitter& e) { e.vcmppd(2, 3, 4, Cmp::LtOQ); }, "c4 e1 65 c2 d4 11" },
    { "vcmpnge_uqpd ymm13,ymm9,[r8+0x40]", [](Emitter& e) { e.vcmppd(13, 9, ptr(Gp::r8, 64), Cmp::NgeUQ); }, "c4 41 35 c2 a8 40 00 00 00 19" },
    { "vblendvpd ymm4,ymm5,ymm11,ymm12", [](Emitter& e) { e.vblendvpd(4, 5, 11, 12); }, "c4 c3 55 4b e3 c0" },
    { "vroundpd ymm7,ymm13,0x9", [](Emitter& e) { e.vroundpd(7, 13, 9); }, "c4 c3 7d 09 fd 09" },
    { "vmovupd ymm3,[rax+r10*8]", [](Emitter& e) { e.vmovupd_load(3, ptr(Gp::rax, Gp::r10, 8)); }, "c4 a1 7d 10 9c d0 00 00 00 00" },
    { "vmovupd [rax+r14*8+0x20],ymm14", [](Emitter& e) { e.vmovupd_store(ptr(Gp::rax, Gp::r14, 8, 32), 14); }, "c4 21 7d 11 b4 f0 20 00 00 00" },
    { "vcvttpd2dq xmm11,ymm12", [](Emitter& e) { e.vcvttpd2dq(11, 12); }, "c4 41 7d e6 dc" },
    { "vmovdqu [r13+r14*4+0x10],xmm11", [](Emitter& e) { e.vmovdqu_store_xmm(ptr(Gp::r13, Gp::r14, 4, 16), 11); }, "c4 01 7a 7f 9c b5 10 00 00 00" },
    { "mov [rsp+0x40],rcx", [](Emitter& e) { e.mov(ptr(Gp::rsp, 64), Gp::rcx); }, "48 89 8c 24 40 00 00 00" },
    { "mov rax,[r12+0x10]", [](Emitter& e) { e.mov(Gp::rax, ptr(Gp::r12, 16)); }, "49 8b 84 24 10 00 00 00" },
    { "movabs rax,0x1122334455667788", [](Emitter& e) { e.mov_imm64(Gp::rax, 0x1122334455667788ull); }, "48 b8 88 77 66 55 44 33 22 11" },
    { "lea rsp,[rbp-0x28]", [](Emitter& e) { e.lea(Gp::rsp, ptr(Gp::rbp, -40)); }, "48 8d a5 d8 ff ff ff" },
    { "call rax", [](Emitter& e) { e.call(Gp::rax); }, "ff d0" },
    { "cmp r14,[rsp+0x40]", [](Emitter& e) { e.cmp(Gp::r14, ptr(Gp::rsp, 64)); }, "4c 3b b4 24 40 00 00 00" },
    { "push r15", [](Emitter& e) { e.push(Gp::r15); }, "41 57" },
    { "and rsp,-32", [](Emitter& e) { e.and_imm(Gp::rsp, -32); }, "48 81 e4 e0 ff ff ff" },
  };
  for (const Golden& row : rows)
  {
    Emitter e;
    row.emit(e);
    EXPECT_EQ(hex(e.code()), row.bytes) << row.instruction;
  }
}

TEST(X86Emitter, ForwardAndBackwardJumpsArePatched)
{
  Emitter e;
  const int back = e.label();
  e.bind(back);
  e.jb(back); // to itself: rel32 = -6
  const int ahead = e.label();
  e.jz(ahead);  // over the jmp: rel32 = 5
  e.jmp(ahead); // rel32 = 0
  e.bind(ahead);
  EXPECT_EQ(hex(e.code()), "0f 82 fa ff ff ff 0f 84 05 00 00 00 e9 00 00 00 00");
}

} // namespace
} // namespace frep::eval::x86
