// Opaque tape calls: a library function without a generic form (evaluated by library::call on
// doubles), and the whole-object interpreter fallback.
#pragma once

#include "Compiler/tape.h"
#include "Language/ast.h"

#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace frep::compiler
{

/// Messages library functions abort with (DoubleContext::abort_message), registered as tape
/// errors at every opaque library call site.
std::span<const char* const> library_abort_messages();

/// A library call as an opaque function. Inputs: [path flag, real arguments in declaration
/// order, the items of each distinct array buffer]; outputs: [result, the buffer items after the
/// call]. When the path flag is 0 (the call is on a branch the point does not take) nothing is
/// evaluated and the items pass through. `buffer_of[i]` is the buffer of argument i when
/// `is_array[i]`; `aborts` maps abort messages to tape error ids.
std::shared_ptr<const OpaqueFunction> make_library_function(FunctionId id,
  std::vector<std::size_t> buffer_of,
  std::vector<bool> is_array,
  std::vector<std::size_t> buffer_sizes,
  std::vector<std::pair<std::string, int>> aborts);

/// The reference Interpreter as one opaque function (the fallback for objects the compiler
/// cannot lower). Inputs: x[1..x_dim]; outputs: value, s[1..s_dim]. Every point starts from the
/// given parameters and s[] = 0 (the conformance "fresh" mode). Run-time errors map to the
/// tape errors `errors` (by message and position); `unknown_error` is used for any other.
std::shared_ptr<const OpaqueFunction> make_interpreter_function(
  std::shared_ptr<const ast::Program> program,
  int object_index,
  std::vector<double> parameters,
  std::vector<TapeError> errors,
  int unknown_error);

/// Every (message, position) pair the interpreter can report for the object (and the objects it
/// calls), so that the fallback tape can name each error it may raise.
std::vector<TapeError> possible_errors(const ast::Program& program, int object_index);

} // namespace frep::compiler
