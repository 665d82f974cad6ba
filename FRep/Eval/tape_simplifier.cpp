// One pass over the whole tape and two over what survives: (1) backward over the tape, keep what
// an output, an ErrorIf or a Call needs, as values (SSA), a decided instruction only renaming one
// (merging two names of one value); (2) forward over the survivors, resolve the merged names and
// find each value's last reader; (3) forward, give the survivors registers, reusing a register
// once its value's last reader has run. The one pass over the long tape is what a box pays (the
// earlier three passes over it were a third of Prospero's sampling time).
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
  return !opcode_info(op).has(OpcodeInfo::NoResult);
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

std::uint32_t TapeSimplifier::find(std::uint32_t v)
{
  while (merged_[v] != v)
  {
    merged_[v] = merged_[merged_[v]]; // path halving
    v = merged_[v];
  }
  return v;
}

std::uint32_t TapeSimplifier::fresh_value()
{
  const auto v = static_cast<std::uint32_t>(merged_.size());
  merged_.push_back(v);
  return v;
}

std::uint32_t TapeSimplifier::demand(std::uint32_t slot)
{
  if (wanted_[slot] == kNone)
  {
    wanted_[slot] = fresh_value();
  }
  return wanted_[slot];
}

void TapeSimplifier::keep_call(const Tape& tape, const Instruction& ins, std::size_t i)
{
  const CallSite& site = tape.calls[static_cast<std::size_t>(ins.index)];
  std::vector<std::uint32_t> out;
  out.reserve(site.outputs.size());
  for (std::uint32_t s : site.outputs)
  {
    out.push_back(wanted_[s] != kNone ? wanted_[s] : fresh_value()); // (written, unread)
  }
  for (std::uint32_t s : site.outputs)
  {
    wanted_[s] = kNone;
  }
  std::vector<std::uint32_t> in;
  in.reserve(site.inputs.size());
  for (std::uint32_t s : site.inputs)
  {
    in.push_back(demand(s));
  }
  Instruction n = ins;
  n.index = static_cast<std::int32_t>(site_inputs_.size());
  n.c = static_cast<std::uint32_t>(i); // the original site, until pass (3)
  site_inputs_.push_back(std::move(in));
  site_outputs_.push_back(std::move(out));
  ssa_.push_back(n);
}

// (1) Backward over the tape. wanted_[slot]: the value (SSA) that the instructions kept after
// this point read from `slot`, or kNone. A kept instruction defines the value wanted from its
// out slot and then wants its operands; a decided one renames (its value is the chosen
// operand's: the two values are merged) or becomes a constant; one whose value nobody wants
// is dropped. ErrorIf (unless decided) and Call are always kept: they can set the error.
void TapeSimplifier::keep_backward(const Tape& tape, std::span<const Choice> choices)
{
  wanted_.assign(tape.slot_count, kNone);
  merged_.clear();
  ssa_.clear();
  site_inputs_.clear();
  site_outputs_.clear();
  output_values_.clear();
  for (std::uint32_t slot : tape.outputs)
  {
    output_values_.push_back(demand(slot));
  }
  for (std::size_t i = tape.code.size(); i-- > 0;)
  {
    const Instruction& ins = tape.code[i];
    const Choice choice = choices[i];
    if (ins.op == Opcode::ErrorIf)
    {
      if (choice != Choice::Drop)
      {
        Instruction n = ins;
        n.a = demand(ins.a);
        ssa_.push_back(n);
      }
      continue;
    }
    if (ins.op == Opcode::Call)
    {
      keep_call(tape, ins, i);
      continue;
    }
    const std::uint32_t v = wanted_[ins.out];
    if (v == kNone)
    {
      continue; // nothing kept reads this result
    }
    wanted_[ins.out] = kNone;
    if (choice == Choice::TakeA || choice == Choice::TakeB || choice == Choice::TakeC)
    {
      const std::uint32_t from = choice == Choice::TakeA ? ins.a
                               : choice == Choice::TakeB ? ins.b
                                                         : ins.c;
      if (wanted_[from] == kNone)
      {
        wanted_[from] = v;
      }
      else
      {
        merged_[find(v)] = find(wanted_[from]); // one value read under two names
      }
      continue;
    }
    Instruction n = ins;
    n.out = v;
    n.a = n.b = n.c = 0;
    if (choice == Choice::True || choice == Choice::False)
    {
      n.op = Opcode::Const;
      n.imm = choice == Choice::True ? 1.0 : 0.0;
      ssa_.push_back(n);
      continue;
    }
    const int reads = operands(ins.op);
    if (reads >= 1)
    {
      n.a = demand(ins.a);
    }
    if (reads >= 2)
    {
      n.b = demand(ins.b);
    }
    if (reads >= 3)
    {
      n.c = demand(ins.c);
    }
    ssa_.push_back(n);
  }
  // A slot read before any write holds the register file's initial 0 (no producer emits that).
  for (std::uint32_t slot = 0; slot < tape.slot_count; ++slot)
  {
    if (wanted_[slot] != kNone)
    {
      Instruction zero;
      zero.op = Opcode::Const;
      zero.imm = 0.0;
      zero.out = wanted_[slot];
      ssa_.push_back(zero);
    }
  }
  std::reverse(ssa_.begin(), ssa_.end());
}

