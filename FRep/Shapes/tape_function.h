// Any k-D tape (a vtkFRepObject's, a compiled model's) as a user function name(x) over a
// k-item array: how an object built elsewhere (a VTK pipeline, another file) is named inside a
// HyperFun program, with the tape's own enclosures (so culling goes through) and gradients.
#pragma once

#include "Compiler/tape.h"
#include "Language/user_functions.h"

#include <memory>
#include <string>

namespace frep::shapes
{

/// A point where the tape raises a run-time error fails the call (the caller's error policy).
/// Evaluators are pooled: the forms are safe from any number of threads.
UserFunction tape_function(const std::string& name, std::shared_ptr<const Tape> tape);

} // namespace frep::shapes
