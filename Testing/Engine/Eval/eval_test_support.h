// Hand-built tapes and an independent reference for the evaluator tests.
#pragma once

#include "Semantics/detail/op_semantics.h"
#include "Compiler/tape.h"

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace frep::test
{

/// Builds a tape instruction by instruction; every instruction gets a fresh slot.
struct TapeBuilder
{
  Tape tape;

  explicit TapeBuilder(std::uint32_t inputs) { tape.input_count = inputs; }

  std::uint32_t emit(Instruction ins)
  {
    ins.out = tape.slot_count++;
    tape.code.push_back(ins);
    return ins.out;
  }
  std::uint32_t input(int k) { return emit({ Opcode::Input, 0, 0, 0, 0, k, 0 }); }
  std::uint32_t constant(double v) { return emit({ Opcode::Const, 0, 0, 0, 0, 0, v }); }
  std::uint32_t op(Opcode o,
    std::uint32_t a,
    std::uint32_t b = 0,
    std::uint32_t c = 0,
    int index = 0)
  {
    return emit({ o, 0, a, b, c, index, 0 });
  }
  /// ErrorIf(cond) with a new error id (returned).
  int error_if(std::uint32_t cond)
  {
    tape.errors.push_back({ "error " + std::to_string(tape.errors.size() + 1), {} });
    const int id = static_cast<int>(tape.errors.size());
    tape.code.push_back({ Opcode::ErrorIf, 0, cond, 0, 0, id, 0 });
    tape.can_fail = true;
    return id;
  }
  std::shared_ptr<const Tape> finish(std::vector<std::uint32_t> outputs)
  {
    tape.outputs = std::move(outputs);
    return std::make_shared<const Tape>(tape);
  }
};

/// Every opcode with a value rule, with the number of operands it reads.
struct OpInfo
{
  Opcode op;
  int arity;
  const char* name;
};

inline const std::vector<OpInfo>& value_ops()
{
  static const std::vector<OpInfo> ops = {
    { Opcode::Add, 2, "Add" },
    { Opcode::Sub, 2, "Sub" },
    { Opcode::Mul, 2, "Mul" },
    { Opcode::Div, 2, "Div" },
    { Opcode::Neg, 1, "Neg" },
    { Opcode::Square, 1, "Square" },
    { Opcode::Abs, 1, "Abs" },
    { Opcode::Sqrt, 1, "Sqrt" },
    { Opcode::Exp, 1, "Exp" },
    { Opcode::Log, 1, "Log" },
    { Opcode::Log10, 1, "Log10" },
    { Opcode::Sin, 1, "Sin" },
    { Opcode::Cos, 1, "Cos" },
    { Opcode::Tan, 1, "Tan" },
    { Opcode::Asin, 1, "Asin" },
    { Opcode::Acos, 1, "Acos" },
    { Opcode::Atan, 1, "Atan" },
    { Opcode::Sinh, 1, "Sinh" },
    { Opcode::Cosh, 1, "Cosh" },
    { Opcode::Tanh, 1, "Tanh" },
    { Opcode::Atan2, 2, "Atan2" },
    { Opcode::Pow, 2, "Pow" },
    { Opcode::Floor, 1, "Floor" },
    { Opcode::Ceil, 1, "Ceil" },
    { Opcode::Trunc, 1, "Trunc" },
    { Opcode::Frac, 1, "Frac" },
    { Opcode::Fmod, 2, "Fmod" },
    { Opcode::HfPow, 2, "HfPow" },
    { Opcode::HfMod, 2, "HfMod" },
    { Opcode::HfRound, 1, "HfRound" },
    { Opcode::Max, 2, "Max" },
    { Opcode::Min, 2, "Min" },
    { Opcode::Union, 2, "Union" },
    { Opcode::Intersect, 2, "Intersect" },
    { Opcode::UnionPlain, 2, "UnionPlain" },
    { Opcode::IntersectPlain, 2, "IntersectPlain" },
    { Opcode::Eq, 2, "Eq" },
    { Opcode::Ne, 2, "Ne" },
    { Opcode::Lt, 2, "Lt" },
    { Opcode::Le, 2, "Le" },
    { Opcode::Gt, 2, "Gt" },
    { Opcode::Ge, 2, "Ge" },
    { Opcode::Truthy, 1, "Truthy" },
    { Opcode::And, 2, "And" },
    { Opcode::Or, 2, "Or" },
    { Opcode::Not, 1, "Not" },
    { Opcode::Select, 3, "Select" },
  };
  return ops;
}

/// A tape computing op(x0, x1, x2) (HfPowInt: x0 ^ index).
inline std::shared_ptr<const Tape> single_op_tape(Opcode op, int index = 0)
{
  TapeBuilder b(3);
  const auto x0 = b.input(0);
  const auto x1 = b.input(1);
  const auto x2 = b.input(2);
  return b.finish({ b.op(op, x0, x1, x2, index) });
}

/// The reference value, written from LANGUAGE.md/op_semantics.h independently of the
/// evaluators' shared scalar table.
inline double reference(Opcode op, double a, double b, double c, int index = 0)
{
  namespace hf = frep::semantics;
  switch (op)
  {
    case Opcode::Add:
      return a + b;
    case Opcode::Sub:
      return a - b;
    case Opcode::Mul:
      return a * b;
    case Opcode::Div:
      return a / b;
    case Opcode::Neg:
      return -a;
    case Opcode::Square:
      return a * a;
    case Opcode::Abs:
      return std::fabs(a);
    case Opcode::Sqrt:
      return std::sqrt(a);
    case Opcode::Exp:
      return std::exp(a);
    case Opcode::Log:
      return std::log(a);
    case Opcode::Log10:
      return std::log10(a);
    case Opcode::Sin:
      return std::sin(a);
    case Opcode::Cos:
      return std::cos(a);
    case Opcode::Tan:
      return std::tan(a);
    case Opcode::Asin:
      return std::asin(a);
    case Opcode::Acos:
      return std::acos(a);
    case Opcode::Atan:
      return std::atan(a);
    case Opcode::Sinh:
      return std::sinh(a);
    case Opcode::Cosh:
      return std::cosh(a);
    case Opcode::Tanh:
      return std::tanh(a);
    case Opcode::Atan2:
      return std::atan2(a, b);
    case Opcode::Pow:
      return std::pow(a, b);
    case Opcode::Floor:
      return std::floor(a);
    case Opcode::Ceil:
      return std::ceil(a);
    case Opcode::Trunc:
      return std::trunc(a);
    case Opcode::Frac:
    {
      double ip = 0;
      return std::modf(a, &ip);
    }
    case Opcode::Fmod:
      return std::fmod(a, b);
    case Opcode::HfPow:
      return hf::hf_pow(a, b);
    case Opcode::HfPowInt:
      return hf::hf_pow_int(a, index);
    case Opcode::HfMod:
      return hf::hf_mod(a, b);
    case Opcode::HfRound:
      return hf::hf_round(a);
    case Opcode::Max:
      return hf::hf_max(a, b);
    case Opcode::Min:
      return hf::hf_min(a, b);
    case Opcode::Union:
      return hf::unite(a, b);
    case Opcode::Intersect:
      return hf::intersect(a, b);
    case Opcode::UnionPlain: // written out here, independently of op_semantics.h
      return (a + b) + std::sqrt(a * a + b * b);
    case Opcode::IntersectPlain:
      return (a + b) - std::sqrt(a * a + b * b);
    case Opcode::Eq:
      return std::fabs(a - b) < 1e-6 ? 1 : 0;
    case Opcode::Ne:
      return std::fabs(a - b) >= 1e-6 ? 1 : 0;
    case Opcode::Lt:
      return a < b ? 1 : 0;
    case Opcode::Le:
      return a <= b ? 1 : 0;
    case Opcode::Gt:
      return a > b ? 1 : 0;
    case Opcode::Ge:
      return a >= b ? 1 : 0;
    case Opcode::Truthy:
      return hf::truthy(a) ? 1 : 0;
    case Opcode::And:
      return hf::truthy(a) && hf::truthy(b) ? 1 : 0;
    case Opcode::Or:
      return hf::truthy(a) || hf::truthy(b) ? 1 : 0;
    case Opcode::Not:
      return hf::truthy(a) ? 0 : 1;
    case Opcode::Select:
      return a != 0 ? b : c;
    default:
      return std::nan("");
  }
}

/// Same bits (every NaN counts as equal to every NaN: payloads are not part of the contract).
inline bool same_bits(double x, double y)
{
  if (std::isnan(x) && std::isnan(y))
  {
    return true;
  }
  return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
}

/// Values that break naive implementations: signed zeros, EPS neighbours, infinities, NaN.
inline const std::vector<double>& special_values()
{
  static const std::vector<double> v = { 0.0,
    -0.0,
    1e-7,
    -1e-7,
    1e-6,
    -1e-6,
    1.0,
    -1.0,
    0.5,
    -0.5,
    1.5,
    -2.5,
    2.0,
    3.0,
    -3.0,
    1e-300,
    1e300,
    -1e300,
    std::numeric_limits<double>::infinity(),
    -std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::quiet_NaN(),
    3.14159265358979,
    12345.0,
    -7.25 };
  return v;
}

/// A random operand: mostly ordinary numbers of several scales, sometimes special values.
inline double random_value(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 9);
  switch (kind(rng))
  {
    case 0:
    {
      const auto& s = special_values();
      return s[std::uniform_int_distribution<std::size_t>(0, s.size() - 1)(rng)];
    }
    case 1:
      return unit(rng) * 1e-5;
    case 2:
      return unit(rng) * 1e3;
    case 3:
      return std::round(unit(rng) * 5); // integers: exercise EPS rules and HfPow
    default:
      return unit(rng) * 4;
  }
}

