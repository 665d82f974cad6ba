// compose (combine.h): a model of models of the coordinates. Each coordinate function's tape is
// appended first (in order), then the outer model's with its inputs read from their outputs, so
// the whole is one DAG and one tape: enclosures see through it, and the projector's tape split
// separates what reads the kept coordinates alone (Meta5D's key shapes) from the path.
#include "Compiler/combine.h"

#include "Compiler/detail/emit.h"
#include "Compiler/detail/model_impl.h"
#include "Compiler/detail/operand_tape.h"
#include "Compiler/detail/tape_join.h"

#include <limits>
#include <utility>

namespace frep
{
namespace
{

using compiler::Lowered;
using compiler::NodeId;

class ComposedSource final : public compiler::TapeSource
{
public:
  ComposedSource(Operand outer, std::vector<CoordinateFunction> coordinates, int x_dim)
    : outer_(std::move(outer))
    , coordinates_(std::move(coordinates))
    , x_dim_(x_dim)
  {
    if (!outer_.model->is_compiled())
      reason_ = outer_.model->name() + ": " + outer_.model->fallback_reason();
    for (const CoordinateFunction& c : coordinates_)
      if (c.function.model && !c.function.model->is_compiled() && reason_.empty())
        reason_ = c.function.model->name() + ": " + c.function.model->fallback_reason();
  }

  Built build(const Specialisation& spec) const override
  {
    Lowered lowered(std::numeric_limits<std::size_t>::max());
    const std::vector<int> input_of = compiler::input_indices(x_dim_, spec);
    for (const int index : input_of)
      lowered.input_count += index >= 0 ? 1 : 0;
    std::vector<NodeId> values; // F's inputs
    for (const CoordinateFunction& c : coordinates_)
    {
      if (!c.function.model)
      {
        values.push_back(coordinate(c.coordinate, spec, input_of, lowered));
        continue;
      }
      const std::vector<int> free =
        compiler::free_coordinates(c.function.model->x_dim(), c.function.specialisation);
      values.push_back(
        compiler::append_operand(c.function, free, 0, spec, input_of, lowered).front());
    }
    Specialisation outer = outer_.specialisation;
    outer.fixed.resize(static_cast<std::size_t>(outer_.model->x_dim()));
    const std::shared_ptr<const Tape> tape = outer_.model->specialise(outer);
    lowered.outputs = compiler::append_tape(lowered, *tape, values);
    Built built;
    built.node_count = lowered.dag.size();
    built.tape = compiler::emit(lowered);
    built.fallback_reason = reason_;
    return built;
  }

private:
  // Coordinate r of G: its tape input, or its value where the specialisation fixes it.
  static NodeId coordinate(
    int r, const Specialisation& spec, const std::vector<int>& input_of, Lowered& lowered)
  {
    const auto k = static_cast<std::size_t>(r);
    if (k < spec.fixed.size() && spec.fixed[k])
      return lowered.dag.constant(*spec.fixed[k]);
    return lowered.dag.input(input_of[k]);
  }

  Operand outer_;
  std::vector<CoordinateFunction> coordinates_;
  int x_dim_ = 0;
  std::string reason_;
};

std::string compose_error(
  const Operand& outer, const std::vector<CoordinateFunction>& coordinates, int x_dim)
{
  if (!outer.model)
    return "compose: the outer model is missing";
  if (std::string e = compiler::specialisation_error(outer.model->x_dim(), outer.specialisation);
      !e.empty())
    return "compose: " + outer.model->name() + ": " + e;
  const std::size_t free =
    compiler::free_coordinates(outer.model->x_dim(), outer.specialisation).size();
  if (free != coordinates.size())
    return "compose: " + outer.model->name() + " has " + std::to_string(free) +
           " free coordinates but " + std::to_string(coordinates.size()) + " are given";
  if (x_dim < 1)
    return "compose: the composed model needs at least one coordinate";
  for (std::size_t i = 0; i < coordinates.size(); ++i)
  {
    const CoordinateFunction& c = coordinates[i];
    const std::string which = "compose: coordinate " + std::to_string(i + 1) + " of " +
                              outer.model->name();
    if (!c.function.model)
    {
      if (c.coordinate < 0 || c.coordinate >= x_dim)
        return which + " is x" + std::to_string(c.coordinate + 1) + ", not one of x1..x" +
               std::to_string(x_dim);
      continue;
    }
    const Model& g = *c.function.model;
    if (std::string e = compiler::specialisation_error(g.x_dim(), c.function.specialisation);
        !e.empty())
      return which + " (" + g.name() + "): " + e;
    const std::size_t k = compiler::free_coordinates(g.x_dim(), c.function.specialisation).size();
    if (k != static_cast<std::size_t>(x_dim))
      return which + " (" + g.name() + ") has " + std::to_string(k) +
             " free coordinates, the composed model " + std::to_string(x_dim);
  }
  return {};
}

} // namespace

CombineResult compose(Operand outer, std::vector<CoordinateFunction> coordinates, int x_dim)
{
  CombineResult result;
  result.error = compose_error(outer, coordinates, x_dim);
  if (!result.error.empty())
    return result;
  auto impl = std::make_unique<Model::Impl>();
  impl->name = "compose(" + outer.model->name() + ")";
  impl->s_dim = outer.model->s_dim();
  impl->a_dim = 0;
  impl->x_dim = x_dim;
  impl->source = std::make_unique<ComposedSource>(std::move(outer), std::move(coordinates), x_dim);
  result.model = Model::Impl::make(std::move(impl));
  return result;
}

} // namespace frep
