#include "Eval/detail/batch_program.h"

#include <limits>

namespace frep::eval
{

bool takes_immediate(Opcode op)
{
  return opcode_info(op).has(OpcodeInfo::ImmediateForm);
}

namespace
{

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

} // namespace

BatchProgram make_batch_program(const Tape& tape)
{
  const std::size_t count = tape.code.size();
  // Forward scan: which Const instruction currently defines each slot; a read either becomes an
  // immediate (one per instruction, operand a or b) or keeps the Const.
  std::vector<std::uint32_t> defined_by(tape.slot_count, kNone);
  std::vector<bool> needed(count, false);
  std::vector<Immediate> immediate(count, Immediate::None);
  const auto keep = [&](std::uint32_t slot)
  {
    if (slot < defined_by.size() && defined_by[slot] != kNone)
    {
      needed[defined_by[slot]] = true;
    }
  };
  for (std::size_t i = 0; i < count; ++i)
  {
    const Instruction& ins = tape.code[i];
    if (ins.op == Opcode::Call)
    {
      for (std::uint32_t slot : tape.calls[static_cast<std::size_t>(ins.index)].inputs)
      {
        keep(slot);
      }
    }
    const int reads = operand_count(ins.op);
    const std::uint32_t operand[3] = { ins.a, ins.b, ins.c };
    for (int k = 0; k < reads; ++k)
    {
      const std::uint32_t slot = operand[k];
      const bool is_const = slot < defined_by.size() && defined_by[slot] != kNone;
      if (is_const && k < 2 && takes_immediate(ins.op) && immediate[i] == Immediate::None)
      {
        immediate[i] = k == 0 ? Immediate::A : Immediate::B;
        continue;
      }
      keep(slot);
    }
    if (ins.op == Opcode::Call)
    {
      for (std::uint32_t slot : tape.calls[static_cast<std::size_t>(ins.index)].outputs)
      {
        if (slot < defined_by.size())
        {
          defined_by[slot] = kNone;
        }
      }
    }
    else if (ins.op != Opcode::ErrorIf && ins.out < defined_by.size())
    {
      defined_by[ins.out] = ins.op == Opcode::Const ? static_cast<std::uint32_t>(i) : kNone;
    }
  }
  for (std::uint32_t slot : tape.outputs)
  {
    keep(slot);
  }

  // Second pass: write the program, taking each immediate's value from its Const.
  BatchProgram program;
  std::fill(defined_by.begin(), defined_by.end(), kNone);
  for (std::size_t i = 0; i < count; ++i)
  {
    Instruction ins = tape.code[i];
    const Immediate side = immediate[i];
    if (side != Immediate::None)
    {
      const std::uint32_t slot = side == Immediate::A ? ins.a : ins.b;
      ins.imm = tape.code[defined_by[slot]].imm;
    }
    if (ins.op == Opcode::Call)
    {
      for (std::uint32_t slot : tape.calls[static_cast<std::size_t>(ins.index)].outputs)
      {
        if (slot < defined_by.size())
        {
          defined_by[slot] = kNone;
        }
      }
    }
    else if (ins.op != Opcode::ErrorIf && ins.out < defined_by.size())
    {
      defined_by[ins.out] = ins.op == Opcode::Const ? static_cast<std::uint32_t>(i) : kNone;
    }
    if (ins.op == Opcode::Const && !needed[i])
    {
      continue;
    }
    program.code.push_back(ins);
    program.immediate.push_back(side);
    program.origin.push_back(static_cast<std::uint32_t>(i));
  }
  return program;
}

} // namespace frep::eval
