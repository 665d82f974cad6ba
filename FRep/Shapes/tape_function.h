// Any k-D tape (a vtkFRepObject's, a compiled model's) as a user function name(x) over a
// k-item array: how an object built elsewhere (a VTK pipeline, another file) is named inside a
// HyperFun program, with the tape's own enclosures (so culling goes through) and gradients.
#pragma once

#include "Compiler/tape.h"
#include "Eval/interval_evaluator.h"
#include "Language/user_functions.h"

#include <functional>
#include <span>

#include <memory>
#include <string>

namespace frep::shapes
{

/// The forms of a function of one k-item array, each over the array's items (a point, a box).
/// `point` is required; the others may be empty (no enclosure: the whole line; no gradient:
/// differences). Each must be safe from any thread.
struct ArrayForms
{
  std::function<double(std::span<const double> x)> point;           ///< NaN: the point fails
  std::function<IntervalResult(std::span<const Interval> box)> interval;
  std::function<double(std::span<const double> x, std::span<double> gradient)> gradient;
};

/// name(x) over a k-item array, from its forms: what tape_function and Project's
/// projection_function are made of.
UserFunction array_function(const std::string& name, int k, ArrayForms forms);

/// A point where the tape raises a run-time error fails the call (the caller's error policy).
/// Evaluators are pooled: the forms are safe from any number of threads.
UserFunction tape_function(const std::string& name, std::shared_ptr<const Tape> tape);

} // namespace frep::shapes
