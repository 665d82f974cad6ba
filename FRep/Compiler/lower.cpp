// Symbolic execution of a HyperFun object with the original interpreter's semantics
// (int_calc.c): operands right to left, library arguments last to first, in-place library
// arrays, if/else on both paths merged with Select, loops unrolled while their condition is a
// constant, object calls inlined on copies of their arrays. Every run-time check becomes a guard
// (an ErrorIf in the tape) in evaluation order, AND-ed with the path condition; checks that fold
// to false vanish, so most models compile to check-free tapes.
//
// Dynamic array indices (depending on free coordinates) are lowered to a range guard plus a
// chain of Selects over the array's elements (reads) or one Select per element (writes).
#include "Compiler/detail/lower.h"

#include "Compiler/detail/lowerer.h"

#include <algorithm>

namespace frep::compiler
{

namespace lowering
{

void Lowerer::run(int object_index, const Specialisation& spec)
{
  const ast::Object& object = program_.objects[static_cast<std::size_t>(object_index)];
  file_ = object_file(object);
  Frame frame = fresh_frame(object);
  const std::vector<int> inputs = input_indices(object.x_dim, spec);
  for (int i = 0; i < object.x_dim; ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    if (inputs[k] >= 0)
    {
      frame.arrays[0][k].value = Expr(&dag_, dag_.input(inputs[k]));
      ++out_.input_count;
    }
    else
    {
      frame.arrays[0][k].value = Expr(*spec.fixed[k]);
    }
  }
  for (int i = 0; i < object.a_dim; ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    frame.arrays[1][k].value = Expr(k < spec.parameters.size() ? spec.parameters[k] : 0.0);
  }
  const Expr value = execute(frame);
  out_.outputs.push_back(value.node(dag_));
  for (const Cell& cell : frame.arrays[2])
  {
    out_.outputs.push_back(cell.value.node(dag_));
  }
}

void Lowerer::guard(const Expr& condition, const char* message, SourceLocation location)
{
  if (dead_)
  {
    return;
  }
  const Expr full = logical_and(path_, condition);
  if (full.is_constant() && !semantics::truthy(full.constant()))
  {
    return;
  }
  if (condition.is_constant())
  {
    dead_ = true; // this path always stops here: nothing after it is evaluated
  }
  Effect effect;
  effect.node = full.node(dag_);
  // The same condition guarded again (e.g. in an unrolled loop) can never fire first: if it
  // held, the earlier guard (or an error before it) has already stopped the point.
  if (!guarded_.insert(effect.node).second)
  {
    return;
  }
  effect.error_id = error_id(message, location);
  out_.effects.push_back(effect);
}

int Lowerer::error_id(const std::string& message, SourceLocation location)
{
  const auto key = std::make_tuple(message, location.line, location.column, *file_);
  if (auto it = error_ids_.find(key); it != error_ids_.end())
  {
    return it->second;
  }
  out_.errors.push_back(TapeError{ message, location, *file_ });
  const int id = static_cast<int>(out_.errors.size());
  error_ids_.emplace(key, id);
  return id;
}

Frame Lowerer::fresh_frame(const ast::Object& object)
{
  Frame f;
  f.object = &object;
  f.scalars.assign(object.scalars.size(), Cell{ Expr(0.0), Expr(0.0) });
  f.arrays.resize(3 + object.arrays.size());
  f.arrays[0].assign(static_cast<std::size_t>(std::max(object.x_dim, 0)), Cell{});
  f.arrays[1].assign(static_cast<std::size_t>(std::max(object.a_dim, 0)), Cell{});
  f.arrays[2].assign(static_cast<std::size_t>(std::max(object.s_dim, 0)), Cell{});
  for (std::size_t i = 0; i < object.arrays.size(); ++i)
  {
    f.arrays[3 + i].assign(
      static_cast<std::size_t>(std::max(object.arrays[i].size, 0)), Cell{ Expr(0.0), Expr(0.0) });
  }
  return f;
}

Expr Lowerer::execute(Frame& frame)
{
  if (!frame.object->result)
  {
    throw CannotCompile("malformed AST: object without result");
  }
  execute_block(frame, frame.object->body);
  if (dead_)
  {
    return Expr(0.0);
  }
  return eval(frame, *frame.object->result);
}

} // namespace lowering

using lowering::Lowerer;

std::vector<int> input_indices(int x_dim, const Specialisation& spec)
{
  std::vector<int> result(static_cast<std::size_t>(std::max(x_dim, 0)), -1);
  auto is_free = [&](int i)
  {
    const auto k = static_cast<std::size_t>(i);
    return k >= spec.fixed.size() || !spec.fixed[k].has_value();
  };
  if (spec.input_order.empty())
  {
    int next = 0;
    for (int i = 0; i < x_dim; ++i)
    {
      if (is_free(i))
      {
        result[static_cast<std::size_t>(i)] = next++;
      }
    }
    return result;
  }
  for (std::size_t k = 0; k < spec.input_order.size(); ++k)
  {
    result[static_cast<std::size_t>(spec.input_order[k])] = static_cast<int>(k);
  }
  return result;
}

void lower(const ast::Program& program,
  int object_index,
  const Specialisation& specialisation,
  const CompileOptions& options,
  Lowered& out)
{
  Lowerer lowerer(program, options, out);
  lowerer.run(object_index, specialisation);
}

} // namespace frep::compiler
