#include "Compiler/detail/user_call.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace frep::compiler
{
namespace
{

class UserCall final : public OpaqueFunction
{
public:
  UserCall(std::shared_ptr<const UserFunction> function, std::vector<int> sizes, int error_id)
    : function_(std::move(function))
    , sizes_(std::move(sizes))
    , error_id_(error_id)
  {
    for (int s : sizes_)
    {
      items_ += static_cast<std::size_t>(s);
    }
  }

  int evaluate(Scratch*, std::span<const double> inputs, std::span<double> outputs) const override
  {
    if (inputs.size() != 1 + items_ || outputs.size() != 1)
    {
      return error_id_;
    }
    if (inputs[0] == 0.0)
    {
      outputs[0] = 0.0;
      return 0;
    }
    const std::array<UserArgument, kMaxFunctionArity> args = arguments(inputs);
    try
    {
      double value = 0;
      if (!function_->point(std::span(args.data(), sizes_.size()), value))
      {
        return error_id_;
      }
      outputs[0] = value;
      return 0;
    }
    catch (...)
    {
      return error_id_; // a throw is a run-time error of this point, never the caller's crash
    }
  }

  bool evaluate_lanes(Scratch* scratch, const double* const* inputs, int count,
    double* const* outputs, std::uint32_t* errors) const override
  {
    if (!function_->batch)
    {
      return false;
    }
    // The batch form wants argument-major rows; the tape has one row per item already.
    std::vector<double> rows(items_ * static_cast<std::size_t>(count));
    for (std::size_t k = 0; k < items_; ++k)
    {
      std::copy_n(inputs[1 + k], count, rows.begin() + static_cast<std::ptrdiff_t>(k * count));
    }
    std::array<UserBatchArgument, kMaxFunctionArity> args{};
    std::size_t offset = 0;
    for (std::size_t i = 0; i < sizes_.size(); ++i)
    {
      args[i] = UserBatchArgument{ rows.data() + offset * count, sizes_[i] };
      offset += static_cast<std::size_t>(sizes_[i]);
    }
    std::vector<unsigned char> failed(static_cast<std::size_t>(count), 0);
    try
    {
      function_->batch(std::span(args.data(), sizes_.size()), count, outputs[0], failed.data());
    }
    catch (...)
    {
      std::fill(failed.begin(), failed.end(), 1);
    }
    (void)scratch;
    const double* path = inputs[0];
    for (int i = 0; i < count; ++i)
    {
      if (path[i] == 0.0)
      {
        outputs[0][i] = 0.0;
      }
      else if (failed[static_cast<std::size_t>(i)] && errors[i] == 0)
      {
        errors[i] = static_cast<std::uint32_t>(error_id_);
      }
    }
    return true;
  }

  bool enclose(std::span<const double> lo, std::span<const double> hi, std::span<double> out_lo,
    std::span<double> out_hi, bool& may_fail) const override
  {
    if (!function_->interval || lo.size() != 1 + items_ || out_lo.size() != 1)
    {
      return false;
    }
    std::array<UserIntervalArgument, kMaxFunctionArity> args{};
    std::size_t offset = 1;
    for (std::size_t i = 0; i < sizes_.size(); ++i)
    {
      args[i] = UserIntervalArgument{ lo.data() + offset, hi.data() + offset, sizes_[i] };
      offset += static_cast<std::size_t>(sizes_[i]);
    }
    double l = 0;
    double h = 0;
    bool fails = false;
    try
    {
      if (!function_->interval(std::span(args.data(), sizes_.size()), l, h, fails))
      {
        return false;
      }
    }
    catch (...)
    {
      return false;
    }
    if (std::isnan(l) || std::isnan(h) || l > h)
    {
      return false; // a broken enclosure must never pass for one
    }
    // Off the path the value is 0: widen to include it unless the path is surely taken.
    if (lo[0] <= 0.0 && hi[0] >= 0.0)
    {
      l = std::min(l, 0.0);
      h = std::max(h, 0.0);
    }
    out_lo[0] = l;
    out_hi[0] = h;
    may_fail = fails;
    return true;
  }

  bool has_jacobian() const override { return static_cast<bool>(function_->gradient); }

  int evaluate_jacobian(Scratch* scratch, std::span<const double> inputs,
    std::span<double> outputs, std::span<double> jacobian) const override
  {
    if (!function_->gradient || inputs.size() != 1 + items_ || outputs.size() != 1 ||
        jacobian.size() < inputs.size())
    {
      return evaluate(scratch, inputs, outputs);
    }
    std::fill(jacobian.begin(), jacobian.end(), 0.0);
    if (inputs[0] == 0.0)
    {
      outputs[0] = 0.0;
      return 0;
    }
    const std::array<UserArgument, kMaxFunctionArity> args = arguments(inputs);
    try
    {
      double value = 0;
      if (!function_->gradient(std::span(args.data(), sizes_.size()), value,
            jacobian.subspan(1, items_)))
      {
        return error_id_;
      }
      outputs[0] = value;
      return 0;
    }
    catch (...)
    {
      return error_id_;
    }
  }

private:
  /// The call's inputs after the path flag, cut into the function's arguments.
  std::array<UserArgument, kMaxFunctionArity> arguments(std::span<const double> inputs) const
  {
    std::array<UserArgument, kMaxFunctionArity> args{};
    const double* p = inputs.data() + 1;
    for (std::size_t i = 0; i < sizes_.size(); ++i)
    {
      args[i] = UserArgument{ p, sizes_[i] };
      p += sizes_[i];
    }
    return args;
  }

  std::shared_ptr<const UserFunction> function_;
  std::vector<int> sizes_;
  std::size_t items_ = 0;
  int error_id_;
};

} // namespace

std::shared_ptr<const OpaqueFunction> make_user_function(
  std::shared_ptr<const UserFunction> function, std::vector<int> sizes, int error_id)
{
  return std::make_shared<UserCall>(std::move(function), std::move(sizes), error_id);
}

} // namespace frep::compiler
