// Three passes over the tape: (1) forward, resolve the choices into values (SSA: every surviving
// instruction defines a new value, a decided instruction only renames one); (2) backward, keep
// what an output, an ErrorIf or a Call needs; (3) forward, give the survivors registers again,
// reusing a register once its value's last reader has run (never for that reader's own result:
// the batch kernel relies on an instruction not writing a slot it reads, as the emitter does).
#include "Eval/tape_simplifier.h"


#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>

namespace frep
{

namespace
{
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t kForever = kNone - 1; // last use of an output: the end of the tape

bool writes_out(Opcode op)
{
  return op != Opcode::ErrorIf && op != Opcode::Call;
}

/// operand_count per opcode, as a table (simplification runs per box: no call per instruction).
std::array<std::uint8_t, 256> make_operand_table()
{
  std::array<std::uint8_t, 256> t{};
  for (int o = 0; o <= static_cast<int>(Opcode::Call); ++o)
  {
    t[static_cast<std::size_t>(o)] = static_cast<std::uint8_t>(operand_count(static_cast<Opcode>(o)));
  }
  return t;
}
const std::array<std::uint8_t, 256> operand_table = make_operand_table();

inline int operands(Opcode op)
{
  return operand_table[static_cast<std::size_t>(op)];
}
} // namespace

bool may_simplify(const Tape& tape)
{
  return std::any_of(tape.code.begin(), tape.code.end(),
    [](const Instruction& ins)
    {
      return is_boolean_opcode(ins.op) || ins.op == Opcode::Max || ins.op == Opcode::Min ||
             ins.op == Opcode::Select || ins.op == Opcode::ErrorIf;
    });
}

bool worth_switching(const Tape& simplified, const Tape& from)
{
  const std::size_t n = simplified.code.size();
  const std::size_t m = from.code.size();
  return n + 4 <= m && n * 8 <= m * 7;
}

std::shared_ptr<const Tape> TapeSimplifier::simplify(
  const Tape& tape, std::span<const Choice> choices)
{
  if (choices.size() != tape.code.size())
  {
    throw std::invalid_argument("TapeSimplifier::simplify: one choice per instruction expected");
  }
  if (std::all_of(choices.begin(), choices.end(), [](Choice c) { return c == Choice::Keep; }))
  {
    return nullptr;
  }

  // (1) Resolve choices.
  value_of_.assign(tape.slot_count, kNone);
  // About one value per instruction (written by index: push_back was a tenth of the time).
  ssa_.resize(tape.code.size() + 3);
  std::size_t ssa_count = 0;
  const auto emit = [&](const Instruction& ins)
  {
    if (ssa_count == ssa_.size())
    {
      ssa_.resize(2 * ssa_.size()); // constants for many slots read before any write
    }
    ssa_[ssa_count++] = ins;
  };
  site_inputs_.clear();
  site_outputs_.clear();
  std::uint32_t values = 0;
  std::uint32_t true_value = kNone;
  std::uint32_t false_value = kNone;
  const auto define_const = [&](double v)
  {
    Instruction c;
    c.op = Opcode::Const;
    c.imm = v;
    c.out = values++;
    emit(c);
    return c.out;
  };
  // A slot read before any write holds the register file's initial 0 (no producer emits that).
  const auto read = [&](std::uint32_t slot)
  {
    if (value_of_[slot] == kNone)
    {
      value_of_[slot] = define_const(0.0);
    }
    return value_of_[slot];
  };
  for (std::size_t i = 0; i < tape.code.size(); ++i)
  {
    const Instruction& ins = tape.code[i];
    switch (choices[i])
    {
      case Choice::TakeA:
        value_of_[ins.out] = read(ins.a);
        continue;
      case Choice::TakeB:
        value_of_[ins.out] = read(ins.b);
        continue;
      case Choice::TakeC:
        value_of_[ins.out] = read(ins.c);
        continue;
      case Choice::True:
        value_of_[ins.out] = true_value != kNone ? true_value : (true_value = define_const(1.0));
        continue;
      case Choice::False:
        value_of_[ins.out] = false_value != kNone ? false_value : (false_value = define_const(0.0));
        continue;
      case Choice::Drop:
        continue;
      case Choice::Keep:
        break;
    }
    Instruction n = ins;
    n.a = n.b = n.c = 0;
    if (ins.op == Opcode::Call)
    {
      const CallSite& site = tape.calls[static_cast<std::size_t>(ins.index)];
      std::vector<std::uint32_t> in, out;
      in.reserve(site.inputs.size());
      out.reserve(site.outputs.size());
      for (std::uint32_t s : site.inputs)
      {
        in.push_back(read(s));
      }
      for (std::uint32_t s : site.outputs)
      {
        out.push_back(values);
        value_of_[s] = values++;
      }
      n.index = static_cast<std::int32_t>(site_inputs_.size());
      n.c = static_cast<std::uint32_t>(i); // the original site, until pass (3)
      site_inputs_.push_back(std::move(in));
      site_outputs_.push_back(std::move(out));
      emit(n);
      continue;
    }
    if (operands(ins.op) >= 1)
    {
      n.a = read(ins.a);
    }
    if (operands(ins.op) >= 2)
    {
      n.b = read(ins.b);
    }
    if (operands(ins.op) >= 3)
    {
      n.c = read(ins.c);
    }
    if (writes_out(ins.op))
    {
      n.out = values++;
      value_of_[ins.out] = n.out;
    }
    emit(n);
  }
  std::vector<std::uint32_t>& output_values = output_values_;
  output_values.clear();
  for (std::uint32_t s : tape.outputs)
  {
    output_values.push_back(read(s));
  }

  // (2) Keep what is needed: outputs, and every ErrorIf and Call (they can set the error).
  live_.assign(values, 0);
  for (std::uint32_t v : output_values)
  {
    live_[v] = 1;
  }
  ssa_.resize(ssa_count);
  keep_.assign(ssa_.size(), 0);
  std::vector<unsigned char>& keep = keep_;
  for (std::size_t j = ssa_.size(); j-- > 0;)
  {
    const Instruction& n = ssa_[j];
    const bool needed =
      n.op == Opcode::ErrorIf || n.op == Opcode::Call || (writes_out(n.op) && live_[n.out]);
    if (!needed)
    {
      continue;
    }
    keep[j] = 1;
    if (n.op == Opcode::Call)
    {
      for (std::uint32_t v : site_inputs_[static_cast<std::size_t>(n.index)])
      {
        live_[v] = 1;
      }
      continue;
    }
    if (operands(n.op) >= 1)
    {
      live_[n.a] = 1;
    }
    if (operands(n.op) >= 2)
    {
      live_[n.b] = 1;
    }
    if (operands(n.op) >= 3)
    {
      live_[n.c] = 1;
    }
  }

  // (3) Registers.
  last_use_.assign(values, kNone);
  {
    std::uint32_t j = 0;
    for (std::size_t k = 0; k < ssa_.size(); ++k)
    {
      if (!keep[k])
      {
        continue;
      }
      const Instruction& n = ssa_[k];
      if (n.op == Opcode::Call)
      {
        for (std::uint32_t v : site_inputs_[static_cast<std::size_t>(n.index)])
        {
          last_use_[v] = j;
        }
      }
      else
      {
        if (operands(n.op) >= 1)
        {
          last_use_[n.a] = j;
        }
        if (operands(n.op) >= 2)
        {
          last_use_[n.b] = j;
        }
        if (operands(n.op) >= 3)
        {
          last_use_[n.c] = j;
        }
      }
      ++j;
    }
  }
  for (std::uint32_t v : output_values)
  {
    last_use_[v] = kForever;
  }

  auto result = std::make_shared<Tape>();
  result->code.reserve(static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 1)));
  result->input_count = tape.input_count;
  result->errors = tape.errors;
  slot_of_.assign(values, kNone);
  free_slots_.clear();
  std::uint32_t slot_count = 0;
  const auto take = [&]
  {
    if (!free_slots_.empty())
    {
      const std::uint32_t s = free_slots_.back();
      free_slots_.pop_back();
      return s;
    }
    return slot_count++;
  };
  const auto release_if_last = [&](std::uint32_t v, std::uint32_t j)
  {
    if (last_use_[v] == j)
    {
      free_slots_.push_back(slot_of_[v]);
      last_use_[v] = kNone; // released once, even when read twice (a op a)
    }
  };
  std::uint32_t j = 0;
  for (std::size_t k = 0; k < ssa_.size(); ++k)
  {
    if (!keep[k])
    {
      continue;
    }
    Instruction n = ssa_[k];
    if (n.op == Opcode::Call)
    {
      const std::size_t site_index = static_cast<std::size_t>(n.index);
      const CallSite& original = tape.calls[static_cast<std::size_t>(tape.code[n.c].index)];
      CallSite site;
      site.function = original.function;
      for (std::uint32_t v : site_inputs_[site_index])
      {
        site.inputs.push_back(slot_of_[v]);
      }
      for (std::uint32_t v : site_outputs_[site_index])
      {
        slot_of_[v] = take();
        site.outputs.push_back(slot_of_[v]);
      }
      for (std::uint32_t v : site_inputs_[site_index])
      {
        release_if_last(v, j);
      }
      for (std::uint32_t v : site_outputs_[site_index])
      {
        if (last_use_[v] == kNone) // written, never read
        {
          free_slots_.push_back(slot_of_[v]);
        }
      }
      n.index = static_cast<std::int32_t>(result->calls.size());
      n.c = 0;
      result->calls.push_back(std::move(site));
      result->code.push_back(n);
      ++j;
      continue;
    }
    const std::uint32_t a = n.a, b = n.b, c = n.c;
    const bool ra = operands(n.op) >= 1, rb = operands(n.op) >= 2, rc = operands(n.op) >= 3;
    n.a = ra ? slot_of_[a] : 0;
    n.b = rb ? slot_of_[b] : 0;
    n.c = rc ? slot_of_[c] : 0;
    if (writes_out(n.op))
    {
      const std::uint32_t v = n.out;
      n.out = slot_of_[v] = take();
      if (last_use_[v] == kNone)
      {
        free_slots_.push_back(n.out); // (only an unread Const can get here)
      }
    }
    if (ra)
    {
      release_if_last(a, j);
    }
    if (rb)
    {
      release_if_last(b, j);
    }
    if (rc)
    {
      release_if_last(c, j);
    }
    result->code.push_back(n);
    ++j;
  }
  for (std::uint32_t v : output_values)
  {
    result->outputs.push_back(slot_of_[v]);
  }
  result->slot_count = std::max<std::uint32_t>(slot_count, 1);
  result->can_fail = std::any_of(result->code.begin(), result->code.end(),
    [](const Instruction& n) { return n.op == Opcode::ErrorIf || n.op == Opcode::Call; });
  last_length_ = result->code.size();
  return result;
}

} // namespace frep
