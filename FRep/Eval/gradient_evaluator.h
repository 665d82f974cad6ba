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
  /// (gradient.size() == tape input count; NaN on a run-time error). F is bit-identical to
  /// PointEvaluator. Where an operation is not differentiable (|x| at 0, a kink of max/min, a
  /// step of floor or a comparison) the derivative of the branch actually taken is used.
  double evaluate(std::span<const double> inputs, std::span<double> gradient);

private:
  int call(const CallSite& site, std::size_t site_index);

  std::shared_ptr<const Tape> tape_;
  std::vector<double> values_;
  std::vector<double> derivatives_; // slot-major: derivatives_[slot * n + k]
  std::vector<std::unique_ptr<OpaqueFunction::Scratch>> call_scratch_; // per call site
  std::vector<double> call_in_;
  std::vector<double> call_out_;
  std::vector<double> call_plus_;     // outputs at in + h e_i
  std::vector<double> call_minus_;    // outputs at in - h e_i
  std::vector<double> call_jacobian_; // d out_j / d in_i at [j * inputs + i]
};

} // namespace frep
