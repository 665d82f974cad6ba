#include "tape_to_libfive.h"

#include <libfive/tree/operations.hpp>

#include <cmath>
#include <set>
#include <vector>

namespace peers
{
namespace
{

using libfive::Tree;

Tree truthy(const Tree& a)
{
  // |a| >= 1e-6  <=>  not (|a| < 1e-6); compare gives -1 below
  return Tree(1.0) - max(Tree(0.0), -compare(abs(a), Tree(1e-6)));
}

Tree less(const Tree& a, const Tree& b)
{
  return max(Tree(0.0), -compare(a, b));
}

Tree greater(const Tree& a, const Tree& b)
{
  return max(Tree(0.0), compare(a, b));
}

Tree integer_power(const Tree& a, int n)
{
  if (n == 0)
  {
    return Tree(1.0);
  }
  const Tree p = n == 1 ? a : n == 2 ? square(a) : pow(a, Tree(double(n < 0 ? -n : n)));
  return n < 0 ? Tree(1.0) / p : p;
}

} // namespace

LibfiveTranslation tape_to_libfive(const frep::Tape& tape)
{
  using frep::Opcode;
  LibfiveTranslation result;
  std::vector<Tree> slot(tape.slot_count, Tree::invalid());
  std::vector<double> constant(tape.slot_count, NAN); // Const slots, for integral exponents
  std::set<std::string> unsupported;
  for (const frep::Instruction& in : tape.code)
  {
    // An operand from an untranslatable instruction: this one is untranslatable too.
    const int operands = frep::operand_count(in.op);
    if ((operands > 0 && !slot[in.a].is_valid()) || (operands > 1 && !slot[in.b].is_valid()) ||
        (operands > 2 && !slot[in.c].is_valid()))
    {
      continue;
    }
    const Tree& a = slot[in.a];
    const Tree& b = slot[in.b];
    const Tree& c = slot[in.c];
    Tree out = Tree::invalid();
    switch (in.op)
    {
      case Opcode::Const: out = Tree(in.imm); constant[in.out] = in.imm; break;
      case Opcode::Input:
        if (in.index == 0) out = Tree::X();
        else if (in.index == 1) out = Tree::Y();
        else if (in.index == 2) out = Tree::Z();
        else unsupported.insert("input x[" + std::to_string(in.index + 1) + "]");
        break;
      case Opcode::Add: out = a + b; break;
      case Opcode::Sub: out = a - b; break;
      case Opcode::Mul: out = a * b; break;
      case Opcode::Div: out = a / b; break;
      case Opcode::Neg: out = -a; break;
      case Opcode::Square: out = square(a); break;
      case Opcode::Abs: out = abs(a); break;
      case Opcode::Sqrt: out = sqrt(a); break;
      case Opcode::Exp: out = exp(a); break;
      case Opcode::Log: out = log(a); break;
      case Opcode::Sin: out = sin(a); break;
      case Opcode::Cos: out = cos(a); break;
      case Opcode::Tan: out = tan(a); break;
      case Opcode::Asin: out = asin(a); break;
      case Opcode::Acos: out = acos(a); break;
      case Opcode::Atan: out = atan(a); break;
      case Opcode::Atan2: out = atan2(a, b); break;
      case Opcode::Max: out = max(a, b); break;
      case Opcode::Min: out = min(a, b); break;
      case Opcode::Union:
      case Opcode::UnionPlain: out = a + b + sqrt(square(a) + square(b)); break;
      case Opcode::Intersect:
      case Opcode::IntersectPlain: out = a + b - sqrt(square(a) + square(b)); break;
      case Opcode::Log10: out = log(a) / Tree(std::log(10.0)); ++result.approximated; break;
      case Opcode::Sinh: out = (exp(a) - exp(-a)) / Tree(2.0); ++result.approximated; break;
      case Opcode::Cosh: out = (exp(a) + exp(-a)) / Tree(2.0); ++result.approximated; break;
      case Opcode::Tanh:
        out = (exp(a) - exp(-a)) / (exp(a) + exp(-a));
        ++result.approximated;
        break;
      case Opcode::HfPowInt: out = integer_power(a, in.index); ++result.approximated; break;
      case Opcode::Pow:
      case Opcode::HfPow:
      {
        const double e = constant[in.b];
        if (std::isfinite(e) && e == std::floor(e) && std::fabs(e) < 1024)
        {
          out = integer_power(a, static_cast<int>(e));
        }
        else
        {
          out = exp(b * log(a));
        }
        ++result.approximated;
        break;
      }
      case Opcode::Lt: out = less(a, b); ++result.approximated; break;
      case Opcode::Gt: out = greater(a, b); ++result.approximated; break;
      case Opcode::Le: out = Tree(1.0) - greater(a, b); ++result.approximated; break;
      case Opcode::Ge: out = Tree(1.0) - less(a, b); ++result.approximated; break;
      case Opcode::Eq: out = less(abs(a - b), Tree(1e-6)); ++result.approximated; break;
      case Opcode::Ne: out = Tree(1.0) - less(abs(a - b), Tree(1e-6)); ++result.approximated; break;
      case Opcode::Truthy: out = truthy(a); ++result.approximated; break;
      case Opcode::Not: out = Tree(1.0) - truthy(a); ++result.approximated; break;
      case Opcode::And: out = truthy(a) * truthy(b); ++result.approximated; break;
      case Opcode::Or: out = max(truthy(a), truthy(b)); ++result.approximated; break;
      case Opcode::Select: out = a * b + (Tree(1.0) - a) * c; ++result.approximated; break;
      case Opcode::ErrorIf: ++result.dropped_checks; continue;
      default: unsupported.insert(frep::opcode_name(in.op)); continue;
    }
    slot[in.out] = out;
  }
  for (const std::string& name : unsupported)
  {
    result.unsupported += (result.unsupported.empty() ? "" : ", ") + name;
  }
  if (result.unsupported.empty())
  {
    if (tape.outputs.empty())
    {
      result.unsupported = "no output";
    }
    else
    {
      result.tree = slot[tape.outputs[0]];
    }
  }
  return result;
}

} // namespace peers
