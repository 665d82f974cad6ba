#include "Compiler/tape.h"

#include <cstdio>
#include <sstream>

namespace frep
{

namespace
{

std::string number(double v)
{
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

} // namespace

std::string Tape::dump() const
{
  std::ostringstream os;
  os << "; tape: " << code.size() << " instructions, " << slot_count << " slots, " << input_count
     << " inputs, " << outputs.size() << " outputs\n";
  for (const Instruction& ins : code)
  {
    switch (ins.op)
    {
      case Opcode::ErrorIf:
      {
        os << "error_if r" << ins.a << " -> #" << ins.index;
        const auto k = static_cast<std::size_t>(ins.index - 1);
        if (ins.index >= 1 && k < errors.size())
        {
          os << " \"" << errors[k].message << "\" at " << errors[k].location.line << ':'
             << errors[k].location.column;
        }
        break;
      }
      case Opcode::Call:
      {
        os << "call #" << ins.index;
        const auto k = static_cast<std::size_t>(ins.index);
        if (ins.index >= 0 && k < calls.size())
        {
          os << " (";
          for (std::size_t i = 0; i < calls[k].inputs.size(); ++i)
          {
            os << (i ? " r" : "r") << calls[k].inputs[i];
          }
          os << ") -> (";
          for (std::size_t i = 0; i < calls[k].outputs.size(); ++i)
          {
            os << (i ? " r" : "r") << calls[k].outputs[i];
          }
          os << ')';
        }
        break;
      }
      case Opcode::Const:
        os << 'r' << ins.out << " = const " << number(ins.imm);
        break;
      case Opcode::Input:
        os << 'r' << ins.out << " = input " << ins.index;
        break;
      default:
      {
        os << 'r' << ins.out << " = " << opcode_name(ins.op);
        const int n = operand_count(ins.op);
        if (n > 0)
          os << " r" << ins.a;
        if (n > 1)
          os << " r" << ins.b;
        if (n > 2)
          os << " r" << ins.c;
        if (ins.op == Opcode::HfPowInt)
          os << " ^" << ins.index;
        break;
      }
    }
    os << '\n';
  }
  os << "outputs:";
  for (std::uint32_t s : outputs)
  {
    os << " r" << s;
  }
  os << '\n';
  return os.str();
}

} // namespace frep
