// The reference interpreter: evaluates an object of a parsed program point by point with the
// original interpreter's exact semantics (right-to-left operands, in-place library arrays,
// run-time errors with the original's messages and positions, a[] and s[] persisting between
// points as in hfp). It is the ground truth the compiled evaluators are tested against and the
// fallback for models the compiler cannot turn into a tape (data-dependent loops).
//
// An Interpreter holds per-run state (a[], s[]); use one per thread. The program is shared.
#pragma once

#include "Language/ast.h"
#include "Language/source_location.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace frep
{

/// A run-time error of one evaluation.
struct RuntimeError
{
  std::string message;     ///< the original's text, e.g. "Division by zero"
  SourceLocation location; ///< the position the original attaches (operator, function name...)
  bool abort = false;      ///< the original called error() and aborted the whole run
};

struct PointResult
{
  double value = 0;                 ///< F at the point (meaningless when error is set)
  std::optional<RuntimeError> error;
};

class Interpreter
{
public:
  /// Evaluates program.objects[object_index]. The program must outlive nothing: it is shared.
  Interpreter(std::shared_ptr<const ast::Program> program, int object_index);

  const ast::Object& object() const;

  /// Sets a[1..a_dim] (missing values are 0, extra values ignored). Persists across points:
  /// whatever the model writes into a[] stays, as in hfp.
  void set_parameters(std::span<const double> a);

  /// Resets s[] to zeros (it otherwise persists across points, as in hfp).
  void reset_attributes();

  /// Evaluates at x[1..x_dim] (x.size() must equal x_dim).
  PointResult evaluate(std::span<const double> x);

  /// a[] and s[] after the last evaluation.
  std::span<const double> parameters() const;
  std::span<const double> attributes() const;

private:
  struct State;
  std::shared_ptr<const ast::Program> program_;
  int object_index_;
  std::vector<double> a_;
  std::vector<double> s_;
};

} // namespace frep
