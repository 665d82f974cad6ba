#include "Compiler/detail/tape_check.h"

#include <stdexcept>
#include <string>

namespace frep::eval
{

bool reads_a(Opcode op)
{
  return operand_count(op) >= 1;
}

bool reads_b(Opcode op)
{
  return operand_count(op) >= 2;
}

bool reads_c(Opcode op)
{
  return operand_count(op) >= 3;
}

namespace
{

[[noreturn]] void fail(const char* who, const std::string& what)
{
  throw std::invalid_argument(std::string(who) + ": malformed tape: " + what);
}

} // namespace

void check_tape(const Tape& tape, const char* who)
{
  const auto bad_slot = [&](std::uint32_t slot) { return slot >= tape.slot_count; };
  for (std::size_t i = 0; i < tape.code.size(); ++i)
  {
    const Instruction& ins = tape.code[i];
    // (the message is built only on failure: this runs for every tape an evaluator takes,
    // simplified tapes per box included)
    const auto at = [i] { return "instruction " + std::to_string(i); };
    if (static_cast<unsigned>(ins.op) > static_cast<unsigned>(Opcode::Call))
    {
      fail(who, at() + " has an unknown opcode");
    }
    const bool writes = !opcode_info(ins.op).has(OpcodeInfo::NoResult);
    if ((writes && bad_slot(ins.out)) || (reads_a(ins.op) && bad_slot(ins.a)) ||
        (reads_b(ins.op) && bad_slot(ins.b)) || (reads_c(ins.op) && bad_slot(ins.c)))
    {
      fail(who, at() + " uses a slot beyond slot_count");
    }
    if (ins.op == Opcode::Input &&
        (ins.index < 0 || static_cast<std::uint32_t>(ins.index) >= tape.input_count))
    {
      fail(who, at() + " reads an input beyond input_count");
    }
    if (ins.op == Opcode::ErrorIf && ins.index <= 0)
    {
      fail(who, at() + " raises a non-positive error id");
    }
    if (ins.op == Opcode::Call)
    {
      if (ins.index < 0 || static_cast<std::size_t>(ins.index) >= tape.calls.size())
      {
        fail(who, at() + " calls a missing call site");
      }
      const CallSite& site = tape.calls[static_cast<std::size_t>(ins.index)];
      if (!site.function)
      {
        fail(who, at() + " calls a site without a function");
      }
      for (std::uint32_t slot : site.inputs)
      {
        if (bad_slot(slot))
        {
          fail(who, at() + ": call input slot beyond slot_count");
        }
      }
      for (std::uint32_t slot : site.outputs)
      {
        if (bad_slot(slot))
        {
          fail(who, at() + ": call output slot beyond slot_count");
        }
      }
    }
  }
  for (std::uint32_t slot : tape.outputs)
  {
    if (bad_slot(slot))
    {
      fail(who, "an output slot is beyond slot_count");
    }
  }
}

} // namespace frep::eval
