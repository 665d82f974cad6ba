// A user function's call site as an opaque tape call (user_functions.h): the point, batch,
// interval and gradient forms the user gave become the OpaqueFunction's forms.
#pragma once

#include "Compiler/tape.h"
#include "Language/user_functions.h"

#include <memory>
#include <vector>

namespace frep::compiler
{

/// Inputs: [path flag, the items of every argument in order (a real is one item)]; output: the
/// value. `sizes` has one entry per argument. When the path flag is 0 (a branch the point does
/// not take) the function is not called and the value is 0. A failure (false or a throw) returns
/// `error_id`.
std::shared_ptr<const OpaqueFunction> make_user_function(
  std::shared_ptr<const UserFunction> function, std::vector<int> sizes, int error_id);

} // namespace frep::compiler
