#include "Project/detail/tape_split.h"

#include <map>
#include <utility>
#include <vector>

namespace frep::project::detail
{
namespace
{

// Where a slot's current value lives: in the prefix (x' only) or the suffix, and its slot there.
struct Value
{
  bool in_suffix = false;
  std::uint32_t slot = 0;
};

class Splitter
{
public:
  Splitter(const Tape& tape, std::size_t kept)
    : tape_(tape)
    , kept_(kept)
    , values_(tape.slot_count)
  {
    prefix_.errors = suffix_.errors = tape.errors; // ErrorIf keeps its id
  }

  SplitTape run()
  {
    for (const Instruction& in : tape_.code)
      in.op == Opcode::Call ? call(in) : instruction(in);
    suffix_.outputs = { suffix_slot(tape_.outputs.front()) }; // may ask the prefix for F
    // The suffix's inputs: the prefix's outputs first, then t; its Input instructions were
    // numbered in the order the prefix's values were asked for, t's after all of them.
    const std::uint32_t m = static_cast<std::uint32_t>(prefix_.outputs.size());
    for (Instruction& in : suffix_.code)
      if (in.op == Opcode::Input && in.index < 0)
        in.index = static_cast<std::int32_t>(m) + (-in.index - 1);
    suffix_.input_count = m + static_cast<std::uint32_t>(tape_.input_count - kept_);
    prefix_.input_count = static_cast<std::uint32_t>(kept_);
    SplitTape split;
    if (m > 0 || prefix_.can_fail) // a prefix that only checks still fails its points
      split.prefix = std::make_shared<const Tape>(std::move(prefix_));
    split.suffix = std::make_shared<const Tape>(std::move(suffix_));
    return split;
  }

private:
  static std::uint32_t emit(Tape& tape, Instruction in)
  {
    in.out = tape.slot_count++;
    tape.code.push_back(in);
    return in.out;
  }

  // The suffix's slot holding slot `s`'s current value: a prefix value becomes a suffix input
  // (a constant is copied instead, so the suffix's enclosures and kernels see a constant).
  std::uint32_t suffix_slot(std::uint32_t s)
  {
    const Value& v = values_[s];
    if (v.in_suffix)
      return v.slot;
    if (const auto found = imported_.find(v.slot); found != imported_.end())
      return found->second;
    Instruction load;
    const Instruction& made = prefix_.code[made_by_[v.slot]];
    if (made.op == Opcode::Const)
    {
      load = made;
    }
    else
    {
      load.op = Opcode::Input;
      load.index = static_cast<std::int32_t>(prefix_.outputs.size()); // >= 0: a prefix value
      prefix_.outputs.push_back(v.slot);
    }
    const std::uint32_t slot = emit(suffix_, load);
    imported_.emplace(v.slot, slot);
    return slot;
  }

  void put(std::uint32_t old_slot, bool in_suffix, std::uint32_t slot)
  {
    values_[old_slot] = { in_suffix, slot };
  }

  void instruction(const Instruction& in)
  {
    const int n = operand_count(in.op);
    const std::uint32_t operands[3] = { in.a, in.b, in.c };
    bool t = in.op == Opcode::Input && static_cast<std::size_t>(in.index) >= kept_;
    for (int k = 0; k < n; ++k)
      t = t || values_[operands[k]].in_suffix;
    Instruction out = in;
    if (!t)
    {
      std::uint32_t* fields[3] = { &out.a, &out.b, &out.c };
      for (int k = 0; k < n; ++k)
        *fields[k] = values_[operands[k]].slot;
      made_by_.resize(prefix_.slot_count + 1);
      made_by_[prefix_.slot_count] = prefix_.code.size();
      const std::uint32_t slot = emit(prefix_, out);
      prefix_.can_fail = prefix_.can_fail || in.op == Opcode::ErrorIf;
      if (!opcode_info(in.op).has(OpcodeInfo::NoResult))
        put(in.out, false, slot);
      return;
    }
    std::uint32_t* fields[3] = { &out.a, &out.b, &out.c };
    for (int k = 0; k < n; ++k)
      *fields[k] = suffix_slot(operands[k]);
    if (in.op == Opcode::Input) // t's k-th input: numbered once the prefix's outputs are known
      out.index = -(in.index - static_cast<std::int32_t>(kept_)) - 1;
    const std::uint32_t slot = emit(suffix_, out);
    suffix_.can_fail = suffix_.can_fail || in.op == Opcode::ErrorIf;
    if (!opcode_info(in.op).has(OpcodeInfo::NoResult))
      put(in.out, true, slot);
  }

  // A call goes where its inputs are; its outputs are new slots of that part.
  void call(const Instruction& in)
  {
    const CallSite& site = tape_.calls[static_cast<std::size_t>(in.index)];
    bool t = false;
    for (const std::uint32_t s : site.inputs)
      t = t || values_[s].in_suffix;
    Tape& part = t ? suffix_ : prefix_;
    CallSite moved;
    moved.function = site.function;
    for (const std::uint32_t s : site.inputs)
      moved.inputs.push_back(t ? suffix_slot(s) : values_[s].slot);
    Instruction out = in;
    out.index = static_cast<std::int32_t>(part.calls.size());
    for (const std::uint32_t s : site.outputs)
    {
      const std::uint32_t slot = part.slot_count++;
      moved.outputs.push_back(slot);
      if (!t)
      {
        made_by_.resize(prefix_.slot_count);
        made_by_[slot] = prefix_.code.size(); // the call (not a Const)
      }
      put(s, t, slot);
    }
    part.calls.push_back(std::move(moved));
    out.out = 0;
    part.code.push_back(out);
    part.can_fail = true;
  }

  const Tape& tape_;
  std::size_t kept_;
  std::vector<Value> values_;           // per slot of the tape: its current value
  std::vector<std::size_t> made_by_;    // per prefix slot: the instruction that wrote it
  std::map<std::uint32_t, std::uint32_t> imported_; // prefix slot -> its suffix slot
  Tape prefix_, suffix_;
};

} // namespace

SplitTape split_tape(const Tape& tape, std::size_t kept)
{
  return Splitter(tape, kept).run();
}

} // namespace frep::project::detail
