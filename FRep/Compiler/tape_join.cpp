#include "Compiler/detail/tape_join.h"

#include "Compiler/detail/tape_check.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace frep::compiler
{

namespace
{

constexpr NodeId kUnset = std::numeric_limits<NodeId>::max();

/// An opaque function whose error ids are those of another tape: a called function returns a
/// 1-based id into the error table of the tape it was made for, which starts at `offset` + 1 in
/// the joined table.
class RenumberedErrors final : public OpaqueFunction
{
public:
  RenumberedErrors(std::shared_ptr<const OpaqueFunction> inner, int offset)
    : inner_(std::move(inner))
    , offset_(offset)
  {
  }

  /// Wraps `function` (or the function it wraps, so that joins of joins stay one call deep).
  static std::shared_ptr<const OpaqueFunction> wrap(std::shared_ptr<const OpaqueFunction> function,
    int offset)
  {
    if (offset == 0)
    {
      return function;
    }
    if (const auto* renumbered = dynamic_cast<const RenumberedErrors*>(function.get()))
    {
      return std::make_shared<RenumberedErrors>(renumbered->inner_, renumbered->offset_ + offset);
    }
    return std::make_shared<RenumberedErrors>(std::move(function), offset);
  }

  std::unique_ptr<Scratch> make_scratch() const override { return inner_->make_scratch(); }

  int evaluate(Scratch* scratch,
    std::span<const double> inputs,
    std::span<double> outputs) const override
  {
    const int id = inner_->evaluate(scratch, inputs, outputs);
    return id > 0 ? id + offset_ : id;
  }

  // The optional forms pass through, their error ids renumbered like evaluate()'s.
  bool evaluate_lanes(Scratch* scratch, const double* const* inputs, int count,
    double* const* outputs, std::uint32_t* errors) const override
  {
    std::vector<std::uint32_t> inner(errors, errors + count);
    if (!inner_->evaluate_lanes(scratch, inputs, count, outputs, inner.data()))
    {
      return false;
    }
    for (int i = 0; i < count; ++i)
    {
      if (errors[i] == 0 && inner[static_cast<std::size_t>(i)] != 0)
      {
        errors[i] = inner[static_cast<std::size_t>(i)] + static_cast<std::uint32_t>(offset_);
      }
    }
    return true;
  }
  bool enclose(std::span<const double> lo, std::span<const double> hi, std::span<double> out_lo,
    std::span<double> out_hi, bool& may_fail) const override
  {
    return inner_->enclose(lo, hi, out_lo, out_hi, may_fail);
  }
  bool has_jacobian() const override { return inner_->has_jacobian(); }
  int evaluate_jacobian(Scratch* scratch, std::span<const double> inputs,
    std::span<double> outputs, std::span<double> jacobian) const override
  {
    const int id = inner_->evaluate_jacobian(scratch, inputs, outputs, jacobian);
    return id > 0 ? id + offset_ : id;
  }

private:
  std::shared_ptr<const OpaqueFunction> inner_;
  int offset_ = 0;
};

[[noreturn]] void malformed(const std::string& what)
{
  throw std::invalid_argument("append_tape: malformed tape: " + what);
}

} // namespace

std::vector<NodeId> append_tape(Lowered& out, const Tape& tape, std::span<const NodeId> inputs)
{
  if (inputs.size() != tape.input_count)
  {
    throw std::invalid_argument("append_tape: the tape has " + std::to_string(tape.input_count) +
                                " inputs, " + std::to_string(inputs.size()) + " given");
  }
  eval::check_tape(tape, "append_tape");
  Dag& dag = out.dag;
  const int error_offset = static_cast<int>(out.errors.size());
  out.errors.insert(out.errors.end(), tape.errors.begin(), tape.errors.end());

  // The node each slot holds at this point of the tape (slots are reused, so this changes).
  std::vector<NodeId> node(tape.slot_count, kUnset);
  const auto read = [&](std::uint32_t slot)
  {
    if (node[slot] == kUnset)
    {
      malformed("slot " + std::to_string(slot) + " is read before it is written");
    }
    return node[slot];
  };

  for (const Instruction& ins : tape.code)
  {
    switch (ins.op)
    {
      case Opcode::Const:
        node[ins.out] = dag.constant(ins.imm);
        break;
      case Opcode::Input:
        node[ins.out] = inputs[static_cast<std::size_t>(ins.index)];
        break;
      case Opcode::ErrorIf:
        out.effects.push_back(Effect{ false, read(ins.a), ins.index + error_offset });
        break;
      case Opcode::Call:
      {
        const CallSite& site = tape.calls[static_cast<std::size_t>(ins.index)];
        std::vector<NodeId> args;
        for (std::uint32_t slot : site.inputs)
        {
          args.push_back(read(slot));
        }
        const NodeId call = dag.call(RenumberedErrors::wrap(site.function, error_offset),
          std::move(args),
          static_cast<std::uint32_t>(site.outputs.size()));
        out.effects.push_back(Effect{ true, call, 0 });
        const std::vector<NodeId>& results = dag.call_of(call).outputs;
        for (std::size_t k = 0; k < site.outputs.size(); ++k)
        {
          node[site.outputs[k]] = results[k];
        }
        break;
      }
      case Opcode::HfPowInt:
        node[ins.out] = dag.pow_int(read(ins.a), ins.index);
        break;
      case Opcode::Select:
        node[ins.out] = dag.select(read(ins.a), read(ins.b), read(ins.c));
        break;
      default:
        // Operands are read before the output is written: an instruction may reuse its own
        // operand's slot in a hand-built tape.
        if (operand_count(ins.op) == 1)
        {
          node[ins.out] = dag.unary(ins.op, read(ins.a));
        }
        else
        {
          const NodeId a = read(ins.a);
          const NodeId b = read(ins.b);
          node[ins.out] = dag.binary(ins.op, a, b);
        }
        break;
    }
  }

  std::vector<NodeId> outputs;
  for (std::uint32_t slot : tape.outputs)
  {
    outputs.push_back(read(slot));
  }
  return outputs;
}

} // namespace frep::compiler
