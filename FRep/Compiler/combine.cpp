// A composed model's tapes: each operand is specialised with its own specialisation plus the
// result coordinates fixed so far, both tapes are read back into one DAG (tape_join.h), the
// operation is expanded on their outputs, and the DAG is emitted as one tape. So a slice of a
// union is the union of the operands' slices, each folded as far as its own model allows.
#include "Compiler/combine.h"

#include "Compiler/detail/emit.h"
#include "Compiler/detail/expr.h"
#include "Compiler/detail/model_impl.h"
#include "Compiler/detail/operand_tape.h"
#include "Compiler/detail/tape_join.h"
#include "Library/detail/library_generic.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace frep
{

namespace compiler
{

std::vector<int> free_coordinates(int x_dim, const Specialisation& s)
{
  if (!s.input_order.empty())
  {
    return s.input_order;
  }
  std::vector<int> free;
  for (int i = 0; i < x_dim; ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    if (k >= s.fixed.size() || !s.fixed[k])
    {
      free.push_back(i);
    }
  }
  return free;
}

std::vector<NodeId> append_operand(const Operand& operand,
  const std::vector<int>& free,
  int first,
  const Specialisation& spec,
  const std::vector<int>& input_of,
  Lowered& lowered)
{
  Specialisation s = operand.specialisation;
  s.fixed.resize(static_cast<std::size_t>(operand.model->x_dim()));
  std::vector<std::pair<int, int>> order; // (result tape input, operand coordinate)
  for (std::size_t i = 0; i < free.size(); ++i)
  {
    const auto r = static_cast<std::size_t>(first) + i;
    const auto c = static_cast<std::size_t>(free[i]);
    if (r < spec.fixed.size() && spec.fixed[r])
    {
      s.fixed[c] = spec.fixed[r];
    }
    else
    {
      order.emplace_back(input_of[r], free[i]);
    }
  }
  std::sort(order.begin(), order.end());
  s.input_order.clear();
  std::vector<NodeId> inputs;
  for (const auto& [input, coordinate] : order)
  {
    s.input_order.push_back(coordinate);
    inputs.push_back(lowered.dag.input(input));
  }
  const std::shared_ptr<const Tape> tape = operand.model->specialise(s);
  return compiler::append_tape(lowered, *tape, inputs);
}

} // namespace compiler

namespace
{

using compiler::Expr;
using compiler::Lowered;
using compiler::NodeId;
using compiler::append_operand;
using compiler::free_coordinates;

bool is_pointwise(Operation operation)
{
  return operation != Operation::CartesianProduct;
}

/// The Ctx of library::call_generic<Expr>: an abort of the library becomes a guard, as in the
/// lowering (the blends never abort; this keeps the expansion general).
struct OperationContext
{
  Lowered* out;
  void abort_if(const Expr& condition, const char* message)
  {
    if (condition.is_constant() && condition.constant() == 0.0)
    {
      return;
    }
    out->errors.push_back(TapeError{ message, {} });
    out->effects.push_back(
      compiler::Effect{ false, condition.node(out->dag), static_cast<int>(out->errors.size()) });
  }
  void abort_if(bool condition, const char* message)
  {
    abort_if(Expr(condition ? 1.0 : 0.0), message);
  }
};

/// F of the operation on the operands' values, with the operators' and the library's own code.
Expr apply_operation(Operation operation,
  const OperationParameters& p,
  const Expr& fa,
  const Expr& fb,
  Lowered& out)
{
  switch (operation)
  {
    case Operation::Union:
      return compiler::apply(Opcode::Union, fa, fb);
    case Operation::Intersection:
    case Operation::CartesianProduct: // the language's `@` is `&`
      return compiler::apply(Opcode::Intersect, fa, fb);
    case Operation::Difference:
      return compiler::apply(Opcode::Intersect, fa, -fb);
    case Operation::BlendUnion:
    case Operation::BlendIntersection:
    {
      std::vector<library::Arg<Expr>> args(5);
      args[0].real = fa;
      args[1].real = fb;
      args[2].real = p.a0;
      args[3].real = p.a1;
      args[4].real = p.a2;
      OperationContext context{ &out };
      const FunctionId id =
        operation == Operation::BlendUnion ? FunctionId::BlendUni : FunctionId::BlendInt;
      return *library::call_generic<Expr, OperationContext>(id, std::span(args), context);
    }
  }
  return Expr(0.0);
}

class CombinedSource final : public compiler::TapeSource
{
public:
  CombinedSource(Operation operation, Operand a, Operand b, const OperationParameters& parameters)
    : operation_(operation)
    , parameters_(parameters)
  {
    sides_[0].operand = std::move(a);
    sides_[1].operand = std::move(b);
    for (Side& side : sides_)
    {
      side.free = free_coordinates(side.operand.model->x_dim(), side.operand.specialisation);
    }
    const auto k_a = static_cast<int>(sides_[0].free.size());
    sides_[1].first = is_pointwise(operation) ? 0 : k_a;
    x_dim_ = sides_[1].first + static_cast<int>(sides_[1].free.size());
    for (const Side& side : sides_)
    {
      const Model& m = *side.operand.model;
      if (!m.is_compiled() && reason_.empty())
      {
        reason_ = m.name() + ": " + m.fallback_reason();
      }
    }
  }

  int x_dim() const { return x_dim_; }

  Built build(const Specialisation& spec) const override
  {
    // The operands' tapes are bounded by their own limits; their join is linear in them.
    Lowered lowered(std::numeric_limits<std::size_t>::max());
    const std::vector<int> input_of = compiler::input_indices(x_dim_, spec);
    for (int index : input_of)
    {
      lowered.input_count += index >= 0 ? 1 : 0;
    }
    // Right operand first, as the original evaluates `A | B`.
    const std::vector<NodeId> out_b = append_operand(sides_[1].operand, sides_[1].free, sides_[1].first, spec, input_of, lowered);
    const std::vector<NodeId> out_a = append_operand(sides_[0].operand, sides_[0].free, sides_[0].first, spec, input_of, lowered);
    compiler::Dag& dag = lowered.dag;
    const Expr fa(&dag, out_a[0]);
    const Expr fb(&dag, out_b[0]);
    lowered.outputs.push_back(apply_operation(operation_, parameters_, fa, fb, lowered).node(dag));

    const std::size_t s_dim = std::max(out_a.size(), out_b.size()) - 1;
    if (s_dim > 0)
    {
      const Expr take_a = fa >= fb;
      for (std::size_t j = 1; j <= s_dim; ++j)
      {
        const Expr sa = j < out_a.size() ? Expr(&dag, out_a[j]) : Expr(0.0);
        const Expr sb = j < out_b.size() ? Expr(&dag, out_b[j]) : Expr(0.0);
        lowered.outputs.push_back(compiler::select(take_a, sa, sb).node(dag));
      }
    }
    Built built;
    built.node_count = dag.size();
    built.tape = compiler::emit(lowered);
    built.fallback_reason = reason_;
    return built;
  }

private:
  struct Side
  {
    Operand operand;
    std::vector<int> free; ///< operand coordinate of each of its free coordinates
    int first = 0;         ///< result coordinate of its free coordinate 0
  };

  Operation operation_;
  OperationParameters parameters_;
  Side sides_[2];
  int x_dim_ = 0;
  std::string reason_;
};

} // namespace

const char* operation_name(Operation operation)
{
  switch (operation)
  {
    case Operation::Union:
      return "union";
    case Operation::Intersection:
      return "intersection";
    case Operation::Difference:
      return "difference";
    case Operation::BlendUnion:
      return "blend_union";
    case Operation::BlendIntersection:
      return "blend_intersection";
    case Operation::CartesianProduct:
      return "product";
  }
  return "?";
}

CombineResult combine(Operation operation,
  Operand a,
  Operand b,
  const OperationParameters& parameters)
{
  CombineResult result;
  const std::string what = std::string("combine (") + operation_name(operation) + "): ";
  const Operand* operands[2] = { &a, &b };
  for (int i = 0; i < 2; ++i)
  {
    const char* label = i == 0 ? "operand A" : "operand B";
    const Operand& o = *operands[i];
    if (!o.model)
    {
      result.error = what + label + " has no model";
      return result;
    }
    const std::string error = compiler::specialisation_error(o.model->x_dim(), o.specialisation);
    if (!error.empty())
    {
      result.error = what + label + " (" + o.model->name() + "): " + error;
      return result;
    }
  }
  const std::size_t k_a = free_coordinates(a.model->x_dim(), a.specialisation).size();
  const std::size_t k_b = free_coordinates(b.model->x_dim(), b.specialisation).size();
  if (is_pointwise(operation) && k_a != k_b)
  {
    result.error = what + "the operands must have the same number of free coordinates, but " +
                   a.model->name() + " has " + std::to_string(k_a) + " and " + b.model->name() +
                   " has " + std::to_string(k_b);
    return result;
  }

  auto impl = std::make_unique<Model::Impl>();
  impl->name =
    std::string(operation_name(operation)) + "(" + a.model->name() + ", " + b.model->name() + ")";
  impl->s_dim = std::max(a.model->s_dim(), b.model->s_dim());
  impl->a_dim = 0;
  auto source = std::make_unique<CombinedSource>(operation, std::move(a), std::move(b), parameters);
  impl->x_dim = source->x_dim();
  impl->source = std::move(source);
  result.model = Model::Impl::make(std::move(impl));
  return result;
}

} // namespace frep
