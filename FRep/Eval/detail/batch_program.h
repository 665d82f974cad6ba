// The batch kernel's form of a tape: constant operands folded into the instructions that read
// them, so a Const does not fill a whole row of lanes per block only to be read once. Only the
// Const instructions whose value is read by something that cannot take an immediate (or that is
// an output) stay. The operations performed per lane are unchanged, so results stay identical.
#pragma once

#include "Compiler/tape.h"

#include <cstdint>
#include <vector>

namespace frep::eval
{

/// Which operand of an instruction is the immediate Instruction::imm instead of a slot.
enum class Immediate : std::uint8_t
{
  None = 0,
  A = 1, ///< operand a
  B = 2  ///< operand b
};

struct BatchProgram
{
  std::vector<Instruction> code;
  std::vector<Immediate> immediate; ///< parallel to code
  std::vector<std::uint32_t> origin; ///< parallel to code: the instruction's index in the tape
};

/// Whether the batch kernel has an immediate form of `op` for operand a or b.
bool takes_immediate(Opcode op);

BatchProgram make_batch_program(const Tape& tape);

} // namespace frep::eval
