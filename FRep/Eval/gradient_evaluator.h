// F and its gradient with respect to the tape inputs, by forward-mode differentiation over the
// tape (exact derivatives of every operation; opaque calls are differentiated numerically).
#pragma once

#include "Compiler/tape.h"

#include <memory>
#include <span>
#include <vector>

namespace frep
{

class GradientEvaluator
{
public:
  explicit GradientEvaluator(std::shared_ptr<const Tape> tape);

  /// Returns F (NaN on a run-time error) and writes dF/dinput_k into gradient[k]
  /// (gradient.size() == tape input count).
  double evaluate(std::span<const double> inputs, std::span<double> gradient);

private:
  std::shared_ptr<const Tape> tape_;
  std::vector<double> values_;
  std::vector<double> derivatives_; // slot-major: derivatives_[slot * n + k]
  std::vector<std::unique_ptr<struct GradientScratch>> scratch_;
};

} // namespace frep
