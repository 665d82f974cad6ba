#include "Semantics/detail/ast_validation.h"

#include "Language/function_table.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace frep::semantics
{
namespace
{

class Validator
{
public:
  Validator(const ast::Program& program)
    : program_(program)
    , checked_(program.objects.size())
  {
  }

  void check_object(int index)
  {
    if (index < 0 || index >= static_cast<int>(program_.objects.size()))
    {
      fail("object index out of range");
    }
    if (checked_[index])
    {
      return;
    }
    checked_[index] = true;
    const ast::Object& object = program_.objects[index];
    current_ = index;
    if (object.x_dim < 0 || object.a_dim < 0 || object.s_dim < 0)
    {
      fail("negative array dimension in object '" + object.name + "'");
    }
    for (const ast::LocalArray& array : object.arrays)
    {
      if (array.size <= 0)
      {
        fail("local array '" + array.name + "' has no items");
      }
    }
    check_block(object, object.body);
    if (!object.result)
    {
      fail("object '" + object.name + "' has no final expression");
    }
    check_expr(object, *object.result);
    // Callees are checked after this object's own nodes (the "earlier object" rule of
    // check_node uses current_, which each nested check_object sets for itself).
    std::vector<int> callees;
    callees.swap(callees_of_current_);
    for (int callee : callees)
    {
      check_object(callee);
    }
  }

private:
  [[noreturn]] void fail(const std::string& what) const
  {
    throw std::invalid_argument("invalid HyperFun AST: " + what);
  }

  void check_array(const ast::Object& object, const ast::ArrayName& array)
  {
    if (array_size(object, array) < 0)
    {
      fail("invalid array reference in object '" + object.name + "'");
    }
  }

  void check_block(const ast::Object& object, const ast::Block& block)
  {
    for (const ast::Stmt& stmt : block)
    {
      check_stmt(object, stmt);
    }
  }

  void check_stmt(const ast::Object& object, const ast::Stmt& stmt)
  {
    if (const auto* s = std::get_if<ast::AssignScalar>(&stmt.node))
    {
      check_scalar(object, s->scalar);
      check_child(object, s->value);
    }
    else if (const auto* s = std::get_if<ast::AssignElement>(&stmt.node))
    {
      check_writable(object, s->array);
      check_child(object, s->index);
      check_child(object, s->value);
    }
    else if (const auto* s = std::get_if<ast::AssignArray>(&stmt.node))
    {
      check_writable(object, s->array);
    }
    else if (const auto* s = std::get_if<ast::IfStmt>(&stmt.node))
    {
      check_child(object, s->condition);
      check_block(object, s->then_block);
      check_block(object, s->else_block);
    }
    else if (const auto* s = std::get_if<ast::WhileStmt>(&stmt.node))
    {
      check_child(object, s->condition);
      check_block(object, s->body);
    }
  }

  void check_writable(const ast::Object& object, const ast::ArrayName& array)
  {
    check_array(object, array);
    if (array.kind != ast::ArrayKind::Local && array.kind != ast::ArrayKind::S)
    {
      fail("assignment to x[] or a[] in object '" + object.name + "'");
    }
  }

  void check_scalar(const ast::Object& object, int scalar)
  {
    if (scalar < 0 || scalar >= static_cast<int>(object.scalars.size()))
    {
      fail("scalar slot out of range in object '" + object.name + "'");
    }
  }

  void check_child(const ast::Object& object, const ast::ExprPtr& expr)
  {
    if (!expr)
    {
      fail("missing expression in object '" + object.name + "'");
    }
    check_expr(object, *expr);
  }

  void check_expr(const ast::Object& object, const ast::Expr& expr)
  {
    std::visit([&](const auto& node) { check_node(object, node); }, expr.node);
  }

  void check_node(const ast::Object&, const ast::NumberExpr&) {}
  void check_node(const ast::Object& object, const ast::ScalarExpr& node)
  {
    check_scalar(object, node.scalar);
  }
  void check_node(const ast::Object& object, const ast::ElementExpr& node)
  {
    check_array(object, node.array);
    check_child(object, node.index);
  }
  void check_node(const ast::Object& object, const ast::UnaryExpr& node)
  {
    check_child(object, node.operand);
  }
  /// BinaryExpr, CompareExpr, LogicExpr: two operands.
  template<class Node>
    requires requires(const Node& n) { n.lhs, n.rhs; }
  void check_node(const ast::Object& object, const Node& node)
  {
    check_child(object, node.lhs);
    check_child(object, node.rhs);
  }
  void check_node(const ast::Object& object, const ast::NotExpr& node)
  {
    check_child(object, node.operand);
  }
  void check_node(const ast::Object& object, const ast::CallExpr& node)
  {
    if (static_cast<int>(node.function) >= static_cast<int>(FunctionId::Count))
    {
      fail("unknown function id in object '" + object.name + "'");
    }
    const FunctionInfo& info = function_info(node.function);
    if (static_cast<int>(node.args.size()) != info.arity)
    {
      fail("wrong argument count for " + std::string(info.spelling));
    }
    for (int i = 0; i < info.arity; ++i)
    {
      const ast::CallArg& arg = node.args[i];
      switch (info.kinds[i])
      {
        case ArgKind::Real:
          if (!std::holds_alternative<ast::ExprPtr>(arg))
          {
            fail("argument kind mismatch for " + std::string(info.spelling));
          }
          check_child(object, std::get<ast::ExprPtr>(arg));
          break;
        case ArgKind::Array:
          if (!std::holds_alternative<ast::ArrayName>(arg))
          {
            fail("argument kind mismatch for " + std::string(info.spelling));
          }
          check_array(object, std::get<ast::ArrayName>(arg));
          break;
        case ArgKind::String:
          if (!std::holds_alternative<std::string>(arg))
          {
            fail("argument kind mismatch for " + std::string(info.spelling));
          }
          break;
      }
    }
  }
  void check_node(const ast::Object& object, const ast::UserCallExpr& node)
  {
    const auto& users = program_.user_functions;
    if (!users || node.function < 0 || node.function >= users->size())
    {
      fail("unknown user function in object '" + object.name + "'");
    }
    const UserFunction& f = users->at(node.function);
    if (node.args.size() != f.kinds.size())
    {
      fail("wrong argument count for " + f.name);
    }
    for (std::size_t i = 0; i < f.kinds.size(); ++i)
    {
      const ast::CallArg& arg = node.args[i];
      if (f.kinds[i] == ArgKind::Array)
      {
        if (!std::holds_alternative<ast::ArrayName>(arg))
        {
          fail("argument kind mismatch for " + f.name);
        }
        check_array(object, std::get<ast::ArrayName>(arg));
        const int wanted = i < f.array_sizes.size() ? f.array_sizes[i] : 0;
        if (wanted > 0 && array_size(object, std::get<ast::ArrayName>(arg)) != wanted)
        {
          fail("array size mismatch for " + f.name);
        }
      }
      else
      {
        if (!std::holds_alternative<ast::ExprPtr>(arg))
        {
          fail("argument kind mismatch for " + f.name);
        }
        check_child(object, std::get<ast::ExprPtr>(arg));
      }
    }
  }
  void check_node(const ast::Object& object, const ast::ObjectCallExpr& node)
  {
    // Only earlier objects may be called: this is what rules out recursion.
    if (node.object < 0 || node.object >= current_)
    {
      fail("object '" + object.name + "' calls an object that is not defined before it");
    }
    const ast::Object& callee = program_.objects[node.object];
    check_array(object, node.x);
    check_array(object, node.a);
    const bool sizes_ok =
      array_size(object, node.x) == callee.x_dim && array_size(object, node.a) == callee.a_dim &&
      (node.s ? array_size(object, *node.s) == callee.s_dim : callee.s_dim <= object.s_dim);
    if (node.s)
    {
      check_array(object, *node.s);
    }
    if (!sizes_ok)
    {
      fail("array sizes of a call of '" + callee.name + "' do not match");
    }
    callees_of_current_.push_back(node.object);
  }

  const ast::Program& program_;
  std::vector<bool> checked_;
  int current_ = 0;
  std::vector<int> callees_of_current_;
};

} // namespace

int array_size(const ast::Object& object, const ast::ArrayName& array)
{
  switch (array.kind)
  {
    case ast::ArrayKind::X:
      return object.x_dim;
    case ast::ArrayKind::A:
      return object.a_dim;
    case ast::ArrayKind::S:
      return object.s_dim;
    case ast::ArrayKind::Local:
      if (array.local >= 0 && array.local < static_cast<int>(object.arrays.size()))
      {
        return object.arrays[array.local].size;
      }
      return -1;
  }
  return -1;
}

void validate_object_graph(const ast::Program& program, int object_index)
{
  Validator(program).check_object(object_index);
}

} // namespace frep::semantics
