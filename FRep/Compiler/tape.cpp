#include "Compiler/tape.h"

#include <cstdio>
#include <sstream>

namespace frep
{

const char* opcode_name(Opcode op)
{
  switch (op)
  {
    case Opcode::Const:
      return "const";
    case Opcode::Input:
      return "input";
    case Opcode::Add:
      return "add";
    case Opcode::Sub:
      return "sub";
    case Opcode::Mul:
      return "mul";
    case Opcode::Div:
      return "div";
    case Opcode::Neg:
      return "neg";
    case Opcode::Square:
      return "square";
    case Opcode::Abs:
      return "abs";
    case Opcode::Sqrt:
      return "sqrt";
    case Opcode::Exp:
      return "exp";
    case Opcode::Log:
      return "log";
    case Opcode::Log10:
      return "log10";
    case Opcode::Sin:
      return "sin";
    case Opcode::Cos:
      return "cos";
    case Opcode::Tan:
      return "tan";
    case Opcode::Asin:
      return "asin";
    case Opcode::Acos:
      return "acos";
    case Opcode::Atan:
      return "atan";
    case Opcode::Sinh:
      return "sinh";
    case Opcode::Cosh:
      return "cosh";
    case Opcode::Tanh:
      return "tanh";
    case Opcode::Atan2:
      return "atan2";
    case Opcode::Pow:
      return "pow";
    case Opcode::Floor:
      return "floor";
    case Opcode::Ceil:
      return "ceil";
    case Opcode::Trunc:
      return "trunc";
    case Opcode::Frac:
      return "frac";
    case Opcode::Fmod:
      return "fmod";
    case Opcode::HfPow:
      return "hf_pow";
    case Opcode::HfPowInt:
      return "hf_pow_int";
    case Opcode::HfMod:
      return "hf_mod";
    case Opcode::HfRound:
      return "hf_round";
    case Opcode::Max:
      return "max";
    case Opcode::Min:
      return "min";
    case Opcode::Union:
      return "union";
    case Opcode::Intersect:
      return "intersect";
    case Opcode::UnionPlain:
      return "union_plain";
    case Opcode::IntersectPlain:
      return "intersect_plain";
    case Opcode::Eq:
      return "eq";
    case Opcode::Ne:
      return "ne";
    case Opcode::Lt:
      return "lt";
    case Opcode::Le:
      return "le";
    case Opcode::Gt:
      return "gt";
    case Opcode::Ge:
      return "ge";
    case Opcode::Truthy:
      return "truthy";
    case Opcode::And:
      return "and";
    case Opcode::Or:
      return "or";
    case Opcode::Not:
      return "not";
    case Opcode::Select:
      return "select";
    case Opcode::ErrorIf:
      return "error_if";
    case Opcode::Call:
      return "call";
  }
  return "?";
}

namespace
{

std::string number(double v)
{
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

} // namespace

bool is_boolean_opcode(Opcode op)
{
  switch (op)
  {
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
      return true;
    default:
      return false;
  }
}

int operand_count(Opcode op)
{
  switch (op)
  {
    case Opcode::Const:
    case Opcode::Input:
    case Opcode::Call:
      return 0;
    case Opcode::Add:
    case Opcode::Sub:
    case Opcode::Mul:
    case Opcode::Div:
    case Opcode::Atan2:
    case Opcode::Pow:
    case Opcode::Fmod:
    case Opcode::HfPow:
    case Opcode::HfMod:
    case Opcode::Max:
    case Opcode::Min:
    case Opcode::Union:
    case Opcode::Intersect:
    case Opcode::UnionPlain:
    case Opcode::IntersectPlain:
    case Opcode::Eq:
    case Opcode::Ne:
    case Opcode::Lt:
    case Opcode::Le:
    case Opcode::Gt:
    case Opcode::Ge:
    case Opcode::And:
    case Opcode::Or:
      return 2;
    case Opcode::Select:
      return 3;
    default:
      return 1;
  }
}

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
