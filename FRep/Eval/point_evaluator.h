// Evaluates a tape at one point at a time. Exact: the same operations in the same order as the
// original interpreter (see Semantics/detail/op_semantics.h). One evaluator per thread; tapes are
// shared.
#pragma once

#include "Compiler/tape.h"

#include <memory>
#include <span>
#include <vector>

namespace frep
{

class PointEvaluator
{
public:
  explicit PointEvaluator(std::shared_ptr<const Tape> tape);

  const Tape& tape() const { return *tape_; }

  /// Evaluates every output (value, s[1..]) at `inputs` (size tape().input_count). Returns 0, or
  /// the 1-based error id of the first run-time error, in which case the outputs are NaN.
  int evaluate(std::span<const double> inputs, std::span<double> outputs);

  /// F at `inputs`, NaN when the point raised a run-time error.
  double value(std::span<const double> inputs);

private:
  std::shared_ptr<const Tape> tape_;
  std::vector<double> slots_;
  std::vector<std::unique_ptr<OpaqueFunction::Scratch>> call_scratch_;
  std::vector<double> call_in_;
  std::vector<double> call_out_;
};

} // namespace frep
