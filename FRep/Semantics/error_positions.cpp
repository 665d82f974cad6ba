#include "Semantics/detail/error_positions.h"

#include <type_traits>
#include <variant>

namespace frep::semantics
{
namespace
{

bool before(SourceLocation a, SourceLocation b)
{
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

} // namespace

SourceLocation first_instruction_location(const ast::Expr& expr)
{
  // Iterative descent: each step moves to the operand whose code comes first.
  const ast::Expr* e = &expr;
  for (;;)
  {
    const ast::Expr* next = nullptr;
    SourceLocation here = e->location;
    std::visit(
      [&](const auto& node)
      {
        using T = std::decay_t<decltype(node)>;
        if constexpr (std::is_same_v<T, ast::ElementExpr>)
        {
          next = node.index.get();
        }
        else if constexpr (std::is_same_v<T, ast::UnaryExpr> || std::is_same_v<T, ast::NotExpr>)
        {
          next = node.operand.get();
        }
        else if constexpr (std::is_same_v<T, ast::BinaryExpr> ||
                           std::is_same_v<T, ast::CompareExpr> || std::is_same_v<T, ast::LogicExpr>)
        {
          next = node.lhs.get();
        }
        else if constexpr (std::is_same_v<T, ast::CallExpr> || std::is_same_v<T, ast::UserCallExpr>)
        {
          if (!node.args.empty())
          {
            const ast::CallArg& first = node.args.front();
            if (const auto* p = std::get_if<ast::ExprPtr>(&first))
            {
              next = p->get();
            }
            else if (const auto* array = std::get_if<ast::ArrayName>(&first))
            {
              here = array->location;
            }
            // A string argument's position is not kept; the call's own position stands in.
          }
        }
        else if constexpr (std::is_same_v<T, ast::ObjectCallExpr>)
        {
          // The call's code starts with its third-argument instruction.
          here =
            node.s ? node.s->location : (node.close_paren.valid() ? node.close_paren : e->location);
        }
      },
      e->node);
    if (next == nullptr)
    {
      return here;
    }
    e = next;
  }
}

SourceLocation first_token_location(const ast::Expr& expr)
{
  const ast::Expr* e = &expr;
  for (;;)
  {
    const ast::Expr* next = nullptr;
    std::visit(
      [&](const auto& node)
      {
        using T = std::decay_t<decltype(node)>;
        if constexpr (std::is_same_v<T, ast::BinaryExpr> || std::is_same_v<T, ast::CompareExpr> ||
                      std::is_same_v<T, ast::LogicExpr>)
        {
          next = node.lhs.get(); // infix: the left operand comes first in the text
        }
      },
      e->node);
    if (next == nullptr)
    {
      return e->location; // prefix operator, name, literal or call: its own token is first
    }
    e = next;
  }
}

SourceLocation index_write_location(const ast::Expr& index, SourceLocation index_first_token)
{
  const SourceLocation derived = first_token_location(index);
  if (index_first_token.valid() && before(index_first_token, derived))
  {
    return index_first_token;
  }
  return derived;
}

SourceLocation object_call_x_check_location(const ast::ObjectCallExpr& call)
{
  return call.a.location;
}

SourceLocation object_call_as_check_location(const ast::ObjectCallExpr& call,
  SourceLocation call_location)
{
  if (call.s)
  {
    return call.s->location;
  }
  return call.close_paren.valid() ? call.close_paren : call_location;
}

} // namespace frep::semantics
