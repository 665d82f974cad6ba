// The tape's operations, each described once: the enum, and one table row per opcode with what
// the compiler, the simplifier, the freezes and the evaluators need to know about it apart from
// its value (name, operands, boolean result, bitwise commutativity, whether a box can decide it,
// whether the batch kernel has a form with a constant operand). Adding an opcode: a row here, its
// value rule (Compiler/detail/op_eval.h, and the interval rule in Eval/interval_evaluator.cpp),
// and the evaluators' kernels; `static_assert`s below keep the table in the enum's order and
// complete.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace frep
{

/// Operations. Unless stated, operands are slots a, b, c and the result goes to `out`.
/// Booleans are the doubles 1.0 (true) and 0.0 (false). "HyperFun" ops reproduce exactly what
/// the original interpreter computes (same operations in the same order, bit for bit).
// (The groups read better several to a line.)
// clang-format off
enum class Opcode : std::uint8_t
{
  // leaves
  Const, ///< out = imm
  Input, ///< out = inputs[index]

  // IEEE arithmetic
  Add, Sub, Mul, Div, ///< a op b (Div unchecked: checks are separate ErrorIf instructions)
  Neg,                ///< -a
  Square,             ///< a * a
  Abs,                ///< fabs(a)

  // C library, no domain checks (the compiler emits ErrorIf where HyperFun checks)
  Sqrt, Exp, Log, Log10, Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh,
  Atan2, ///< atan2(a, b)
  Pow,   ///< C pow(a, b)
  Floor, Ceil, Trunc,
  Frac,  ///< fractional part as C modf computes it (keeps the sign; 0 for infinities)
  Fmod,  ///< fmod(a, b)

  // HyperFun semantics
  HfPow,     ///< a ^ b by the original's rules, value part (errors via ErrorIf)
  HfPowInt,  ///< a ^ index for a constant integral exponent `index` (may be negative)
  HfMod,     ///< fmod(HF_round(a), HF_round(b))
  HfRound,   ///< HF_round(a): round half up (array indices)
  Max, Min,  ///< as the original's builtins compute them
  Union,     ///< a + b + sqrt(a*a + b*b)
  Intersect, ///< a + b - sqrt(a*a + b*b)   (a \ b = Intersect(a, -b) bit for bit)
  /// (a + b) ± sqrt(a*a + b*b) as hfBlendUni/hfBlendInt write it: without the R-functions'
  /// 0*a*b term, so an infinite operand gives inf (or NaN) as written, not always NaN. Its own
  /// opcode so the interval evaluator can use the monotone rule (the expanded sqrt is loose).
  UnionPlain,
  IntersectPlain,

  // comparisons and logic (results 1.0 / 0.0)
  Eq, Ne,         ///< |a - b| < 1e-6 ; |a - b| >= 1e-6
  Lt, Le, Gt, Ge, ///< exact
  Truthy,         ///< |a| >= 1e-6
  And, Or,        ///< truthiness of a and b
  Not,            ///< !(|a| >= 1e-6)
  Select,         ///< a != 0 ? b : c   (a is a boolean slot)

  // run-time errors
  ErrorIf, ///< if a != 0 and the point has no error yet: error = index (1-based into errors)

  // opaque: a library function without a generic form, or a whole interpreted model
  Call ///< calls[index]: reads its input slots, writes its output slots, may set the error
};
// clang-format on

inline constexpr std::size_t kOpcodeCount = static_cast<std::size_t>(Opcode::Call) + 1;

/// What is known about an opcode apart from its value.
struct OpcodeInfo
{
  enum Flag : std::uint8_t
  {
    None = 0,
    Boolean = 1,       ///< the result is always 1.0 or 0.0 (comparisons and logic)
    Commutative = 2,   ///< f(a, b) == f(b, a) bit for bit (so the DAG may order the operands)
    Choice = 4,        ///< max/min or an R-function: a box may decide it (interval freezes)
    ImmediateForm = 8, ///< the batch kernel has a form with one constant operand
    NoResult = 16,     ///< writes no `out` slot (ErrorIf; Call writes its call site's outputs)
  };

  Opcode op;
  const char* name;      ///< the mnemonic of dumps and tests
  std::uint8_t operands; ///< slots a, b, c read (0 for Const, Input and Call: an immediate, an
                         ///< input index or a call site)
  std::uint8_t flags;

  constexpr bool has(Flag f) const { return (flags & f) != 0; }
};

namespace detail
{
using F = OpcodeInfo;
// Max/Min are not commutative: NaN picks a side. Sub, Div, Pow... are not either.
inline constexpr std::array<OpcodeInfo, kOpcodeCount> kOpcodeTable{ {
  { Opcode::Const, "const", 0, F::None },
  { Opcode::Input, "input", 0, F::None },
  { Opcode::Add, "add", 2, F::Commutative | F::ImmediateForm },
  { Opcode::Sub, "sub", 2, F::ImmediateForm },
  { Opcode::Mul, "mul", 2, F::Commutative | F::ImmediateForm },
  { Opcode::Div, "div", 2, F::ImmediateForm },
  { Opcode::Neg, "neg", 1, F::None },
  { Opcode::Square, "square", 1, F::None },
  { Opcode::Abs, "abs", 1, F::None },
  { Opcode::Sqrt, "sqrt", 1, F::None },
  { Opcode::Exp, "exp", 1, F::None },
  { Opcode::Log, "log", 1, F::None },
  { Opcode::Log10, "log10", 1, F::None },
  { Opcode::Sin, "sin", 1, F::None },
  { Opcode::Cos, "cos", 1, F::None },
  { Opcode::Tan, "tan", 1, F::None },
  { Opcode::Asin, "asin", 1, F::None },
  { Opcode::Acos, "acos", 1, F::None },
  { Opcode::Atan, "atan", 1, F::None },
  { Opcode::Sinh, "sinh", 1, F::None },
  { Opcode::Cosh, "cosh", 1, F::None },
  { Opcode::Tanh, "tanh", 1, F::None },
  { Opcode::Atan2, "atan2", 2, F::None },
  { Opcode::Pow, "pow", 2, F::None },
  { Opcode::Floor, "floor", 1, F::None },
  { Opcode::Ceil, "ceil", 1, F::None },
  { Opcode::Trunc, "trunc", 1, F::None },
  { Opcode::Frac, "frac", 1, F::None },
  { Opcode::Fmod, "fmod", 2, F::None },
  { Opcode::HfPow, "hf_pow", 2, F::None },
  { Opcode::HfPowInt, "hf_pow_int", 1, F::None },
  { Opcode::HfMod, "hf_mod", 2, F::None },
  { Opcode::HfRound, "hf_round", 1, F::None },
  { Opcode::Max, "max", 2, F::Choice | F::ImmediateForm },
  { Opcode::Min, "min", 2, F::Choice | F::ImmediateForm },
  { Opcode::Union, "union", 2, F::Commutative | F::Choice | F::ImmediateForm },
  { Opcode::Intersect, "intersect", 2, F::Commutative | F::Choice | F::ImmediateForm },
  { Opcode::UnionPlain, "union_plain", 2, F::Commutative | F::Choice | F::ImmediateForm },
  { Opcode::IntersectPlain, "intersect_plain", 2, F::Commutative | F::Choice | F::ImmediateForm },
  { Opcode::Eq, "eq", 2, F::Boolean | F::Commutative },
  { Opcode::Ne, "ne", 2, F::Boolean | F::Commutative },
  { Opcode::Lt, "lt", 2, F::Boolean | F::ImmediateForm },
  { Opcode::Le, "le", 2, F::Boolean | F::ImmediateForm },
  { Opcode::Gt, "gt", 2, F::Boolean | F::ImmediateForm },
  { Opcode::Ge, "ge", 2, F::Boolean | F::ImmediateForm },
  { Opcode::Truthy, "truthy", 1, F::Boolean },
  { Opcode::And, "and", 2, F::Boolean | F::Commutative },
  { Opcode::Or, "or", 2, F::Boolean | F::Commutative },
  { Opcode::Not, "not", 1, F::Boolean },
  { Opcode::Select, "select", 3, F::None },
  { Opcode::ErrorIf, "error_if", 1, F::NoResult },
  { Opcode::Call, "call", 0, F::NoResult },
} };

constexpr bool table_in_enum_order()
{
  for (std::size_t i = 0; i < kOpcodeTable.size(); ++i)
  {
    if (static_cast<std::size_t>(kOpcodeTable[i].op) != i || kOpcodeTable[i].name == nullptr)
    {
      return false;
    }
  }
  return true;
}
static_assert(table_in_enum_order(), "kOpcodeTable: one row per opcode, in the enum's order");
} // namespace detail

/// The row of `op`.
constexpr const OpcodeInfo& opcode_info(Opcode op)
{
  return detail::kOpcodeTable[static_cast<std::size_t>(op)];
}

/// Returns the mnemonic, for dumps and tests ("?" for a value outside the enum).
constexpr const char* opcode_name(Opcode op)
{
  return static_cast<std::size_t>(op) < kOpcodeCount ? opcode_info(op).name : "?";
}

/// How many of the operand slots a, b, c an opcode reads (0 for Const, Input and Call, whose
/// operands are an immediate, an input index or a call site; 3 only for Select).
constexpr int operand_count(Opcode op)
{
  return opcode_info(op).operands;
}

/// Whether the opcode's result is always the boolean 1.0 or 0.0 (comparisons and logic).
constexpr bool is_boolean_opcode(Opcode op)
{
  return opcode_info(op).has(OpcodeInfo::Boolean);
}

} // namespace frep
