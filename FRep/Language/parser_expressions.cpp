// The Parser's expressions and calls (detail/parser_class.h).
#include "Language/detail/parser_class.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace frep::parsing
{

bool Parser::additive_op(TokenKind k, ast::BinaryOp& op)
{
  switch (k)
  {
    case TokenKind::Plus:
      op = ast::BinaryOp::Add;
      return true;
    case TokenKind::Minus:
      op = ast::BinaryOp::Sub;
      return true;
    case TokenKind::Bar:
      op = ast::BinaryOp::Union;
      return true;
    case TokenKind::Ampersand:
      op = ast::BinaryOp::Intersect;
      return true;
    case TokenKind::Backslash:
      op = ast::BinaryOp::Subtract;
      return true;
    case TokenKind::At:
      op = ast::BinaryOp::Product;
      return true;
    default:
      return false;
  }
}

Parsed Parser::binary(SourceLocation where, ast::BinaryOp op, Parsed lhs, Parsed rhs)
{
  const int depth = 1 + std::max(lhs.depth, rhs.depth);
  check_depth(depth);
  return Parsed{ make(where, ast::BinaryExpr{ op, std::move(lhs.expr), std::move(rhs.expr) }),
    depth };
}

Parsed Parser::parse_expression()
{
  Nest nest(*this);
  Parsed lhs = parse_term();
  ast::BinaryOp op{};
  while (additive_op(kind(), op))
  {
    const SourceLocation where = tok().location;
    advance();
    Parsed rhs = parse_term();
    lhs = binary(where, op, std::move(lhs), std::move(rhs));
  }
  return lhs;
}

Parsed Parser::parse_term()
{
  Parsed lhs = parse_power();
  while (kind() == TokenKind::Star || kind() == TokenKind::Slash)
  {
    const ast::BinaryOp op = kind() == TokenKind::Star ? ast::BinaryOp::Mul : ast::BinaryOp::Div;
    const SourceLocation where = tok().location;
    advance();
    Parsed rhs = parse_power();
    lhs = binary(where, op, std::move(lhs), std::move(rhs));
  }
  return lhs;
}

Parsed Parser::parse_power()
{
  Parsed lhs = parse_unary();
  while (kind() == TokenKind::Power)
  {
    const SourceLocation where = tok().location;
    advance();
    Parsed rhs = parse_unary();
    lhs = binary(where, ast::BinaryOp::Pow, std::move(lhs), std::move(rhs));
  }
  return lhs;
}

Parsed Parser::parse_unary()
{
  Nest nest(*this);
  ast::UnaryOp op{};
  switch (kind())
  {
    case TokenKind::Plus:
      op = ast::UnaryOp::Plus;
      break;
    case TokenKind::Minus:
      op = ast::UnaryOp::Minus;
      break;
    case TokenKind::Tilde:
      op = ast::UnaryOp::Negate;
      break;
    default:
      return parse_primary();
  }
  const SourceLocation where = tok().location;
  advance();
  Parsed operand = parse_unary();
  check_depth(operand.depth + 1);
  return Parsed{ make(where, ast::UnaryExpr{ op, std::move(operand.expr) }), operand.depth + 1 };
}

SourceLocation Parser::first_instruction(const ast::Expr& expr)
{
  const ast::Expr* e = &expr;
  for (;;)
  {
    if (const auto* element = std::get_if<ast::ElementExpr>(&e->node))
    {
      e = element->index.get();
    }
    else if (const auto* unary = std::get_if<ast::UnaryExpr>(&e->node))
    {
      e = unary->operand.get();
    }
    else if (const auto* binary = std::get_if<ast::BinaryExpr>(&e->node))
    {
      e = binary->lhs.get();
    }
    else if (const auto* compare = std::get_if<ast::CompareExpr>(&e->node))
    {
      e = compare->lhs.get();
    }
    else if (const auto* logic = std::get_if<ast::LogicExpr>(&e->node))
    {
      e = logic->lhs.get();
    }
    else if (const auto* negation = std::get_if<ast::NotExpr>(&e->node))
    {
      e = negation->operand.get();
    }
    else if (std::holds_alternative<ast::CallExpr>(e->node) ||
             std::holds_alternative<ast::UserCallExpr>(e->node))
    {
      const auto* call = std::get_if<ast::CallExpr>(&e->node);
      const auto* user = std::get_if<ast::UserCallExpr>(&e->node);
      const std::vector<ast::CallArg>& args = call ? call->args : user->args;
      if (args.empty())
      {
        return e->location;
      }
      const ast::CallArg& first = args.front();
      if (const auto* arg = std::get_if<ast::ExprPtr>(&first))
      {
        e = arg->get();
      }
      else if (const auto* array = std::get_if<ast::ArrayName>(&first))
      {
        return array->location;
      }
      else
      {
        return e->location; // string arguments: no registered function takes one
      }
    }
    else if (const auto* object = std::get_if<ast::ObjectCallExpr>(&e->node))
    {
      return object->s ? object->s->location : object->close_paren;
    }
    else
    {
      return e->location;
    }
  }
}

Parsed Parser::parse_element(const Token& name, ast::ArrayName array)
{
  advance(); // the name
  expect(TokenKind::LeftBracket, "Left bracket expected");
  advance();
  Parsed index = parse_expression();
  expect(TokenKind::RightBracket, "Right bracket expected");
  advance();
  check_depth(index.depth + 1);
  ast::ElementExpr node;
  node.array = array;
  node.index_end = first_instruction(*index.expr);
  node.index = std::move(index.expr);
  return Parsed{ make(name.location, std::move(node)), index.depth + 1 };
}

ast::ArrayName Parser::array_argument(int& size)
{
  const Token& t = tok();
  switch (t.kind)
  {
    case TokenKind::X:
      size = object_->x_dim;
      return ast::ArrayName{ ast::ArrayKind::X, -1, t.location };
    case TokenKind::A:
      size = object_->a_dim;
      return ast::ArrayName{ ast::ArrayKind::A, -1, t.location };
    case TokenKind::S:
      size = object_->s_dim;
      return ast::ArrayName{ ast::ArrayKind::S, -1, t.location };
    case TokenKind::Identifier:
    {
      const auto found = names_.find(t.text);
      if (found != names_.end() && found->second.kind == NameKind::Array)
      {
        const int index = found->second.index;
        size = object_->arrays[static_cast<std::size_t>(index)].size;
        return ast::ArrayName{ ast::ArrayKind::Local, index, t.location };
      }
      break;
    }
    default:
      break;
  }
  fail(t, "Only array name expected");
}

Parsed Parser::parse_primary()
{
  const Token& t = tok();
  switch (t.kind)
  {
    case TokenKind::Number:
    {
      Parsed out{ make(t.location, ast::NumberExpr{ t.value }), 1 };
      advance();
      return out;
    }
    case TokenKind::LeftParen:
    {
      advance();
      Parsed inner = parse_expression();
      expect(TokenKind::RightParen, "Right parenthes expected");
      advance();
      return inner;
    }
    case TokenKind::X:
      return parse_element(t, ast::ArrayName{ ast::ArrayKind::X, -1, t.location });
    case TokenKind::A:
      return parse_element(t, ast::ArrayName{ ast::ArrayKind::A, -1, t.location });
    case TokenKind::S:
      return parse_element(t, ast::ArrayName{ ast::ArrayKind::S, -1, t.location });
    case TokenKind::Function:
      return parse_call();
    case TokenKind::Identifier:
    {
      const auto found = names_.find(t.text);
      if (found != names_.end())
      {
        if (found->second.kind == NameKind::Array)
        {
          return parse_element(
            t, ast::ArrayName{ ast::ArrayKind::Local, found->second.index, t.location });
        }
        Parsed out{ make(t.location, ast::ScalarExpr{ found->second.index }), 1 };
        advance();
        return out;
      }
      const auto object = object_index_.find(t.text);
      if (object == object_index_.end())
      {
        if (const auto& users = program_->user_functions)
        {
          if (const std::optional<int> user = users->find(t.text))
          {
            return parse_user_call(*user);
          }
          // With user functions in play an unknown call deserves to be named as one.
          if (peek(1).kind == TokenKind::LeftParen)
          {
            fail(t,
              "Unknown function '" + t.text +
                "': not a library function, an earlier object or a registered user function");
          }
        }
        fail(t, "Unassigned identificator used in expression");
      }
      return parse_object_call(object->second);
    }
    default:
      fail(t, "Expression expected");
  }
}

Parsed Parser::parse_call()
{
  const Token& name = tok();
  const FunctionInfo& info = function_info(name.function);
  const SourceLocation where = name.location;
  advance();
  expect(TokenKind::LeftParen, "Left parenthes expected");
  advance();
  ast::CallExpr node;
  node.function = info.id;
  int depth = 1;
  for (int i = 0; i < info.arity; ++i)
  {
    switch (info.kinds[static_cast<std::size_t>(i)])
    {
      case ArgKind::Real:
      {
        Parsed arg = parse_expression();
        depth = std::max(depth, arg.depth + 1);
        node.args.emplace_back(std::move(arg.expr));
        break;
      }
      case ArgKind::String:
        if (kind() != TokenKind::String)
        {
          fail(tok(), "Error in argument in function call");
        }
        node.args.emplace_back(tok().text);
        advance();
        break;
      case ArgKind::Array:
      {
        const TokenKind k = kind();
        if (k != TokenKind::X && k != TokenKind::A && k != TokenKind::S &&
            k != TokenKind::Identifier)
        {
          fail(tok(), "Error in argument in function call");
        }
        int size = 0;
        node.args.emplace_back(array_argument(size));
        advance();
        break;
      }
    }
    if (i + 1 < info.arity)
    {
      expect(TokenKind::Comma, "Comma expected");
      advance();
    }
  }
  expect(TokenKind::RightParen, "Right parenthes expected");
  advance();
  check_depth(depth);
  return Parsed{ make(where, std::move(node)), depth };
}

Parsed Parser::parse_user_call(int index)
{
  const UserFunction& function = program_->user_functions->at(index);
  const std::string signature = user_function_signature(function);
  const SourceLocation where = tok().location;
  advance();
  expect(TokenKind::LeftParen, "Left parenthes expected");
  advance();
  ast::UserCallExpr node;
  node.function = index;
  const int arity = static_cast<int>(function.kinds.size());
  int depth = 1;
  int given = 0;
  const auto wrong_count = [&]
  {
    // Count what was written to say how many were given: `given` parsed, then the rest up
    // to the closing parenthesis (one more than its top-level commas, if anything is there).
    int count = given;
    std::size_t p = pos_;
    if (p < tokens_.size() && tokens_[p].kind == TokenKind::Comma)
    {
      ++p;
    }
    if (p < tokens_.size() && tokens_[p].kind != TokenKind::RightParen)
    {
      ++count;
      int nesting = 0;
      for (; p < tokens_.size() && tokens_[p].kind != TokenKind::End; ++p)
      {
        const TokenKind k = tokens_[p].kind;
        if (k == TokenKind::LeftParen || k == TokenKind::LeftBracket)
        {
          ++nesting;
        }
        else if (k == TokenKind::RightParen || k == TokenKind::RightBracket)
        {
          if (nesting-- == 0)
          {
            break;
          }
        }
        else if (k == TokenKind::Comma && nesting == 0)
        {
          ++count;
        }
      }
    }
    report_message(where,
      "Function " + function.name + " takes " + std::to_string(arity) +
        (arity == 1 ? " argument" : " arguments") + ", " + signature + ", but " +
        std::to_string(count) + " given");
    throw ParseFailure{};
  };
  if (arity == 0 && kind() != TokenKind::RightParen)
  {
    wrong_count();
  }
  for (int i = 0; i < arity; ++i)
  {
    if (kind() == TokenKind::RightParen)
    {
      wrong_count();
    }
    if (function.kinds[static_cast<std::size_t>(i)] == ArgKind::Real)
    {
      Parsed arg = parse_expression();
      depth = std::max(depth, arg.depth + 1);
      node.args.emplace_back(std::move(arg.expr));
    }
    else
    {
      const TokenKind k = kind();
      if (k != TokenKind::X && k != TokenKind::A && k != TokenKind::S && k != TokenKind::Identifier)
      {
        fail(tok(),
          "Argument " + std::to_string(i + 1) + " of " + signature + " must be an array name");
      }
      int size = 0;
      node.args.emplace_back(array_argument(size));
      const int wanted = static_cast<std::size_t>(i) < function.array_sizes.size()
                           ? function.array_sizes[static_cast<std::size_t>(i)]
                           : 0;
      if (wanted > 0 && size != wanted)
      {
        fail(tok(),
          "Argument " + std::to_string(i + 1) + " of " + signature + " must have " +
            std::to_string(wanted) + " items, it has " + std::to_string(size));
      }
      advance();
    }
    given = i + 1;
    if (i + 1 < arity)
    {
      if (kind() == TokenKind::RightParen)
      {
        wrong_count();
      }
      expect(TokenKind::Comma, "Comma expected");
      advance();
    }
  }
  if (kind() == TokenKind::Comma)
  {
    wrong_count();
  }
  expect(TokenKind::RightParen, "Right parenthes expected");
  advance();
  check_depth(depth);
  return Parsed{ make(where, std::move(node)), depth };
}

Parsed Parser::parse_object_call(int callee_index)
{
  const ast::Object& callee = program_->objects[static_cast<std::size_t>(callee_index)];
  const SourceLocation where = tok().location;
  advance();
  expect(TokenKind::LeftParen, "Left parenthes expected");
  advance();

  ast::ObjectCallExpr node;
  node.object = callee_index;
  auto sized_argument = [&](int wanted)
  {
    int size = 0;
    const ast::ArrayName array = array_argument(size);
    if (size != wanted)
    {
      fail(tok(), "Wrong number of items in array");
    }
    advance();
    return array;
  };
  node.x = sized_argument(callee.x_dim);
  expect(TokenKind::Comma, "Comma expected");
  advance();
  node.a = sized_argument(callee.a_dim);
  if (kind() == TokenKind::RightParen)
  {
    // Without a third argument the caller's s is passed as a one-item array.
    if (callee.s_dim != 1)
    {
      fail(tok(), "Wrong number of items in array");
    }
  }
  else
  {
    expect(TokenKind::Comma, "Comma expected");
    advance();
    node.s = sized_argument(callee.s_dim);
    expect(TokenKind::RightParen, "Right parenthes expected");
  }
  node.close_paren = tok().location;
  advance();
  return Parsed{ make(where, std::move(node)), 1 };
}

} // namespace frep::parsing
