// The expression DAG the compiler builds while it executes an object symbolically: pure nodes
// are hash-consed (one node per distinct operation and operands) and constant-folded, but only
// where folding is bit-exact: a constant is computed with the same double code the evaluators
// run (op_eval.h), and algebraic shortcuts are taken only when they hold for every double,
// -0, infinities and NaN included (x*1 -> x, x-0 -> x, x+(-0) -> x; never x+0 or x*0).
//
// Opaque calls (library functions without a generic form, the interpreter fallback) are nodes
// too, but never merged: they have effects (errors) and are sequenced by the lowering.
#pragma once

#include "Compiler/tape.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace frep::compiler
{

using NodeId = std::uint32_t;

/// Thrown when the DAG outgrows CompileOptions::max_nodes; the model then falls back to the
/// interpreter.
struct DagTooLarge : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

enum class NodeKind : std::uint8_t
{
  Pure,      ///< op over operands a, b, c (Const and Input included)
  Call,      ///< opaque call; inputs in calls()[index]; op == Opcode::Call
  CallOutput ///< output `index` of the Call node `a`
};

struct Node
{
  Opcode op = Opcode::Const;
  NodeKind kind = NodeKind::Pure;
  std::uint8_t arity = 0;      ///< operands used among a, b, c
  bool never_negative = false; ///< the value never compares < 0 (NaN allowed): sign analysis
  bool boolean = false;        ///< the value is always 1.0 or 0.0
  NodeId a = 0;
  NodeId b = 0;
  NodeId c = 0;
  std::int32_t index = 0; ///< Input index, HfPowInt exponent, call number, output number
  double imm = 0;         ///< Const value
};

struct DagCall
{
  std::shared_ptr<const OpaqueFunction> function;
  std::vector<NodeId> inputs;
  std::uint32_t output_count = 0;
  std::vector<NodeId> outputs; ///< the CallOutput nodes, one per output
};

class Dag
{
public:
  explicit Dag(std::size_t max_nodes = 20'000'000);

  NodeId constant(double value);
  NodeId input(int index);
  NodeId unary(Opcode op, NodeId a);
  NodeId binary(Opcode op, NodeId a, NodeId b);
  NodeId select(NodeId condition, NodeId if_true, NodeId if_false);
  NodeId pow_int(NodeId base, int exponent);
  /// Creates an opaque call; its outputs are call(...).outputs.
  NodeId call(std::shared_ptr<const OpaqueFunction> function,
    std::vector<NodeId> inputs,
    std::uint32_t output_count);

  const Node& node(NodeId id) const { return nodes_[id]; }
  const DagCall& call_of(NodeId call_node) const { return calls_[nodes_[call_node].index]; }
  std::size_t size() const { return nodes_.size(); }

  bool is_constant(NodeId id) const { return nodes_[id].op == Opcode::Const; }
  double constant_value(NodeId id) const { return nodes_[id].imm; }
  /// True for nodes whose value is always 1.0 or 0.0 (comparisons, logic, their selects).
  bool is_boolean(NodeId id) const { return nodes_[id].boolean; }

private:
  struct Key
  {
    Opcode op;
    std::uint8_t arity;
    NodeId a, b, c;
    std::int32_t index;
    std::uint64_t imm_bits;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash
  {
    std::size_t operator()(const Key& k) const;
  };

  NodeId intern(Node node);
  /// Recognises the original's R-function formula written out (hfBlock's, with the explicit
  /// 2*ALPHA*u*v = (0*u)*v term): (u + v) -/+ sqrt[abs](u*u + v*v - (0*u)*v). Returns the
  /// Intersect/Union node, or no node (0 with ok = false).
  bool match_r_function(Opcode op, NodeId a, NodeId b, NodeId& result);
  NodeId fold_or_intern(Node node);
  bool compute_never_negative(const Node& n) const;
  bool compute_boolean(const Node& n) const;

  std::size_t max_nodes_;
  std::vector<Node> nodes_;
  std::vector<DagCall> calls_;
  std::unordered_map<Key, NodeId, KeyHash> table_;
};

} // namespace frep::compiler
