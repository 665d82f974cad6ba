#include "Compiler/detail/emit.h"

#include <algorithm>
#include <limits>

namespace frep::compiler
{

namespace
{

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

/// A constant whose last copy was emitted further back than this many steps is emitted again
/// instead of occupying a slot all the way (constants are shared by hash-consing across the
/// whole model, e.g. the same centre coordinate in distant primitives).
constexpr std::size_t kRematerialiseDistance = 16;

/// One step of the linear schedule: a pure node, a call, or a guard. Operands are value
/// numbers (a node may be computed more than once: rematerialised constants).
struct Step
{
  enum class Kind : std::uint8_t
  {
    Pure,
    Call,
    Guard
  } kind = Kind::Pure;
  NodeId node = 0;
  int error_id = 0;
  std::vector<std::uint32_t> operands; ///< value numbers read
  std::uint32_t first_value = 0;       ///< first value number defined
  std::uint32_t value_count = 0;       ///< values defined (call outputs, or 1)
};

class Emitter
{
public:
  explicit Emitter(const Lowered& lowered)
    : l_(lowered)
    , dag_(lowered.dag)
    , value_of_(dag_.size(), kNone)
    , emitted_at_(dag_.size(), 0)
  {
  }

  std::shared_ptr<Tape> run()
  {
    for (const Effect& e : l_.effects)
    {
      schedule(e.node);
      if (!e.is_call)
      {
        Step s;
        s.kind = Step::Kind::Guard;
        s.node = e.node;
        s.error_id = e.error_id;
        s.operands.push_back(value_of_[e.node]);
        steps_.push_back(std::move(s));
      }
    }
    for (NodeId out : l_.outputs)
    {
      schedule(out);
      output_values_.push_back(value_of_[out]);
    }
    return allocate();
  }

private:
  void operands(NodeId id, std::vector<NodeId>& ops) const
  {
    ops.clear();
    const Node& n = dag_.node(id);
    switch (n.kind)
    {
      case NodeKind::Pure:
        if (n.arity > 0)
          ops.push_back(n.a);
        if (n.arity > 1)
          ops.push_back(n.b);
        if (n.arity > 2)
          ops.push_back(n.c);
        break;
      case NodeKind::Call:
        ops = dag_.call_of(id).inputs;
        break;
      case NodeKind::CallOutput:
        ops.push_back(n.a);
        break;
    }
  }

  bool needed(NodeId id) const
  {
    if (value_of_[id] == kNone && dag_.node(id).kind != NodeKind::CallOutput)
    {
      return true;
    }
    if (dag_.node(id).kind == NodeKind::CallOutput)
    {
      return value_of_[id] == kNone;
    }
    return dag_.is_constant(id) && steps_.size() - emitted_at_[id] > kRematerialiseDistance;
  }

  /// Post-order DFS without recursion (DAGs of unrolled loops are deep).
  void schedule(NodeId root)
  {
    if (!needed(root))
    {
      return;
    }
    struct Item
    {
      NodeId id;
      std::size_t next;
    };
    std::vector<Item> stack{ { root, 0 } };
    std::vector<NodeId> ops;
    while (!stack.empty())
    {
      Item& top = stack.back();
      operands(top.id, ops);
      if (top.next < ops.size())
      {
        const NodeId child = ops[top.next++];
        if (needed(child))
        {
          stack.push_back(Item{ child, 0 });
        }
        continue;
      }
      const NodeId id = top.id;
      stack.pop_back();
      if (!needed(id))
      {
        continue; // reached twice through the same parent
      }
      const Node& n = dag_.node(id);
      if (n.kind == NodeKind::CallOutput)
      {
        continue; // defined by its Call, scheduled as a child just before
      }
      Step s;
      s.kind = n.kind == NodeKind::Call ? Step::Kind::Call : Step::Kind::Pure;
      s.node = id;
      for (NodeId o : ops)
      {
        s.operands.push_back(value_of_[o]);
      }
      s.first_value = value_count_;
      if (n.kind == NodeKind::Call)
      {
        const DagCall& call = dag_.call_of(id);
        s.value_count = call.output_count;
        for (std::uint32_t k = 0; k < call.output_count; ++k)
        {
          value_of_[call.outputs[k]] = value_count_ + k;
        }
        value_of_[id] = value_count_; // marks the call scheduled
      }
      else
      {
        s.value_count = 1;
        value_of_[id] = value_count_;
      }
      value_count_ += s.value_count;
      emitted_at_[id] = steps_.size();
      steps_.push_back(std::move(s));
    }
  }

