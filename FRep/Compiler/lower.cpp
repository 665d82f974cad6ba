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

#include "Compiler/detail/expr.h"
#include "Compiler/detail/library_call.h"
#include "Compiler/detail/user_call.h"
#include "Semantics/detail/error_positions.h"
#include "Semantics/detail/runtime_messages.h"
#include "Library/library.h"
#include "Library/detail/library_generic.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace frep::compiler
{

namespace
{

constexpr double kEps = semantics::kEps;

/// A scalar variable or array element: its value and whether it is assigned (1.0 / 0.0, or a
/// condition when it was assigned on some paths only).
struct Cell
{
  Expr value;
  Expr assigned{ 1.0 };
};

/// One activation of an object: its scalars and arrays (0 = x, 1 = a, 2 = s, 3.. = locals).
struct Frame
{
  const ast::Object* object = nullptr;
  std::vector<Cell> scalars;
  std::vector<std::vector<Cell>> arrays;

  std::vector<Cell>& array(const ast::ArrayName& name)
  {
    switch (name.kind)
    {
      case ast::ArrayKind::X:
        return arrays[0];
      case ast::ArrayKind::A:
        return arrays[1];
      case ast::ArrayKind::S:
        return arrays[2];
      case ast::ArrayKind::Local:
        break;
    }
    const auto i = static_cast<std::size_t>(name.local) + 3;
    if (name.local < 0 || i >= arrays.size())
    {
      throw CannotCompile("malformed AST: bad local array reference");
    }
    return arrays[i];
  }
};

class Lowerer;

/// The Ctx of library::call_generic<Expr>: an abort of the library becomes a guard.
struct SymbolicContext
{
  Lowerer* lowerer;
  SourceLocation location;
  void abort_if(const Expr& condition, const char* message);
  void abort_if(bool condition, const char* message)
  {
    abort_if(Expr(condition ? 1.0 : 0.0), message);
  }
};

class Lowerer
{
public:
  Lowerer(const ast::Program& program, const CompileOptions& options, Lowered& out)
    : program_(program)
    , options_(options)
    , out_(out)
    , dag_(out.dag)
  {
  }

  void run(int object_index, const Specialisation& spec)
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

  /// Raises `message` at `location` when `condition` holds on the current path.
  void guard(const Expr& condition, const char* message, SourceLocation location)
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

  int error_id(const std::string& message, SourceLocation location)
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

private:
  Frame fresh_frame(const ast::Object& object)
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

  /// Runs the body and the final expression of frame.object.
  Expr execute(Frame& frame)
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

  bool never_negative(const Expr& e) const
  {
    return e.is_constant() ? !(e.constant() < 0.0) : dag_.node(e.node(dag_)).never_negative;
  }

  Expr not_assigned(const Expr& assigned) { return logical_not(assigned); }

  // ---------------------------------------------------------------------------------------
  // statements

  void execute_block(Frame& frame, const ast::Block& block)
  {
    for (const ast::Stmt& stmt : block)
    {
      if (dead_)
      {
        return;
      }
      std::visit([&](const auto& s) { execute_stmt(frame, stmt, s); }, stmt.node);
    }
  }

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::AssignScalar& s)
  {
    const Expr v = eval(frame, *s.value);
    if (s.scalar < 0 || static_cast<std::size_t>(s.scalar) >= frame.scalars.size())
    {
      throw CannotCompile("malformed AST: bad scalar index");
    }
    frame.scalars[static_cast<std::size_t>(s.scalar)] = Cell{ v, Expr(1.0) };
  }

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::AssignElement& s)
  {
    std::vector<Cell>& cells = frame.array(s.array);
    const Expr index = eval(frame, *s.index);
    const Expr r = apply(Opcode::HfRound, index);
    const auto n = static_cast<double>(cells.size());
    const Expr in_range = logical_and(r >= Expr(1.0), r <= Expr(n));
    guard(logical_not(in_range),
      messages::kIndexOutOfRange,
      semantics::index_write_location(*s.index, s.index_end));
    if (dead_)
    {
      return;
    }
    const Expr v = eval(frame, *s.value);
    if (r.is_constant())
    {
      cells[static_cast<std::size_t>(r.constant()) - 1] = Cell{ v, Expr(1.0) };
      return;
    }
    for (std::size_t k = 0; k < cells.size(); ++k)
    {
      const Expr hit = apply(Opcode::Eq, r, Expr(static_cast<double>(k + 1)));
      cells[k].value = select(hit, v, cells[k].value);
      cells[k].assigned = select(hit, Expr(1.0), cells[k].assigned);
    }
  }

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::AssignArray& s)
  {
    std::vector<Cell>& cells = frame.array(s.array);
    for (std::size_t k = 0; k < s.values.size() && k < cells.size(); ++k)
    {
      cells[k] = Cell{ Expr(s.values[k]), Expr(1.0) };
    }
  }

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::IfStmt& s)
  {
    const Expr c = apply(Opcode::Truthy, eval(frame, *s.condition));
    if (dead_)
    {
      return;
    }
    if (c.is_constant())
    {
      execute_block(frame, c.constant() != 0 ? s.then_block : s.else_block);
      return;
    }
    // Only the scalars the branches assign can differ between them: those are saved, run in
    // each branch and merged, not the whole frame (a .vm tape's thousands of choices over
    // thousands of scalars would otherwise cost the product). Arrays are few: all are kept.
    const std::vector<int>& touched = assigned_scalars(s);
    std::vector<Cell> before = gather(frame.scalars, touched);
    std::vector<std::vector<Cell>> then_arrays = frame.arrays;
    const Expr outer_path = path_;
    path_ = logical_and(outer_path, c);
    execute_block(frame, s.then_block);
    const bool then_dead = dead_;
    dead_ = false;
    std::vector<Cell> then_scalars = gather(frame.scalars, touched);
    std::swap(then_arrays, frame.arrays); // frame: the state before, then_arrays: the then branch's
    scatter(frame.scalars, touched, before);
    path_ = logical_and(outer_path, logical_not(c));
    execute_block(frame, s.else_block);
    const bool else_dead = dead_;
    path_ = outer_path;
    dead_ = then_dead && else_dead;
    if (then_dead || else_dead)
    {
      // Points on a dead branch have failed: only the live branch's state matters (the frame
      // holds the else branch's).
      if (else_dead && !then_dead)
      {
        scatter(frame.scalars, touched, then_scalars);
        frame.arrays = std::move(then_arrays);
      }
      return;
    }
    std::vector<Cell> else_scalars = gather(frame.scalars, touched);
    merge(c, then_scalars, else_scalars);
    scatter(frame.scalars, touched, then_scalars);
    for (std::size_t i = 0; i < frame.arrays.size(); ++i)
    {
      merge(c, then_arrays[i], frame.arrays[i]);
    }
    frame.arrays = std::move(then_arrays);
  }

  static std::vector<Cell> gather(const std::vector<Cell>& cells, const std::vector<int>& which)
  {
    std::vector<Cell> out;
    out.reserve(which.size());
    for (const int k : which)
    {
      out.push_back(cells[static_cast<std::size_t>(k)]);
    }
    return out;
  }

  static void scatter(std::vector<Cell>& cells, const std::vector<int>& which,
    const std::vector<Cell>& values)
  {
    for (std::size_t i = 0; i < which.size(); ++i)
    {
      cells[static_cast<std::size_t>(which[i])] = values[i];
    }
  }

  /// The scalars an if-statement's branches assign (at any depth), in increasing order: the only
  /// ones that can differ between the branches (a scalar changes only by assignment; calls
  /// change arrays). Computed once per statement.
  const std::vector<int>& assigned_scalars(const ast::IfStmt& s)
  {
    auto [it, inserted] = assigned_scalars_.try_emplace(&s);
    if (inserted)
    {
      std::vector<int>& out = it->second;
      collect_assigned(s.then_block, out);
      collect_assigned(s.else_block, out);
      std::sort(out.begin(), out.end());
      out.erase(std::unique(out.begin(), out.end()), out.end());
      for (const int k : out)
      {
        if (k < 0)
        {
          throw CannotCompile("malformed AST: bad scalar index");
        }
      }
    }
    return it->second;
  }

  static void collect_assigned(const ast::Block& block, std::vector<int>& out)
  {
    for (const ast::Stmt& stmt : block)
    {
      if (const auto* a = std::get_if<ast::AssignScalar>(&stmt.node))
      {
        out.push_back(a->scalar);
      }
      else if (const auto* i = std::get_if<ast::IfStmt>(&stmt.node))
      {
        collect_assigned(i->then_block, out);
        collect_assigned(i->else_block, out);
      }
      else if (const auto* w = std::get_if<ast::WhileStmt>(&stmt.node))
      {
        collect_assigned(w->body, out);
      }
    }
  }

  void merge(const Expr& c, std::vector<Cell>& then_cells, const std::vector<Cell>& else_cells)
  {
    for (std::size_t k = 0; k < then_cells.size(); ++k)
    {
      Cell& t = then_cells[k];
      const Cell& e = else_cells[k];
      const bool t_unset = t.assigned.is_constant() && t.assigned.constant() == 0;
      const bool e_unset = e.assigned.is_constant() && e.assigned.constant() == 0;
      // Reading an unassigned cell fails before its value is used, so its value is free.
      if (e_unset && !t_unset)
      {
        t.assigned = select(c, t.assigned, e.assigned);
        continue;
      }
      if (t_unset && !e_unset)
      {
        t.value = e.value;
        t.assigned = select(c, t.assigned, e.assigned);
        continue;
      }
      t.value = select(c, t.value, e.value);
      t.assigned = select(c, t.assigned, e.assigned);
    }
  }

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::WhileStmt& s)
  {
    std::size_t iterations = 0;
    while (!dead_)
    {
      const Expr c = eval(frame, *s.condition);
      if (dead_)
      {
        return;
      }
      if (!c.is_constant())
      {
        throw CannotCompile("a while condition depends on the free coordinates");
      }
      if (!semantics::truthy(c.constant()))
      {
        return;
      }
      if (++iterations > options_.max_unrolled_iterations)
      {
        throw CannotCompile("a while loop runs more iterations than the unrolling limit");
      }
      execute_block(frame, s.body);
    }
  }

  // ---------------------------------------------------------------------------------------
  // expressions

  Expr eval(Frame& frame, const ast::Expr& e)
  {
    return std::visit([&](const auto& n) { return eval_node(frame, e, n); }, e.node);
  }

  Expr eval_node(Frame&, const ast::Expr&, const ast::NumberExpr& n) { return Expr(n.value); }

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::ScalarExpr& n)
  {
    if (n.scalar < 0 || static_cast<std::size_t>(n.scalar) >= frame.scalars.size())
    {
      throw CannotCompile("malformed AST: bad scalar index");
    }
    const Cell& cell = frame.scalars[static_cast<std::size_t>(n.scalar)];
    guard(not_assigned(cell.assigned), messages::kNotInitialized, e.location);
    return cell.value;
  }

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::ElementExpr& n)
  {
    if (!n.index)
    {
      throw CannotCompile("malformed AST: element without index");
    }
    const Expr index = eval(frame, *n.index);
    std::vector<Cell>& cells = frame.array(n.array);
    const Expr r = apply(Opcode::HfRound, index);
    const auto size = static_cast<double>(cells.size());
    const Expr in_range = logical_and(r >= Expr(1.0), r <= Expr(size));
    guard(logical_not(in_range),
      messages::kIndexOutOfRange,
      semantics::first_instruction_location(*n.index));
    if (dead_ || cells.empty())
    {
      return Expr(0.0);
    }
    if (r.is_constant())
    {
      const Cell& cell = cells[static_cast<std::size_t>(r.constant()) - 1];
      guard(not_assigned(cell.assigned), messages::kUnassignedElement, e.location);
      return cell.value;
    }
    Cell chosen = cells.back();
    for (std::size_t k = cells.size() - 1; k-- > 0;)
    {
      const Expr hit = apply(Opcode::Eq, r, Expr(static_cast<double>(k + 1)));
      chosen.value = select(hit, cells[k].value, chosen.value);
      chosen.assigned = select(hit, cells[k].assigned, chosen.assigned);
    }
    guard(not_assigned(chosen.assigned), messages::kUnassignedElement, e.location);
    return chosen.value;
  }

  Expr eval_node(Frame& frame, const ast::Expr&, const ast::UnaryExpr& n)
  {
    const Expr v = eval(frame, *n.operand);
    return n.op == ast::UnaryOp::Plus ? v : -v;
  }

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::BinaryExpr& n)
  {
    const Expr r = eval(frame, *n.rhs); // right operand first, as the original
    const Expr l = eval(frame, *n.lhs);
    switch (n.op)
    {
      case ast::BinaryOp::Add:
        return l + r;
      case ast::BinaryOp::Sub:
        return l - r;
      case ast::BinaryOp::Mul:
        return l * r;
      case ast::BinaryOp::Div:
        guard(fabs(r) < Expr(kEps), messages::kDivisionByZero, e.location);
        return l / r;
      case ast::BinaryOp::Pow:
        return power(l, r, e.location);
      case ast::BinaryOp::Union:
        return apply(Opcode::Union, l, r);
      case ast::BinaryOp::Intersect:
      case ast::BinaryOp::Product:
        return apply(Opcode::Intersect, l, r);
      case ast::BinaryOp::Subtract:
        return apply(Opcode::Intersect, l, -r);
    }
    return Expr(0.0);
  }

  Expr power(const Expr& base, const Expr& e, SourceLocation location)
  {
    const Expr tiny = fabs(base) < Expr(kEps);
    if (e.is_constant())
    {
      const double x = e.constant();
      if (x <= kEps)
      {
        guard(tiny, messages::kZeroPowerBase, location);
      }
      if ((x - std::floor(x)) < kEps)
      {
        const int n = semantics::hf_round(std::fabs(x));
        if (n == INT_MIN)
        {
          return apply(Opcode::HfPow, base, e); // |e| beyond int: the general rule handles it
        }
        return pow_int(base, x < 0.0 ? -n : n);
      }
      if (!never_negative(base))
      {
        guard(
          logical_and(logical_not(tiny), base < Expr(0.0)), messages::kNegativePowerBase, location);
      }
      return apply(Opcode::HfPow, base, e);
    }
    guard(logical_and(tiny, e <= Expr(kEps)), messages::kZeroPowerBase, location);
    if (!never_negative(base))
    {
      // Not `>= kEps`: for an infinite or NaN exponent e - floor(e) is NaN, which
      // hf_pow_error counts as fractional (its test is `< kEps`, false for NaN). Found by
      // fuzzing (Testing/Fuzz/regressions/fuzz_hyperfun_eval/negative_base_infinite_exponent.hf).
      const Expr fractional = logical_not((e - floor(e)) < Expr(kEps));
      guard(logical_and(logical_and(logical_not(tiny), fractional), base < Expr(0.0)),
        messages::kNegativePowerBase,
        location);
    }
    return apply(Opcode::HfPow, base, e);
  }

  Expr eval_node(Frame& frame, const ast::Expr&, const ast::CompareExpr& n)
  {
    const Expr r = eval(frame, *n.rhs);
    const Expr l = eval(frame, *n.lhs);
    switch (n.op)
    {
      case ast::CompareOp::Eq:
        return apply(Opcode::Eq, l, r);
      case ast::CompareOp::Ne:
        return apply(Opcode::Ne, l, r);
      case ast::CompareOp::Lt:
        return l < r;
      case ast::CompareOp::Le:
        return l <= r;
      case ast::CompareOp::Gt:
        return l > r;
      case ast::CompareOp::Ge:
        return l >= r;
    }
    return Expr(0.0);
  }

  Expr eval_node(Frame& frame, const ast::Expr&, const ast::LogicExpr& n)
  {
    const Expr r = eval(frame, *n.rhs); // no short circuit: both sides run (and may fail)
    const Expr l = eval(frame, *n.lhs);
    return n.op == ast::LogicOp::And ? logical_and(l, r) : logical_or(l, r);
  }

  Expr eval_node(Frame& frame, const ast::Expr&, const ast::NotExpr& n)
  {
    return logical_not(eval(frame, *n.operand));
  }

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::CallExpr& n)
  {
    if (n.function < FunctionId::Sphere)
    {
      return builtin(frame, e, n);
    }
    return library_call(frame, e, n);
  }

  Expr builtin(Frame& frame, const ast::Expr& e, const ast::CallExpr& n)
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
    const std::size_t want =
      n.function >= FunctionId::Mod && n.function <= FunctionId::Atan2 ? 2 : 1;
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

  Expr library_call(Frame& frame, const ast::Expr& e, const ast::CallExpr& n)
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

  /// A user function: an opaque call with the path flag and every item of every argument;
  /// arguments last to first, arrays checked for unassigned items then (as a library call).
  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::UserCallExpr& n)
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
    const NodeId call =
      dag_.call(make_user_function(users->shared(n.function), std::move(sizes), error),
        std::move(inputs), 1);
    Effect effect;
    effect.is_call = true;
    effect.node = call;
    out_.effects.push_back(effect);
    return Expr(&dag_, dag_.call_of(call).outputs[0]);
  }

  static std::vector<bool> arrays_mask(const std::vector<std::vector<Cell>*>& arrays)
  {
    std::vector<bool> mask;
    for (auto* a : arrays)
    {
      mask.push_back(a != nullptr);
    }
    return mask;
  }

  Expr all_assigned(const std::vector<Cell>& cells)
  {
    Expr all(1.0);
    for (const Cell& c : cells)
    {
      all = logical_and(all, c.assigned);
    }
    return all;
  }

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::ObjectCallExpr& n)
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

  friend struct SymbolicContext;

  const ast::Program& program_;
  const CompileOptions& options_;
  Lowered& out_;
  Dag& dag_;
  Expr path_{ 1.0 };
  bool dead_ = false;
  int call_depth_ = 0;
  std::map<std::tuple<std::string, int, int, std::string>, int> error_ids_;
  std::unordered_set<NodeId> guarded_;
  std::unordered_map<const ast::IfStmt*, std::vector<int>> assigned_scalars_;
  /// The file of the object being lowered (run-time errors name it).
  const std::string* file_ = &program_.file;

  const std::string* object_file(const ast::Object& object) const
  {
    return object.file.empty() ? &program_.file : &object.file;
  }
};

void SymbolicContext::abort_if(const Expr& condition, const char* message)
{
  lowerer->guard(condition, message, location);
}

} // namespace

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
