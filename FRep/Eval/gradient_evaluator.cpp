#include "Eval/gradient_evaluator.h"

#include "Semantics/detail/op_semantics.h"
#include "Eval/detail/instruction_value.h"
#include "Compiler/detail/tape_check.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace frep
{

namespace
{
namespace hf = frep::semantics;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The partial derivatives of one instruction's operation at its operands: d = ca da + cb db,
/// or the whole derivative of one operand (`pick`: select, max, min).
struct Partials
{
  double ca = 0;
  double cb = 0;
  const double* pick = nullptr;
};

/// HyperFun's a ^ b: locally a ^ n (n constant) for an integral b, else exp(b ln a).
[[gnu::always_inline]] inline void hf_pow_partials(double a, double b, double r, Partials& p)
{
  if (std::fabs(a) < hf::kEps)
  {
    return; // constant 0 there
  }
  if ((b - std::floor(b)) < hf::kEps)
  {
    // a ^ n with n = HF_round(|b|) signed: locally constant in b.
    // Beyond the int range hf_round gives INT_MIN, the repeated product runs no
    // iteration and the value is the constant 1: derivative 0 (and -m would overflow,
    // found by fuzz_hyperfun_eval under UBSan).
    const int m = hf::hf_round(std::fabs(b));
    if (m != std::numeric_limits<int>::min())
    {
      const double e = b < 0.0 ? -static_cast<double>(m) : static_cast<double>(m);
      p.ca = e == 0 ? 0.0 : e * std::pow(a, e - 1);
    }
  }
  else
  {
    p.ca = r * b / a;
    p.cb = r * std::log(a);
  }
}

/// Partials of the instruction at operand values a, b (c: Select) with result r; da, db, dc the
/// operands' derivatives. Inlined into the evaluation loop's one switch.
[[gnu::always_inline]] inline Partials partials(const Instruction& ins, double a, double b,
  double r, const double* da, const double* db, const double* dc)
{
  Partials p;
  switch (ins.op)
  {
    case Opcode::Add:
      p.ca = 1;
      p.cb = 1;
      break;
    case Opcode::Sub:
      p.ca = 1;
      p.cb = -1;
      break;
    case Opcode::Mul:
      p.ca = b;
      p.cb = a;
      break;
    case Opcode::Div:
      p.ca = 1 / b;
      p.cb = -a / (b * b);
      break;
    case Opcode::Neg:
      p.ca = -1;
      break;
    case Opcode::Square:
      p.ca = 2 * a;
      break;
    case Opcode::Abs:
      p.ca = a > 0 ? 1.0 : (a < 0 ? -1.0 : 0.0);
      break;
    case Opcode::Sqrt:
      p.ca = 0.5 / r;
      break;
    case Opcode::Exp:
      p.ca = r;
      break;
    case Opcode::Log:
      p.ca = 1 / a;
      break;
    case Opcode::Log10:
      p.ca = 1 / (a * std::numbers::ln10);
      break;
    case Opcode::Sin:
      p.ca = std::cos(a);
      break;
    case Opcode::Cos:
      p.ca = -std::sin(a);
      break;
    case Opcode::Tan:
      p.ca = 1 + r * r;
      break;
    case Opcode::Asin:
      p.ca = 1 / std::sqrt(1 - a * a);
      break;
    case Opcode::Acos:
      p.ca = -1 / std::sqrt(1 - a * a);
      break;
    case Opcode::Atan:
      p.ca = 1 / (1 + a * a);
      break;
    case Opcode::Sinh:
      p.ca = std::cosh(a);
      break;
    case Opcode::Cosh:
      p.ca = std::sinh(a);
      break;
    case Opcode::Tanh:
      p.ca = 1 - r * r;
      break;
    case Opcode::Atan2:
    {
      const double q = a * a + b * b;
      p.ca = b / q;
      p.cb = -a / q;
      break;
    }
    case Opcode::Pow:
      p.ca = b == 0 ? 0.0 : b * std::pow(a, b - 1);
      p.cb = a > 0 ? r * std::log(a) : 0.0;
      break;
    case Opcode::Frac:
      p.ca = std::isfinite(a) ? 1.0 : 0.0;
      break;
    case Opcode::Fmod:
      // fmod(a, b) = a - q b with the integer q = trunc(a / b), locally constant.
      p.ca = 1;
      p.cb = -std::trunc((a - r) / b);
      break;
    case Opcode::HfPow:
      hf_pow_partials(a, b, r, p);
      break;
    case Opcode::HfPowInt:
      if (std::fabs(a) >= hf::kEps && ins.index != 0)
      {
        p.ca = ins.index * std::pow(a, ins.index - 1);
      }
      break;
    case Opcode::Max:
      p.pick = (a > b) ? da : db;
      break;
    case Opcode::Min:
      p.pick = (a < b) ? da : db;
      break;
    case Opcode::Union:
    case Opcode::Intersect:
    case Opcode::UnionPlain:
    case Opcode::IntersectPlain:
    {
      // d/dl (l + r ± sqrt(l² + r²)) = 1 ± l / sqrt(l² + r²); at the origin, where it is not
      // differentiable, the square-root term is left out.
      const double s = std::sqrt(a * a + b * b);
      const double sign = ins.op == Opcode::Union || ins.op == Opcode::UnionPlain ? 1.0 : -1.0;
      p.ca = s > 0 ? 1 + sign * a / s : 1.0;
      p.cb = s > 0 ? 1 + sign * b / s : 1.0;
      break;
    }
    case Opcode::Select:
      p.pick = a != 0.0 ? db : dc;
      break;
    default:
      break; // constants, steps, comparisons, logic: derivative 0
  }
  return p;
}

/// d = ca da + cb db over the n inputs, or a copy of the picked operand's derivative.
[[gnu::always_inline]] inline void combine(double* d, const Partials& p, const double* da,
  const double* db, std::size_t n)
{
  if (p.pick != nullptr)
  {
    if (p.pick != d)
    {
      std::copy(p.pick, p.pick + n, d);
    }
  }
  else
  {
    // Operands may share the output slot: read before write, lane by lane. A zero partial
    // or a zero operand derivative contributes nothing, even where the other is infinite
    // (sqrt at 0 of a constant).
    for (std::size_t k = 0; k < n; ++k)
    {
      const double x = (p.ca == 0 || da[k] == 0) ? 0.0 : p.ca * da[k];
      const double y = (p.cb == 0 || db[k] == 0) ? 0.0 : p.cb * db[k];
      d[k] = x + y;
    }
  }
}

} // namespace

GradientEvaluator::GradientEvaluator(std::shared_ptr<const Tape> tape)
  : tape_(std::move(tape))
{
  if (!tape_)
  {
    throw std::invalid_argument("GradientEvaluator: null tape");
  }
  eval::check_tape(*tape_, "GradientEvaluator");
  const std::size_t n = tape_->input_count;
  values_.assign(tape_->slot_count, 0.0);
  derivatives_.assign(static_cast<std::size_t>(tape_->slot_count) * n, 0.0);
  std::size_t widest_in = 0;
  std::size_t widest_out = 0;
  for (const CallSite& site : tape_->calls)
  {
    call_scratch_.push_back(site.function->make_scratch());
    widest_in = std::max(widest_in, site.inputs.size());
    widest_out = std::max(widest_out, site.outputs.size());
  }
  call_in_.assign(widest_in, 0.0);
  call_out_.assign(widest_out, 0.0);
  call_plus_.assign(widest_out, 0.0);
  call_minus_.assign(widest_out, 0.0);
  call_jacobian_.assign(widest_in * widest_out, 0.0);
}

// Evaluates an opaque call at its input values and differentiates it by central differences,
// one input at a time (one-sided where one side fails, 0 where both do). Returns the call's
// error id at the unperturbed point.
int GradientEvaluator::call(const CallSite& site, std::size_t site_index)
{
  const std::size_t n = tape_->input_count;
  const std::size_t n_in = site.inputs.size();
  const std::size_t n_out = site.outputs.size();
  OpaqueFunction::Scratch* scratch = call_scratch_[site_index].get();
  const auto run = [&](std::vector<double>& out)
  {
    return site.function->evaluate(scratch,
      std::span<const double>(call_in_.data(), n_in),
      std::span<double>(out.data(), n_out));
  };
  for (std::size_t i = 0; i < n_in; ++i)
  {
    call_in_[i] = values_[site.inputs[i]];
  }
  // Exact derivatives when the function gives them (a user function's gradient form).
  const bool exact = site.function->has_jacobian();
  const int status = exact
    ? site.function->evaluate_jacobian(scratch, std::span<const double>(call_in_.data(), n_in),
        std::span<double>(call_out_.data(), n_out),
        std::span<double>(call_jacobian_.data(), n_in * n_out))
    : run(call_out_);
  if (status != 0)
  {
    return status;
  }
  for (std::size_t i = 0; i < n_in && !exact; ++i)
  {
    const double x = call_in_[i];
    // cbrt(machine epsilon) balances truncation and rounding error of a central difference.
    const double h = 6.0e-6 * std::max(1.0, std::fabs(x));
    const double xp = x + h;
    const double xm = x - h;
    call_in_[i] = xp;
    const bool ok_plus = run(call_plus_) == 0;
    call_in_[i] = xm;
    const bool ok_minus = run(call_minus_) == 0;
    call_in_[i] = x;
    for (std::size_t j = 0; j < n_out; ++j)
    {
      double d = 0;
      if (ok_plus && ok_minus)
      {
        d = (call_plus_[j] - call_minus_[j]) / (xp - xm);
      }
      else if (ok_plus)
      {
        d = (call_plus_[j] - call_out_[j]) / (xp - x);
      }
      else if (ok_minus)
      {
        d = (call_out_[j] - call_minus_[j]) / (x - xm);
      }
      call_jacobian_[j * n_in + i] = d;
    }
  }
  for (std::size_t j = 0; j < n_out; ++j)
  {
    const std::uint32_t out = site.outputs[j];
    double* dout = derivatives_.data() + static_cast<std::size_t>(out) * n;
    std::fill(dout, dout + n, 0.0);
    for (std::size_t i = 0; i < n_in; ++i)
    {
      const double c = call_jacobian_[j * n_in + i];
      const double* din = derivatives_.data() + static_cast<std::size_t>(site.inputs[i]) * n;
      for (std::size_t k = 0; k < n; ++k)
      {
        dout[k] += c * din[k];
      }
    }
  }
  // Values last: an output slot may also be an input slot of the same call.
  for (std::size_t j = 0; j < n_out; ++j)
  {
    values_[site.outputs[j]] = call_out_[j];
  }
  return 0;
}

double GradientEvaluator::evaluate(std::span<const double> inputs, std::span<double> gradient)
{
  const Tape& tape = *tape_;
  const std::size_t n = tape.input_count;
  if (inputs.size() < n || gradient.size() < n)
  {
    throw std::invalid_argument("GradientEvaluator::evaluate: span smaller than the input count");
  }
  double* v = values_.data();
  int error = 0;
  for (const Instruction& ins : tape.code)
  {
    const Opcode op = ins.op;
    if (op == Opcode::ErrorIf)
    {
      if (v[ins.a] != 0.0)
      {
        error = ins.index;
        break;
      }
      continue;
    }
    if (op == Opcode::Call)
    {
      error =
        call(tape.calls[static_cast<std::size_t>(ins.index)], static_cast<std::size_t>(ins.index));
      if (error != 0)
      {
        break;
      }
      continue;
    }
    double* d = derivatives_.data() + static_cast<std::size_t>(ins.out) * n;
    if (op == Opcode::Input)
    {
      const std::size_t k = static_cast<std::size_t>(ins.index);
      v[ins.out] = inputs[k];
      std::fill(d, d + n, 0.0);
      d[k] = 1.0;
      continue;
    }
    const double a = v[ins.a];
    const double b = v[ins.b];
    const double c = v[ins.c];
    const double* da = derivatives_.data() + static_cast<std::size_t>(ins.a) * n;
    const double* db = derivatives_.data() + static_cast<std::size_t>(ins.b) * n;
    const double* dc = derivatives_.data() + static_cast<std::size_t>(ins.c) * n;
    const double r = eval::apply(ins, a, b, c);
    combine(d, partials(ins, a, b, r, da, db, dc), da, db, n);
    v[ins.out] = r;
  }
  if (error != 0 || tape.outputs.empty())
  {
    std::fill(gradient.begin(), gradient.begin() + static_cast<std::ptrdiff_t>(n), kNaN);
    return kNaN;
  }
  const double* df = derivatives_.data() + static_cast<std::size_t>(tape.outputs[0]) * n;
  std::copy(df, df + n, gradient.begin());
  return v[tape.outputs[0]];
}

} // namespace frep