  std::shared_ptr<Tape> allocate()
  {
    std::vector<std::size_t> last_use(value_count_, 0);
    std::vector<std::size_t> defined_at(value_count_, 0);
    for (std::size_t i = 0; i < steps_.size(); ++i)
    {
      for (std::uint32_t v : steps_[i].operands)
      {
        last_use[v] = i;
      }
      for (std::uint32_t k = 0; k < steps_[i].value_count; ++k)
      {
        defined_at[steps_[i].first_value + k] = i;
      }
    }
    const std::size_t end = steps_.size();
    for (std::uint32_t v : output_values_)
    {
      last_use[v] = end;
    }
    // Values are released after the output of their last user is allocated, so an instruction
    // never writes a slot it reads.
    std::vector<std::vector<std::uint32_t>> release(steps_.size() + 1);
    for (std::uint32_t v = 0; v < value_count_; ++v)
    {
      release[std::max(last_use[v], defined_at[v])].push_back(v);
    }

    auto tape = std::make_shared<Tape>();
    tape->input_count = l_.input_count;
    tape->errors = l_.errors;
    std::vector<std::uint32_t> slot(value_count_, kNone);
    std::vector<std::uint32_t> free_slots;
    std::uint32_t slot_count = 0;
    auto take = [&]() -> std::uint32_t
    {
      if (!free_slots.empty())
      {
        const std::uint32_t s = free_slots.back();
        free_slots.pop_back();
        return s;
      }
      return slot_count++;
    };

    for (std::size_t i = 0; i < steps_.size(); ++i)
    {
      const Step& s = steps_[i];
      Instruction ins;
      switch (s.kind)
      {
        case Step::Kind::Guard:
          ins.op = Opcode::ErrorIf;
          ins.a = slot[s.operands[0]];
          ins.index = s.error_id;
          tape->can_fail = true;
          break;
        case Step::Kind::Call:
        {
          CallSite site;
          site.function = dag_.call_of(s.node).function;
          for (std::uint32_t v : s.operands)
          {
            site.inputs.push_back(slot[v]);
          }
          for (std::uint32_t k = 0; k < s.value_count; ++k)
          {
            slot[s.first_value + k] = take();
            site.outputs.push_back(slot[s.first_value + k]);
          }
          ins.op = Opcode::Call;
          ins.index = static_cast<std::int32_t>(tape->calls.size());
          tape->calls.push_back(std::move(site));
          tape->can_fail = true;
          break;
        }
        case Step::Kind::Pure:
        {
          const Node& n = dag_.node(s.node);
          ins.op = n.op;
          ins.out = slot[s.first_value] = take();
          ins.a = s.operands.size() > 0 ? slot[s.operands[0]] : 0;
          ins.b = s.operands.size() > 1 ? slot[s.operands[1]] : 0;
          ins.c = s.operands.size() > 2 ? slot[s.operands[2]] : 0;
          ins.index = n.index;
          ins.imm = n.imm;
          break;
        }
      }
      tape->code.push_back(ins);
      for (std::uint32_t dead : release[i])
      {
        free_slots.push_back(slot[dead]);
      }
    }
    for (std::uint32_t v : output_values_)
    {
      tape->outputs.push_back(slot[v]);
    }
    tape->slot_count = std::max<std::uint32_t>(slot_count, 1);
    return tape;
  }

  const Lowered& l_;
  const Dag& dag_;
  std::vector<std::uint32_t> value_of_; ///< latest value number of each node
  std::vector<std::size_t> emitted_at_; ///< step of that value's definition
  std::vector<Step> steps_;
  std::vector<std::uint32_t> output_values_;
  std::uint32_t value_count_ = 0;
};

} // namespace

std::shared_ptr<Tape> emit(const Lowered& lowered)
{
  return Emitter(lowered).run();
}

} // namespace frep::compiler