// (2) Forward over the survivors: the merged names resolved, and each value's last reader.
void TapeSimplifier::resolve_names()
{
  const auto values = static_cast<std::uint32_t>(merged_.size());
  last_use_.assign(values, kNone);
  for (std::uint32_t j = 0; j < ssa_.size(); ++j)
  {
    Instruction& n = ssa_[j];
    if (n.op == Opcode::Call)
    {
      for (std::uint32_t& v : site_inputs_[static_cast<std::size_t>(n.index)])
      {
        v = find(v);
        last_use_[v] = j;
      }
      for (std::uint32_t& v : site_outputs_[static_cast<std::size_t>(n.index)])
      {
        v = find(v);
      }
      continue;
    }
    const int reads = operands(n.op);
    if (reads >= 1)
    {
      n.a = find(n.a);
      last_use_[n.a] = j;
    }
    if (reads >= 2)
    {
      n.b = find(n.b);
      last_use_[n.b] = j;
    }
    if (reads >= 3)
    {
      n.c = find(n.c);
      last_use_[n.c] = j;
    }
    if (writes_out(n.op))
    {
      n.out = find(n.out);
    }
  }
  for (std::uint32_t& v : output_values_)
  {
    v = find(v);
    last_use_[v] = kForever;
  }
}

// (3) Registers: a value's register is free again once its last reader has run (never for
// that reader's own result: the batch kernel relies on an instruction not writing a slot it
// reads, as the emitter does).
std::shared_ptr<Tape> TapeSimplifier::assign_registers(const Tape& tape)
{
  auto result = std::make_shared<Tape>();
  result->code.reserve(ssa_.size());
  result->input_count = tape.input_count;
  result->errors = tape.errors;
  slot_of_.assign(merged_.size(), kNone);
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
  for (std::uint32_t j = 0; j < ssa_.size(); ++j)
  {
    Instruction n = ssa_[j];
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
      continue;
    }
    const std::uint32_t a = n.a, b = n.b, c = n.c;
    const int reads = operands(n.op);
    n.a = reads >= 1 ? slot_of_[a] : 0;
    n.b = reads >= 2 ? slot_of_[b] : 0;
    n.c = reads >= 3 ? slot_of_[c] : 0;
    if (writes_out(n.op))
    {
      const std::uint32_t v = n.out;
      n.out = slot_of_[v] = take();
      if (last_use_[v] == kNone)
      {
        free_slots_.push_back(n.out); // (an unread value: only a constant can get here)
      }
    }
    if (reads >= 1)
    {
      release_if_last(a, j);
    }
    if (reads >= 2)
    {
      release_if_last(b, j);
    }
    if (reads >= 3)
    {
      release_if_last(c, j);
    }
    result->code.push_back(n);
  }
  for (std::uint32_t v : output_values_)
  {
    result->outputs.push_back(slot_of_[v]);
  }
  result->slot_count = std::max<std::uint32_t>(slot_count, 1);
  result->can_fail = std::any_of(result->code.begin(), result->code.end(),
    [](const Instruction& n) { return n.op == Opcode::ErrorIf || n.op == Opcode::Call; });
  return result;
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

  keep_backward(tape, choices);
  resolve_names();
  std::shared_ptr<Tape> result = assign_registers(tape);
  last_length_ = result->code.size();
  return result;
}

} // namespace frep
