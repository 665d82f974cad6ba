#include "Compiler/detail/dag.h"

#include "Compiler/detail/op_eval.h"

#include <bit>
#include <cmath>
#include <utility>

namespace frep::compiler
{

namespace
{

bool is_commutative(Opcode op)
{
  // Bitwise commutative in IEEE arithmetic (Compiler/opcode.h): a+b, a*b, |a-b| and the
  // R-functions, whose formula is symmetric operation for operation.
  return opcode_info(op).has(OpcodeInfo::Commutative);
}

bool same_bits(double x, double y)
{
  return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
}

} // namespace

std::size_t Dag::KeyHash::operator()(const Key& k) const
{
  std::uint64_t h = static_cast<std::uint64_t>(k.op) * 0x9E3779B97F4A7C15ull;
  auto mix = [&h](std::uint64_t v)
  {
    h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h *= 0xBF58476D1CE4E5B9ull;
  };
  mix(k.arity);
  mix(k.a);
  mix(k.b);
  mix(k.c);
  mix(static_cast<std::uint32_t>(k.index));
  mix(k.imm_bits);
  return static_cast<std::size_t>(h ^ (h >> 31));
}

Dag::Dag(std::size_t max_nodes)
  : max_nodes_(max_nodes)
{
}

bool Dag::compute_boolean(const Node& n) const
{
  // Computed once per node (a flag, not a recursive walk: Select chains of unrolled loops are
  // deep).
  if (n.kind != NodeKind::Pure)
  {
    return false;
  }
  if (n.op == Opcode::Const)
  {
    return n.imm == 1.0 || same_bits(n.imm, 0.0);
  }
  if (n.op == Opcode::Select)
  {
    return nodes_[n.b].boolean && nodes_[n.c].boolean;
  }
  return is_boolean_opcode(n.op);
}

bool Dag::compute_never_negative(const Node& n) const
{
  // "Never compares < 0": NaN and -0 are allowed, which is what the guards test (v < 0).
  auto nn = [this](NodeId id) { return nodes_[id].never_negative; };
  if (is_boolean_opcode(n.op))
  {
    return true; // 1.0 or 0.0
  }
  switch (n.op)
  {
    case Opcode::Const:
      return !(n.imm < 0.0);
    case Opcode::Square:
    case Opcode::Abs:
    case Opcode::Sqrt:
    case Opcode::Exp:
    case Opcode::Cosh:
      return true;
    // Not Div: 1 / -0 is -inf. Not HfRound: NaN rounds to INT_MIN.
    case Opcode::Max:
      // (a > b) ? a : b: with b never negative, a is chosen only above b (or b is NaN: then b).
      // With a a non-NaN constant >= 0, b is chosen only at or above a, or when b is NaN.
      return nn(n.b) || (nodes_[n.a].op == Opcode::Const && nodes_[n.a].imm >= 0.0);
    case Opcode::Add:
    case Opcode::Mul:
    case Opcode::Min:
    case Opcode::Union:
    case Opcode::UnionPlain:
      return nn(n.a) && nn(n.b);
    case Opcode::Select:
      return nn(n.b) && nn(n.c);
    case Opcode::HfPowInt:
      return nn(n.a) || (n.index % 2 == 0);
    case Opcode::Floor:
    case Opcode::Ceil:
    case Opcode::Trunc:
    case Opcode::Frac:
    case Opcode::Sinh:
    case Opcode::Tanh:
    case Opcode::Atan:
      return nn(n.a);
    default:
      return false;
  }
}

NodeId Dag::intern(Node node)
{
  Key key{
    node.op, node.arity, node.a, node.b, node.c, node.index, std::bit_cast<std::uint64_t>(node.imm)
  };
  if (auto it = table_.find(key); it != table_.end())
  {
    return it->second;
  }
  if (nodes_.size() >= max_nodes_)
  {
    throw DagTooLarge("the expression DAG exceeds the node limit");
  }
  node.never_negative = compute_never_negative(node);
  node.boolean = compute_boolean(node);
  const auto id = static_cast<NodeId>(nodes_.size());
  nodes_.push_back(node);
  table_.emplace(key, id);
  return id;
}

NodeId Dag::constant(double value)
{
  Node n;
  n.op = Opcode::Const;
  n.imm = value;
  return intern(n);
}

NodeId Dag::input(int index)
{
  Node n;
  n.op = Opcode::Input;
  n.index = index;
  return intern(n);
}

NodeId Dag::fold_or_intern(Node n)
{
  bool all_constant = true;
  const NodeId operands[3] = { n.a, n.b, n.c };
  for (int i = 0; i < n.arity; ++i)
  {
    all_constant = all_constant && is_constant(operands[i]);
  }
  if (all_constant)
  {
    const double a = n.arity > 0 ? constant_value(n.a) : 0.0;
    const double b = n.arity > 1 ? constant_value(n.b) : 0.0;
    const double c = n.arity > 2 ? constant_value(n.c) : 0.0;
    return constant(semantics::evaluate_op(n.op, a, b, c, n.index));
  }
  if (is_commutative(n.op) && n.a > n.b)
  {
    std::swap(n.a, n.b);
  }
  return intern(n);
}

NodeId Dag::unary(Opcode op, NodeId a)
{
  const Node& x = nodes_[a];
  switch (op)
  {
    case Opcode::Neg:
      if (x.kind == NodeKind::Pure && x.op == Opcode::Neg)
      {
        return x.a; // -(-v) == v bit for bit
      }
      break;
    case Opcode::Abs:
      if (x.kind == NodeKind::Pure && (x.op == Opcode::Neg || x.op == Opcode::Abs))
      {
        return unary(Opcode::Abs, x.a); // fabs ignores the sign bit
      }
      break;
    case Opcode::Truthy:
      if (is_boolean(a))
      {
        return a;
      }
      if (x.kind == NodeKind::Pure && (x.op == Opcode::Neg || x.op == Opcode::Abs))
      {
        return unary(Opcode::Truthy, x.a);
      }
      break;
    case Opcode::Not:
      if (x.kind == NodeKind::Pure && x.op == Opcode::Not)
      {
        return unary(Opcode::Truthy, x.a);
      }
      break;
    default:
      break;
  }
  Node n;
  n.op = op;
  n.arity = 1;
  n.a = a;
  return fold_or_intern(n);
}

bool Dag::match_r_function(Opcode op, NodeId a, NodeId b, NodeId& result)
{
  // Only the exact formula with the 0*u*v term is the R-function op: without it an infinite
  // operand gives inf, not NaN; that plain form (hfBlendUni/Int's) becomes UnionPlain /
  // IntersectPlain, the same values, so the interval evaluator's monotone rule applies to both.
  // Every step below is bitwise commutative, so operand order inside the pattern does not matter
  // (NaN payloads aside).
  const Node& sum = nodes_[a];
  if (sum.op != Opcode::Add || nodes_[b].op != Opcode::Sqrt)
  {
    return false;
  }
  const NodeId u = sum.a;
  const NodeId v = sum.b;
  const auto same_pair = [](NodeId p, NodeId q, NodeId x, NodeId y)
  { return (p == x && q == y) || (p == y && q == x); };
  NodeId inner = nodes_[b].a;
  if (nodes_[inner].op == Opcode::Abs)
  {
    inner = nodes_[inner].a;
  }
  const Node& diff = nodes_[inner];
  if (diff.op == Opcode::Add && inner == nodes_[b].a)
  {
    // (u + v) ± sqrt(u*u + v*v) without the 0*u*v term: hfBlendUni/Int's R-function part.
    const Node& plain = diff;
    if (nodes_[plain.a].op == Opcode::Square && nodes_[plain.b].op == Opcode::Square &&
      same_pair(nodes_[plain.a].a, nodes_[plain.b].a, u, v))
    {
      result = binary(op == Opcode::Sub ? Opcode::IntersectPlain : Opcode::UnionPlain, u, v);
      return true;
    }
    return false;
  }
  if (diff.op != Opcode::Sub)
  {
    return false;
  }
  const Node& squares = nodes_[diff.a];
  if (squares.op != Opcode::Add || nodes_[squares.a].op != Opcode::Square ||
    nodes_[squares.b].op != Opcode::Square ||
    !same_pair(nodes_[squares.a].a, nodes_[squares.b].a, u, v))
  {
    return false;
  }
  // (0*x)*y with {x, y} = {u, v}, in any nesting of the two multiplications.
  const Node& outer = nodes_[diff.b];
  if (outer.op != Opcode::Mul)
  {
    return false;
  }
  const auto zero_times = [&](NodeId id, NodeId& other)
  {
    const Node& m = nodes_[id];
    if (m.op != Opcode::Mul)
    {
      return false;
    }
    const auto is_plus_zero = [&](NodeId k)
    { return is_constant(k) && same_bits(constant_value(k), 0.0); };
    if (is_plus_zero(m.a))
    {
      other = m.b;
      return true;
    }
    if (is_plus_zero(m.b))
    {
      other = m.a;
      return true;
    }
    return false;
  };
  NodeId x = 0;
  const bool matched = (zero_times(outer.a, x) && same_pair(x, outer.b, u, v)) ||
                       (zero_times(outer.b, x) && same_pair(x, outer.a, u, v));
  if (!matched)
  {
    return false;
  }
  result = binary(op == Opcode::Sub ? Opcode::Intersect : Opcode::Union, u, v);
  return true;
}

NodeId Dag::binary(Opcode op, NodeId a, NodeId b)
{
  if (op == Opcode::Sub || op == Opcode::Add)
  {
    NodeId r = 0;
    if (match_r_function(op, a, b, r))
    {
      return r;
    }
  }
  auto is_const_bits = [this](NodeId id, double v)
  { return is_constant(id) && same_bits(constant_value(id), v); };
  switch (op)
  {
    case Opcode::Mul:
      if (is_const_bits(b, 1.0) && !is_constant(a))
      {
        return a;
      }
      if (is_const_bits(a, 1.0) && !is_constant(b))
      {
        return b;
      }
      if (a == b)
      {
        return unary(Opcode::Square, a);
      }
      break;
    case Opcode::Div:
      if (is_const_bits(b, 1.0) && !is_constant(a))
      {
        return a;
      }
      break;
    case Opcode::Sub:
      if (is_const_bits(b, 0.0) && !is_constant(a))
      {
        return a;
      }
      break;
    case Opcode::Add:
      if (is_const_bits(b, -0.0) && !is_constant(a))
      {
        return a;
      }
      if (is_const_bits(a, -0.0) && !is_constant(b))
      {
        return b;
      }
      break;
    case Opcode::And:
    case Opcode::Or:
    {
      // truthy(k) decides: And(k, v) is Truthy(v) or false; Or(k, v) is true or Truthy(v).
      for (int side = 0; side < 2; ++side)
      {
        const NodeId k = side == 0 ? a : b;
        const NodeId v = side == 0 ? b : a;
        if (is_constant(k) && !is_constant(v))
        {
          const bool t = semantics::truthy(constant_value(k));
          if (op == Opcode::And)
          {
            return t ? unary(Opcode::Truthy, v) : constant(0.0);
          }
          return t ? constant(1.0) : unary(Opcode::Truthy, v);
        }
      }
      if (a == b)
      {
        return unary(Opcode::Truthy, a);
      }
      break;
    }
    default:
      break;
  }
  Node n;
  n.op = op;
  n.arity = 2;
  n.a = a;
  n.b = b;
  return fold_or_intern(n);
}

NodeId Dag::select(NodeId condition, NodeId if_true, NodeId if_false)
{
  if (is_constant(condition))
  {
    return constant_value(condition) != 0 ? if_true : if_false;
  }
  if (if_true == if_false)
  {
    return if_true;
  }
  Node n;
  n.op = Opcode::Select;
  n.arity = 3;
  n.a = condition;
  n.b = if_true;
  n.c = if_false;
  return fold_or_intern(n);
}

NodeId Dag::pow_int(NodeId base, int exponent)
{
  Node n;
  n.op = Opcode::HfPowInt;
  n.arity = 1;
  n.a = base;
  n.index = exponent;
  return fold_or_intern(n);
}

NodeId Dag::call(std::shared_ptr<const OpaqueFunction> function,
  std::vector<NodeId> inputs,
  std::uint32_t output_count)
{
  if (nodes_.size() + output_count + 1 > max_nodes_)
  {
    throw DagTooLarge("the expression DAG exceeds the node limit");
  }
  Node n;
  n.op = Opcode::Call;
  n.kind = NodeKind::Call;
  n.index = static_cast<std::int32_t>(calls_.size());
  const auto id = static_cast<NodeId>(nodes_.size());
  nodes_.push_back(n);
  DagCall call;
  call.function = std::move(function);
  call.inputs = std::move(inputs);
  call.output_count = output_count;
  for (std::uint32_t k = 0; k < output_count; ++k)
  {
    Node out;
    out.op = Opcode::Call;
    out.kind = NodeKind::CallOutput;
    out.a = id;
    out.index = static_cast<std::int32_t>(k);
    call.outputs.push_back(static_cast<NodeId>(nodes_.size()));
    nodes_.push_back(out);
  }
  calls_.push_back(std::move(call));
  return id;
}

} // namespace frep::compiler