/// An opaque function: out0 = in0 * in1 + 1, out1 = sin(in0); error 1 when in0 > 5. Counts
/// scratch objects to check they are made once per evaluator, not per point.
class TestFunction : public OpaqueFunction
{
public:
  struct CountingScratch : Scratch
  {
    int calls = 0;
  };
  mutable std::atomic<int> scratches{ 0 };

  std::unique_ptr<Scratch> make_scratch() const override
  {
    ++scratches;
    return std::make_unique<CountingScratch>();
  }
  int evaluate(Scratch* scratch, std::span<const double> in, std::span<double> out) const override
  {
    ++static_cast<CountingScratch*>(scratch)->calls;
    if (in[0] > 5)
    {
      return 1;
    }
    out[0] = in[0] * in[1] + 1;
    out[1] = std::sin(in[0]);
    return 0;
  }
};

/// `count` unit balls on a ring of `radius` about the z axis, joined by `join` (Max: a small
/// box decides it; Union: never), with an error check (x > 100) that every box near the ring
/// decides: most balls are far from any small box.
inline std::shared_ptr<const Tape> ring_of_balls(Opcode join, int count, double radius)
{
  TapeBuilder b(3);
  const auto x = b.input(0), y = b.input(1), z = b.input(2);
  std::uint32_t f = 0;
  for (int k = 0; k < count; ++k)
  {
    const double angle = 2 * 3.14159265358979323846 * k / count;
    const auto dx = b.op(Opcode::Sub, x, b.constant(radius * std::cos(angle)));
    const auto dy = b.op(Opcode::Sub, y, b.constant(radius * std::sin(angle)));
    const auto r2 = b.op(Opcode::Add,
      b.op(Opcode::Add, b.op(Opcode::Square, dx), b.op(Opcode::Square, dy)),
      b.op(Opcode::Square, z));
    const auto ball = b.op(Opcode::Sub, b.constant(1.0), b.op(Opcode::Sqrt, r2));
    f = k == 0 ? ball : b.op(join, f, ball);
  }
  b.error_if(b.op(Opcode::Gt, x, b.constant(100)));
  return b.finish({ f });
}

} // namespace frep::test
