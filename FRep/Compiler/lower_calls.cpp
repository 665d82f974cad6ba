// The Lowerer's calls: built-ins, library functions (library arguments last to first, arrays
// in place), user functions (opaque calls) and object calls (inlined on copies).
#include "Compiler/detail/lowerer.h"

#include "Compiler/detail/library_call.h"
#include "Compiler/detail/user_call.h"

#include <utility>

namespace frep::compiler::lowering
{

void SymbolicContext::abort_if(const Expr& condition, const char* message)
{
  lowerer->guard(condition, message, location);
}

Expr Lowerer::eval_node(Frame& frame, const ast::Expr& e, const ast::CallExpr& n)
{
  if (n.function < FunctionId::Sphere)
  {
    return builtin(frame, e, n);
  }
  return library_call(frame, e, n);
}

Expr Lowerer::builtin(Frame& frame, const ast::Expr& e, const ast::CallExpr& n)
{
  std::vector<Expr> args(n.args.size());
  for (std::size_t i = n.args.size(); i-- > 0;)
  {
    const auto* p = std::get_if<ast::ExprPtr>(&n.args[i]);
    if (!p || !*p)
    {
      throw CannotCompile("malformed AST: builtin with a non-expression argument");
    }
    args[i] = eval(frame, **p);
  }
  const std::size_t want = n.function >= FunctionId::Mod && n.function <= FunctionId::Atan2 ? 2 : 1;
  if (args.size() != want)
  {
    throw CannotCompile("malformed AST: builtin with a wrong number of arguments");
  }
  const Expr& v = args[0];
  const SourceLocation at = e.location;
  switch (n.function)
  {
    case FunctionId::Sqrt:
      if (!never_negative(v))
      {
        guard(v < Expr(0.0), messages::kNegativeSqrt, at);
      }
      return sqrt(v);
    case FunctionId::Exp:
      return exp(v);
    case FunctionId::Log:
      guard(logical_not(v > Expr(0.0)), messages::kNegativeLog, at);
      return log(v);
    case FunctionId::Logd:
      guard(logical_not(v > Expr(0.0)), messages::kNegativeLog, at);
      return log10(v);
    case FunctionId::Sin:
      return sin(v);
    case FunctionId::Cos:
      return cos(v);
    case FunctionId::Tan:
      guard(fabs(cos(v)) < Expr(kEps), messages::kTanArgument, at);
      return tan(v);
    case FunctionId::Asin:
      guard(fabs(v) > Expr(1.0), messages::kAsinAcosRange, at);
      return asin(v);
    case FunctionId::Acos:
      guard(fabs(v) > Expr(1.0), messages::kAsinAcosRange, at);
      return acos(v);
    case FunctionId::Atan:
      return atan(v);
    case FunctionId::Abs:
      return fabs(v);
    case FunctionId::Sinh:
      return sinh(v);
    case FunctionId::Cosh:
      return cosh(v);
    case FunctionId::Tanh:
      return tanh(v);
    case FunctionId::Sign:
      return Expr(1.0); // the original's bug: always 1
    case FunctionId::Mod:
      return apply(Opcode::HfMod, args[0], args[1]);
    case FunctionId::Max:
      return apply(Opcode::Max, args[0], args[1]);
    case FunctionId::Min:
      return apply(Opcode::Min, args[0], args[1]);
    case FunctionId::Atan2:
      return atan2(args[0], args[1]);
    case FunctionId::Ceil:
      return ceil(v);
    case FunctionId::Floor:
      return floor(v);
    case FunctionId::Int:
      return trunc(v);
    case FunctionId::Frac:
      return apply(Opcode::Frac, v);
    default:
      break;
  }
  throw CannotCompile("malformed AST: unknown builtin");
}

Expr Lowerer::library_call(Frame& frame, const ast::Expr& e, const ast::CallExpr& n)
{
  const FunctionInfo& info = function_info(n.function);
  if (static_cast<int>(n.args.size()) != info.arity)
  {
    throw CannotCompile("malformed AST: library call with a wrong number of arguments");
  }
  // Arguments last to first; array arguments are checked for unassigned items then.
  std::vector<Expr> reals(n.args.size());
  std::vector<std::vector<Cell>*> arrays(n.args.size(), nullptr);
  for (std::size_t i = n.args.size(); i-- > 0;)
  {
    if (const auto* p = std::get_if<ast::ExprPtr>(&n.args[i]))
    {
      if (!*p)
      {
        throw CannotCompile("malformed AST: empty argument");
      }
      reals[i] = eval(frame, **p);
    }
    else if (const auto* a = std::get_if<ast::ArrayName>(&n.args[i]))
    {
      arrays[i] = &frame.array(*a);
      guard(not_assigned(all_assigned(*arrays[i])), messages::kUnassignedArray, a->location);
    }
  }
  if (dead_)
  {
    return Expr(0.0);
  }
  // The same array passed twice is one buffer, as the original's aliasing pointers are.
  std::vector<std::vector<Cell>*> distinct;
  std::vector<std::size_t> buffer_of(n.args.size(), 0);
  for (std::size_t i = 0; i < n.args.size(); ++i)
  {
    if (!arrays[i])
    {
      continue;
    }
    std::size_t b = 0;
    while (b < distinct.size() && distinct[b] != arrays[i])
    {
      ++b;
    }
    if (b == distinct.size())
    {
      distinct.push_back(arrays[i]);
    }
    buffer_of[i] = b;
  }

  if (library::is_generic(n.function))
  {
    std::vector<std::vector<Expr>> buffers(distinct.size());
    for (std::size_t b = 0; b < distinct.size(); ++b)
    {
      for (const Cell& c : *distinct[b])
      {
        buffers[b].push_back(c.value);
      }
    }
    std::vector<library::Arg<Expr>> args(n.args.size());
    for (std::size_t i = 0; i < n.args.size(); ++i)
    {
      args[i].real = reals[i];
      if (arrays[i])
      {
        args[i].array = std::span<Expr>(buffers[buffer_of[i]]);
      }
    }
    SymbolicContext context{ this, e.location };
    std::optional<Expr> result =
      library::call_generic<Expr, SymbolicContext>(n.function, std::span(args), context);
    if (result)
    {
      for (std::size_t b = 0; b < distinct.size(); ++b)
      {
        for (std::size_t k = 0; k < buffers[b].size(); ++k)
        {
          (*distinct[b])[k].value = buffers[b][k];
        }
      }
      return *result;
    }
  }

  // Opaque call: inputs = path flag, real args, every array item; outputs = result and
  // every array item after the call (in-place effects).
  std::vector<std::size_t> sizes;
  std::vector<NodeId> inputs;
  inputs.push_back(path_.node(dag_));
  for (std::size_t i = 0; i < n.args.size(); ++i)
  {
    inputs.push_back(reals[i].node(dag_));
  }
  for (std::vector<Cell>* cells : distinct)
  {
    sizes.push_back(cells->size());
    for (const Cell& c : *cells)
    {
      inputs.push_back(c.value.node(dag_));
    }
  }
  std::vector<std::pair<std::string, int>> aborts;
  for (const char* message : library_abort_messages())
  {
    aborts.emplace_back(message, error_id(message, e.location));
  }
  auto function =
    make_library_function(n.function, buffer_of, arrays_mask(arrays), sizes, std::move(aborts));
  const std::uint32_t output_count = static_cast<std::uint32_t>(inputs.size() - n.args.size());
  const NodeId call = dag_.call(std::move(function), std::move(inputs), output_count);
  Effect effect;
  effect.is_call = true;
  effect.node = call;
  out_.effects.push_back(effect);
  const DagCall& info_call = dag_.call_of(call);
  std::size_t next = 1;
  for (std::vector<Cell>* cells : distinct)
  {
    for (Cell& c : *cells)
    {
      c.value = Expr(&dag_, info_call.outputs[next++]);
    }
  }
  return Expr(&dag_, info_call.outputs[0]);
}

Expr Lowerer::eval_node(Frame& frame, const ast::Expr& e, const ast::UserCallExpr& n)
{
  const auto& users = program_.user_functions;
  if (!users || n.function < 0 || n.function >= users->size())
  {
    throw CannotCompile("malformed AST: unknown user function");
  }
  std::vector<std::vector<Expr>> items(n.args.size());
  for (std::size_t i = n.args.size(); i-- > 0;)
  {
    if (const auto* p = std::get_if<ast::ExprPtr>(&n.args[i]))
    {
      if (!*p)
      {
        throw CannotCompile("malformed AST: empty argument");
      }
      items[i].push_back(eval(frame, **p));
    }
    else if (const auto* a = std::get_if<ast::ArrayName>(&n.args[i]))
    {
      std::vector<Cell>& cells = frame.array(*a);
      guard(not_assigned(all_assigned(cells)), messages::kUnassignedArray, a->location);
      for (const Cell& c : cells)
      {
        items[i].push_back(c.value);
      }
    }
    else
    {
      throw CannotCompile("malformed AST: a string argument to a user function");
    }
  }
  if (dead_)
  {
    return Expr(0.0);
  }
  const UserFunction& function = users->at(n.function);
  std::vector<NodeId> inputs;
  std::vector<int> sizes;
  inputs.push_back(path_.node(dag_));
  for (const std::vector<Expr>& arg : items)
  {
    sizes.push_back(static_cast<int>(arg.size()));
    for (const Expr& v : arg)
    {
      inputs.push_back(v.node(dag_));
    }
  }
  const int error = error_id(user_function_error(function.name), e.location);
  const NodeId call = dag_.call(
    make_user_function(users->shared(n.function), std::move(sizes), error), std::move(inputs), 1);
  Effect effect;
  effect.is_call = true;
  effect.node = call;
  out_.effects.push_back(effect);
  return Expr(&dag_, dag_.call_of(call).outputs[0]);
}

std::vector<bool> Lowerer::arrays_mask(const std::vector<std::vector<Cell>*>& arrays)
{
  std::vector<bool> mask;
  for (auto* a : arrays)
  {
    mask.push_back(a != nullptr);
  }
  return mask;
}

Expr Lowerer::all_assigned(const std::vector<Cell>& cells)
{
  Expr all(1.0);
  for (const Cell& c : cells)
  {
    all = logical_and(all, c.assigned);
  }
  return all;
}

Expr Lowerer::eval_node(Frame& frame, const ast::Expr& e, const ast::ObjectCallExpr& n)
{
  if (n.object < 0 || static_cast<std::size_t>(n.object) >= program_.objects.size() ||
      &program_.objects[static_cast<std::size_t>(n.object)] == frame.object)
  {
    throw CannotCompile("malformed AST: bad object call");
  }
  if (++call_depth_ > 200)
  {
    throw CannotCompile("object calls nest too deeply");
  }
  const ast::Object& callee = program_.objects[static_cast<std::size_t>(n.object)];
  std::vector<Cell>& xs = frame.array(n.x);
  std::vector<Cell>& as = frame.array(n.a);
  std::vector<Cell>& ss = n.s ? frame.array(*n.s) : frame.arrays[2];
  guard(not_assigned(all_assigned(xs)),
    messages::kUnassignedArray,
    semantics::object_call_x_check_location(n));
  const SourceLocation as_at = semantics::object_call_as_check_location(n, e.location);
  guard(not_assigned(all_assigned(as)), messages::kUnassignedArray, as_at);
  const std::size_t s_count = std::min(ss.size(), static_cast<std::size_t>(callee.s_dim));
  std::vector<Cell> s_used(ss.begin(), ss.begin() + static_cast<std::ptrdiff_t>(s_count));
  guard(not_assigned(all_assigned(s_used)), messages::kUnassignedArray, as_at);
  if (dead_)
  {
    --call_depth_;
    return Expr(0.0);
  }
  Frame inner = fresh_frame(callee);
  auto copy_in = [](std::vector<Cell>& to, const std::vector<Cell>& from)
  {
    for (std::size_t k = 0; k < to.size(); ++k)
    {
      to[k] = Cell{ k < from.size() ? from[k].value : Expr(0.0), Expr(1.0) };
    }
  };
  copy_in(inner.arrays[0], xs);
  copy_in(inner.arrays[1], as);
  copy_in(inner.arrays[2], s_used);
  // Errors inside the callee name its file (a HyperFun library file's objects have their own).
  const std::string* caller_file = std::exchange(file_, object_file(callee));
  const Expr value = execute(inner);
  file_ = caller_file;
  for (std::size_t k = 0; k < s_count && k < inner.arrays[2].size(); ++k)
  {
    ss[k].value = inner.arrays[2][k].value; // the callee's s[] is copied back
  }
  --call_depth_;
  return value;
}

} // namespace frep::compiler::lowering
