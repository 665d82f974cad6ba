// Compiler/opcode.h: the one description of each opcode agrees with its value rule
// (Compiler/detail/op_eval.h) on the properties the value decides, and names every opcode once.
#include "Compiler/detail/op_eval.h"
#include "Compiler/opcode.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace
{

using frep::Opcode;
using frep::OpcodeInfo;

bool pure(Opcode op)
{
  return op != Opcode::Const && op != Opcode::Input && op != Opcode::ErrorIf && op != Opcode::Call;
}

std::vector<double> samples()
{
  const double inf = std::numeric_limits<double>::infinity();
  return { 0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    -2.5,
    3.0,
    1e-7,
    1e300,
    -1e300,
    inf,
    -inf,
    std::numeric_limits<double>::quiet_NaN() };
}

Opcode op_at(std::size_t i)
{
  return static_cast<Opcode>(i);
}

TEST(OpcodeTable, NamesAreUniqueAndKnown)
{
  std::set<std::string> names;
  for (std::size_t i = 0; i < frep::kOpcodeCount; ++i)
  {
    const std::string name = frep::opcode_name(op_at(i));
    EXPECT_FALSE(name.empty());
    EXPECT_NE(name, "?");
    EXPECT_TRUE(names.insert(name).second) << name;
  }
  EXPECT_STREQ(frep::opcode_name(static_cast<Opcode>(frep::kOpcodeCount)), "?");
}

// Commutative <=> f(a, b) and f(b, a) have the same bits for every pair of samples.
TEST(OpcodeTable, CommutativeIsWhatTheValuesSay)
{
  for (std::size_t i = 0; i < frep::kOpcodeCount; ++i)
  {
    const Opcode op = op_at(i);
    if (!pure(op) || frep::operand_count(op) != 2)
    {
      EXPECT_FALSE(frep::opcode_info(op).has(OpcodeInfo::Commutative)) << frep::opcode_name(op);
      continue;
    }
    bool symmetric = true;
    for (double a : samples())
    {
      for (double b : samples())
      {
        const double ab = frep::semantics::evaluate_op(op, a, b, 0.0, 0);
        const double ba = frep::semantics::evaluate_op(op, b, a, 0.0, 0);
        symmetric =
          symmetric && std::bit_cast<std::uint64_t>(ab) == std::bit_cast<std::uint64_t>(ba);
      }
    }
    EXPECT_EQ(frep::opcode_info(op).has(OpcodeInfo::Commutative), symmetric)
      << frep::opcode_name(op);
  }
}

// Boolean => every value is 1.0 or 0.0 (and a non-boolean opcode gives some other value).
TEST(OpcodeTable, BooleanIsWhatTheValuesSay)
{
  for (std::size_t i = 0; i < frep::kOpcodeCount; ++i)
  {
    const Opcode op = op_at(i);
    if (!pure(op) || op == Opcode::Select)
    {
      EXPECT_FALSE(frep::is_boolean_opcode(op)) << frep::opcode_name(op);
      continue;
    }
    bool only_01 = true;
    for (double a : samples())
    {
      for (double b : samples())
      {
        const double v = frep::semantics::evaluate_op(op, a, b, 0.0, 2);
        only_01 =
          only_01 && (std::bit_cast<std::uint64_t>(v) == std::bit_cast<std::uint64_t>(1.0) ||
                       std::bit_cast<std::uint64_t>(v) == std::bit_cast<std::uint64_t>(0.0));
      }
    }
    EXPECT_EQ(frep::is_boolean_opcode(op), only_01) << frep::opcode_name(op);
  }
}

TEST(OpcodeTable, OperandsAndResults)
{
  EXPECT_EQ(frep::operand_count(Opcode::Const), 0);
  EXPECT_EQ(frep::operand_count(Opcode::Call), 0);
  EXPECT_EQ(frep::operand_count(Opcode::Select), 3);
  EXPECT_EQ(frep::operand_count(Opcode::HfPowInt), 1); // the exponent is an immediate
  EXPECT_EQ(frep::operand_count(Opcode::ErrorIf), 1);
  for (std::size_t i = 0; i < frep::kOpcodeCount; ++i)
  {
    const Opcode op = op_at(i);
    EXPECT_EQ(
      frep::opcode_info(op).has(OpcodeInfo::NoResult), op == Opcode::ErrorIf || op == Opcode::Call)
      << frep::opcode_name(op);
    // a constant operand only for binary operations
    if (frep::opcode_info(op).has(OpcodeInfo::ImmediateForm))
    {
      EXPECT_EQ(frep::operand_count(op), 2) << frep::opcode_name(op);
    }
    if (frep::opcode_info(op).has(OpcodeInfo::Choice))
    {
      EXPECT_EQ(frep::operand_count(op), 2) << frep::opcode_name(op);
    }
  }
}

} // namespace
