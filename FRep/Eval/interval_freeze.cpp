// IntervalEvaluator's freezes (interval_evaluator.h, IntervalFreeze): which instructions a box
// dominates, and what the boxes inside it may skip because of it.
#include "Eval/interval_evaluator.h"

#include <algorithm>
#include <cmath>

namespace frep
{

namespace
{

/// An operand's enclosure over the box: its producer's recorded one, or a constant's point.
bool operand_range(const Tape& tape, const IntervalFreeze& rec, std::int32_t producer,
  Interval& range)
{
  if (producer < 0)
  {
    return false;
  }
  const auto p = static_cast<std::size_t>(producer);
  const Instruction& ins = tape.code[p];
  if (ins.op == Opcode::Const)
  {
    // (a folded evaluator does not run constants, so their recorded range may be stale)
    if (std::isnan(ins.imm))
    {
      return false;
    }
    range = Interval::point(ins.imm);
    return true;
  }
  if (rec.nan[p])
  {
    return false;
  }
  range = rec.value[p];
  return !std::isnan(range.lo) && !std::isnan(range.hi);
}

double magnitude(const Interval& i)
{
  return std::max(std::fabs(i.lo), std::fabs(i.hi));
}

/// The instructions whose operands a box may dominate: max/min and the R-functions.
bool joins(Opcode op)
{
  return opcode_info(op).has(OpcodeInfo::Choice);
}

/// Whether `x` is dominated by `y` in the instruction `op` over the box (see IntervalFreeze):
/// a decided max/min, or an R-function operand on the far side of zero from the result's
/// deciding side, at least twice the other's magnitude.
bool dominated(Opcode op, const Interval& x, const Interval& y)
{
  switch (op)
  {
    case Opcode::Max:
      return x.hi < y.lo;
    case Opcode::Min:
      return x.lo > y.hi;
    case Opcode::Union:
    case Opcode::UnionPlain:
      return x.hi < 0.0 && -x.hi >= 2.0 * magnitude(y);
    case Opcode::Intersect:
    case Opcode::IntersectPlain:
      return x.lo > 0.0 && x.lo >= 2.0 * magnitude(y);
    default:
      return false;
  }
}

} // namespace

void IntervalEvaluator::find_producers()
{
  const Tape& tape = *tape_;
  const std::size_t n = tape.code.size();
  producers_.assign(3 * n, -1);
  std::vector<std::int32_t> writer(tape.slot_count, -1);
  for (std::size_t j = 0; j < n; ++j)
  {
    const Instruction& ins = tape.code[j];
    const int operands = ins.op == Opcode::Select ? 3 : operand_count(ins.op);
    const std::uint32_t slots[3] = { ins.a, ins.b, ins.c };
    for (int k = 0; k < operands && k < 3; ++k)
    {
      if (slots[k] < writer.size())
      {
        producers_[3 * j + static_cast<std::size_t>(k)] = writer[slots[k]];
      }
    }
    if (ins.op != Opcode::ErrorIf && ins.out < writer.size())
    {
      writer[ins.out] = static_cast<std::int32_t>(j);
    }
  }
  result_ = tape.outputs.empty() || tape.outputs[0] >= writer.size() ? -1 : writer[tape.outputs[0]];
}

bool IntervalEvaluator::make_freeze(const IntervalFreeze* outer, IntervalFreeze& inner)
{
  const Tape& tape = *tape_;
  const std::size_t n = tape.code.size();
  if (!tape.calls.empty() || tape.outputs.empty() || inner.value.size() != n)
  {
    return false;
  }
  if (producers_.size() != 3 * n)
  {
    find_producers();
  }
  // Only what the outer box still evaluates or froze can matter (the rest stays skipped: fewer
  // frozen operands never make more instructions needed), so the passes walk that list.
  const std::size_t count = outer ? outer->active.size() : n;
  const auto instruction = [&](std::size_t i) -> std::size_t
  { return outer ? outer->active[i] : i; };

  // The frozen instructions: the outer box's, and those this box dominates at every reader
  // that still runs (a value also read elsewhere, say by both sides of a select, stays live).
  readers_.assign(n, 0);
  dominated_.assign(n, 0);
  losers_.clear();
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::size_t j = instruction(i);
    if (outer && outer->action[j] == IntervalFreeze::Frozen)
    {
      continue; // reads nothing
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t p = producers_[3 * j + static_cast<std::size_t>(k)];
      if (p >= 0)
      {
        ++readers_[static_cast<std::size_t>(p)];
      }
    }
    const Opcode op = tape.code[j].op;
    if (!joins(op))
    {
      continue;
    }
    const std::int32_t pa = producers_[3 * j], pb = producers_[3 * j + 1];
    Interval a, b;
    if (pa == pb || !operand_range(tape, inner, pa, a) || !operand_range(tape, inner, pb, b))
    {
      continue;
    }
    const std::int32_t loser = dominated(op, b, a) ? pb : (dominated(op, a, b) ? pa : -1);
    if (loser >= 0 && dominated_[static_cast<std::size_t>(loser)]++ == 0)
    {
      losers_.push_back(static_cast<std::uint32_t>(loser));
    }
  }
  inner.action.assign(n, IntervalFreeze::Skip);
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::size_t j = instruction(i);
    inner.action[j] = outer ? outer->action[j] : std::uint8_t{ IntervalFreeze::Evaluate };
  }
  for (const std::uint32_t p : losers_)
  {
    const Opcode op = tape.code[p].op;
    if (dominated_[p] == readers_[p] && op != Opcode::Const && op != Opcode::Input)
    {
      inner.action[p] = IntervalFreeze::Frozen;
    }
  }
  // What is still needed, backward from the result and every possible error: an instruction
  // that no needed one reads is skipped; a frozen one reads nothing.
  needed_.assign(n, 0);
  if (result_ >= 0)
  {
    needed_[static_cast<std::size_t>(result_)] = 1;
  }
  inner.frozen = 0;
  inner.active.clear();
  for (std::size_t i = count; i-- > 0;)
  {
    const std::size_t j = instruction(i);
    const bool error_check = tape.code[j].op == Opcode::ErrorIf;
    if (!needed_[j] && !error_check)
    {
      inner.action[j] = IntervalFreeze::Skip;
      continue;
    }
    inner.active.push_back(static_cast<std::uint32_t>(j));
    if (inner.action[j] == IntervalFreeze::Frozen)
    {
      ++inner.frozen;
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t p = producers_[3 * j + static_cast<std::size_t>(k)];
      if (p >= 0)
      {
        needed_[static_cast<std::size_t>(p)] = 1;
      }
    }
  }
  std::reverse(inner.active.begin(), inner.active.end());
  inner.skipped = n - inner.active.size();
  return true;
}

} // namespace frep
