// The Lowerer (Compiler/lower.cpp runs it: lower()): the symbolic execution of one object's
// AST, its state and its members, declared here and defined in files by what they execute:
// lower.cpp (running an object, guards, frames), lower_statements.cpp (statements, if-merges,
// loops), lower_expressions.cpp (scalars, elements, operators, comparisons, logic),
// lower_calls.cpp (built-ins, the library, user functions, object calls). Private to the
// engine. The semantics are documented at the top of lower.cpp.
#pragma once

#include "Compiler/detail/expr.h"
#include "Compiler/detail/lower.h"
#include "Library/detail/library_generic.h"
#include "Library/library.h"
#include "Semantics/detail/error_positions.h"
#include "Semantics/detail/runtime_messages.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace frep::compiler::lowering
{

inline constexpr double kEps = semantics::kEps;

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

// Hidden, as the Parser (Language/detail/parser_class.h): calls between the lower_*.cpp files
// stay direct and inlinable inside the shared engine library.
class [[gnu::visibility("hidden")]] Lowerer
{
public:
  Lowerer(const ast::Program& program, const CompileOptions& options, Lowered& out)
    : program_(program)
    , options_(options)
    , out_(out)
    , dag_(out.dag)
  {
  }

  void run(int object_index, const Specialisation& spec);

  /// Raises `message` at `location` when `condition` holds on the current path.
  void guard(const Expr& condition, const char* message, SourceLocation location);

  int error_id(const std::string& message, SourceLocation location);

private:
  Frame fresh_frame(const ast::Object& object);

  /// Runs the body and the final expression of frame.object.
  Expr execute(Frame& frame);

  bool never_negative(const Expr& e) const
  {
    return e.is_constant() ? !(e.constant() < 0.0) : dag_.node(e.node(dag_)).never_negative;
  }

  Expr not_assigned(const Expr& assigned) { return logical_not(assigned); }

  // ---------------------------------------------------------------------------------------
  // statements

  void execute_block(Frame& frame, const ast::Block& block);

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::AssignScalar& s);

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::AssignElement& s);

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::AssignArray& s);

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::IfStmt& s);

  static std::vector<Cell> gather(const std::vector<Cell>& cells, const std::vector<int>& which);

  static void scatter(std::vector<Cell>& cells,
    const std::vector<int>& which,
    const std::vector<Cell>& values);

  /// The scalars an if-statement's branches assign (at any depth), in increasing order: the only
  /// ones that can differ between the branches (a scalar changes only by assignment; calls
  /// change arrays). Computed once per statement.
  const std::vector<int>& assigned_scalars(const ast::IfStmt& s);

  static void collect_assigned(const ast::Block& block, std::vector<int>& out);

  void merge(const Expr& c, std::vector<Cell>& then_cells, const std::vector<Cell>& else_cells);

  void execute_stmt(Frame& frame, const ast::Stmt&, const ast::WhileStmt& s);

  // ---------------------------------------------------------------------------------------
  // expressions

  Expr eval(Frame& frame, const ast::Expr& e)
  {
    return std::visit([&](const auto& n) { return eval_node(frame, e, n); }, e.node);
  }

  Expr eval_node(Frame&, const ast::Expr&, const ast::NumberExpr& n) { return Expr(n.value); }

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::ScalarExpr& n);

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::ElementExpr& n);

  Expr eval_node(Frame& frame, const ast::Expr&, const ast::UnaryExpr& n)
  {
    const Expr v = eval(frame, *n.operand);
    return n.op == ast::UnaryOp::Plus ? v : -v;
  }

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::BinaryExpr& n);

  Expr power(const Expr& base, const Expr& e, SourceLocation location);

  Expr eval_node(Frame& frame, const ast::Expr&, const ast::CompareExpr& n);

  Expr eval_node(Frame& frame, const ast::Expr&, const ast::LogicExpr& n);

  Expr eval_node(Frame& frame, const ast::Expr&, const ast::NotExpr& n)
  {
    return logical_not(eval(frame, *n.operand));
  }

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::CallExpr& n);

  Expr builtin(Frame& frame, const ast::Expr& e, const ast::CallExpr& n);

  Expr library_call(Frame& frame, const ast::Expr& e, const ast::CallExpr& n);

  /// A user function: an opaque call with the path flag and every item of every argument;
  /// arguments last to first, arrays checked for unassigned items then (as a library call).
  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::UserCallExpr& n);

  static std::vector<bool> arrays_mask(const std::vector<std::vector<Cell>*>& arrays);

  Expr all_assigned(const std::vector<Cell>& cells);

  Expr eval_node(Frame& frame, const ast::Expr& e, const ast::ObjectCallExpr& n);

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

} // namespace frep::compiler::lowering
