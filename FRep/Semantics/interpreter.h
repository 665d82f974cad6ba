// The reference interpreter: evaluates an object of a parsed program point by point with the
// original interpreter's exact semantics (right-to-left operands, in-place library arrays,
// run-time errors with the original's messages and positions, a[] and s[] persisting between
// points as in hfp). It is the ground truth the compiled evaluators are tested against and the
// fallback for models the compiler cannot turn into a tape (data-dependent loops).
//
// An Interpreter holds per-run state (a[], s[]); use one per thread. The program is shared and
// never modified, so any number of Interpreters may evaluate one Program concurrently.
#pragma once

#include "Language/ast.h"
#include "Language/source_location.h"

#include <cstdint>
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
  /// The file of the object it happened in (ast::Object::file: the model's or a library
  /// file's): the same message at the same line and column of two files are two errors.
  std::string file{};
};

struct PointResult
{
  double value = 0; ///< F at the point (meaningless when error is set)
  std::optional<RuntimeError> error;
};

struct InterpreterOptions
{
  /// Most `while` iterations one evaluation may run (all loops of the object and its callees
  /// together); beyond it the point fails with "Loop iteration limit exceeded". The original has
  /// no limit: this only guarantees that a tool never hangs on an endless loop. 0 = no limit.
  std::int64_t max_loop_iterations = 100'000'000;
};

/// The message of the iteration-cap error (not one of the original's messages).
inline constexpr const char* kLoopLimitMessage = "Loop iteration limit exceeded";

class Interpreter
{
public:
  /// Evaluates program->objects[object_index]. Throws std::invalid_argument when the program is
  /// null, the index is out of range or the AST is inconsistent (slots, arities, call targets
  /// or array sizes that the parser would never produce): evaluation itself then never needs to
  /// check them. a[] and s[] start at zero.
  Interpreter(std::shared_ptr<const ast::Program> program,
    int object_index,
    const InterpreterOptions& options = {});
  ~Interpreter();
  Interpreter(Interpreter&&) noexcept;
  Interpreter& operator=(Interpreter&&) noexcept;
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  const ast::Object& object() const;
  const std::shared_ptr<const ast::Program>& program() const { return program_; }

  /// Sets a[1..a_dim] (missing values are 0, extra values ignored). Persists across points:
  /// whatever the model writes into a[] stays, as in hfp.
  void set_parameters(std::span<const double> a);

  /// Resets s[] to zeros (it otherwise persists across points, as in hfp, even after an error).
  void reset_attributes();

  /// Evaluates at x[1..x_dim] (missing coordinates are 0, extra ones ignored). Local variables
  /// start unset; a[] and s[] are whatever the previous evaluations left.
  PointResult evaluate(std::span<const double> x);

  /// a[] and s[] after the last evaluation.
  std::span<const double> parameters() const;
  std::span<const double> attributes() const;

private:
  struct State;
  std::shared_ptr<const ast::Program> program_;
  int object_index_;
  std::unique_ptr<State> state_;
};

} // namespace frep
