// User primitives: functions written in C or C++ that a HyperFun program calls by name, like a
// library function. They live in an explicit registry handed to the parser (ParseOptions) and kept
// by the program it returns, so the compiler and the interpreter find them there: no global
// table, and two models in one process may see different user functions.
#pragma once

#include "function_table.h"

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace frep
{

/// One argument as a user function sees it: a real (size 1) or the items of an array.
struct UserArgument
{
  const double* values = nullptr;
  int size = 0;
};

/// One argument over a box: the bounds of each item (size as UserArgument).
struct UserIntervalArgument
{
  const double* lo = nullptr;
  const double* hi = nullptr;
  int size = 0;
};

/// One argument of a batch call: item k of lane i is values[k * count + i].
struct UserBatchArgument
{
  const double* values = nullptr;
  int size = 0;
};

/// A user function. Only `name`, `kinds` and `point` are required. Every form must be safe to
/// call from several threads at once (the evaluators share one registry). A form reports a
/// failure at a point by returning false or by throwing; the point then has the run-time error
/// "User function NAME failed" (the error policy of compatibility.md applies to it).
struct UserFunction
{
  std::string name;              ///< as spelled; looked up case-insensitively
  std::vector<ArgKind> kinds;    ///< Real or Array, one per argument (String is refused)
  /// For each Array argument the number of items it must have (0: any; ignored for reals).
  /// Empty: any sizes.
  std::vector<int> array_sizes;

  /// value = f(args).
  std::function<bool(std::span<const UserArgument> args, double& value)> point;
  /// Optional: `count` points at once (values[count], failed[count] set to 1 where it fails).
  std::function<void(std::span<const UserBatchArgument> args, int count, double* values,
    unsigned char* failed)>
    batch;
  /// Optional: an enclosure of f over a box of arguments. Without it the enclosure is the
  /// whole line (never wrong, never culled). Set may_fail when some point of the box may fail.
  std::function<bool(std::span<const UserIntervalArgument> args, double& lo, double& hi,
    bool& may_fail)>
    interval;
  /// Optional: value and the derivatives by every item of every argument, in argument order
  /// (gradient.size() = the total item count). Without it: central differences.
  std::function<bool(std::span<const UserArgument> args, double& value, std::span<double> gradient)>
    gradient;
};

/// The run-time error a failing user function raises at its call's position.
std::string user_function_error(std::string_view name);

/// Functions by name. Copyable; the forms are shared between copies.
class UserFunctionRegistry
{
public:
  /// Registers a function; returns an empty string, or why it is refused: an empty or invalid
  /// name (letters, digits, '_', starting with a letter), a name of the library or builtins, a
  /// name registered before, no point form, a String or unknown argument kind, more than
  /// kMaxFunctionArity arguments, array_sizes that do not fit the kinds.
  std::string add(UserFunction function);

  /// Index of a function by name (case-insensitive), or nullopt.
  std::optional<int> find(std::string_view name) const;

  const UserFunction& at(int index) const { return *functions_.at(static_cast<std::size_t>(index)); }
  std::shared_ptr<const UserFunction> shared(int index) const
  {
    return functions_.at(static_cast<std::size_t>(index));
  }
  int size() const { return static_cast<int>(functions_.size()); }
  bool empty() const { return functions_.empty(); }

  /// Adds every function of `other` (errors as add(), the first one returned).
  std::string merge(const UserFunctionRegistry& other);

private:
  std::vector<std::shared_ptr<const UserFunction>> functions_;
  std::vector<std::string> keys_; ///< lower-case names
};

/// "bunny(array[3])", "gear(array, real, real)": for diagnostics.
std::string user_function_signature(const UserFunction& function);

} // namespace frep
