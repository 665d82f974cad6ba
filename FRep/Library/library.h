// The HyperFun library (hf* primitives, operations, transformations, SARDF family, hfA_*
// attribute functions): one implementation per function, value-compatible with the original
// C library (pmur002/hyperfun src/hflibrary_lib), written once as templates over the scalar type
// where the function is straight-line arithmetic, so that
//   - T = double gives the reference values (the interpreter, opaque calls in tapes), and
//   - T = frep::compiler::Expr (a symbolic scalar) expands the call into DAG nodes.
// Functions that cannot be written that way (iterative solvers, value-dependent loop counts,
// table searches) have a double-only implementation; the compiler calls them as opaque nodes.
//
// The builtins (sqrt ... frac, FunctionId < Sphere) are not here: the interpreter and compiler
// implement them because they raise run-time errors at source positions.
#pragma once

#include "Language/function_table.h"

#include <optional>
#include <span>
#include <string>

namespace frep::library
{

/// EPS of the original (double EPS = 0.1e-5).
inline constexpr double kEps = 1e-6;
/// Returned by most primitives when the point array does not have 3 items.
inline constexpr double kWrongDimension = -1111111111111.0;

/// One argument, in declaration position: `real` is set for ArgKind::Real, `array` (a mutable
/// view: in-place transformations write through it) for ArgKind::Array.
template <class T>
struct Arg
{
  T real{};
  std::span<T> array{};
};

/// What a double call reports besides its value: the original's error() ("abort").
struct DoubleContext
{
  std::optional<std::string> abort_message;

  /// Records the first abort whose condition holds.
  void abort_if(bool condition, const char* message)
  {
    if (condition && !abort_message)
    {
      abort_message = message;
    }
  }
};

/// Reference evaluation of a library function (FunctionId >= Sphere) with double arguments in
/// declaration order. Array arguments are modified in place exactly as the original does.
/// Sets context.abort_message where the original calls error().
double call(FunctionId id, std::span<Arg<double>> args, DoubleContext& context);

/// True when `id` has a template implementation usable with a symbolic scalar (see
/// library_generic.h); false for double-only functions, which the compiler calls opaquely.
bool is_generic(FunctionId id);

} // namespace frep::library
