// The Parser's statements and conditions (detail/parser_class.h).
#include "Language/detail/parser_class.h"

#include <algorithm>
#include <utility>

namespace frep::parsing
{

void Parser::parse_statements(ast::Block& block)
{
  for (;;)
  {
    const TokenKind k = kind();
    const bool starts_statement = k == TokenKind::If || k == TokenKind::While ||
                                  k == TokenKind::S ||
                                  (k == TokenKind::Identifier && tok().text != object_->name);
    if (!starts_statement)
    {
      return;
    }
    try
    {
      Nest nest(*this);
      block.push_back(parse_statement());
    }
    catch (const ParseFailure&)
    {
      recover_statement();
    }
  }
}

ast::Stmt Parser::parse_statement()
{
  ast::Stmt stmt;
  stmt.location = tok().location;
  switch (kind())
  {
    case TokenKind::If:
      stmt.node = parse_if();
      break;
    case TokenKind::While:
      stmt.node = parse_while();
      break;
    case TokenKind::S:
      parse_s_statement(stmt);
      break;
    default:
      parse_identifier_statement(stmt);
      break;
  }
  return stmt;
}

ast::IfStmt Parser::parse_if()
{
  ast::IfStmt node;
  advance();
  node.condition = parse_condition().expr;
  expect(TokenKind::Then, "Reserved word \"then\" expected");
  advance();
  ++block_depth_;
  struct Leave
  {
    int& depth;
    ~Leave() { --depth; }
  } leave{ block_depth_ };
  parse_statements(node.then_block);
  if (kind() == TokenKind::Else)
  {
    advance();
    parse_statements(node.else_block);
    expect(TokenKind::EndIf, "Reserved word \"endif\" expected");
  }
  else
  {
    expect(TokenKind::EndIf, "Reserved words \"else\" or \"endif\" expected");
  }
  advance();
  expect(TokenKind::Semicolon, "Semicolon expected");
  advance();
  return node;
}

ast::WhileStmt Parser::parse_while()
{
  ast::WhileStmt node;
  advance();
  node.condition = parse_condition().expr;
  expect(TokenKind::Loop, "Reserved word \"loop\" expected");
  advance();
  ++block_depth_;
  struct Leave
  {
    int& depth;
    ~Leave() { --depth; }
  } leave{ block_depth_ };
  parse_statements(node.body);
  expect(TokenKind::EndLoop, "Reserved word \"endloop\" expected");
  advance();
  expect(TokenKind::Semicolon, "Semicolon expected");
  advance();
  return node;
}

void Parser::parse_element_assignment(ast::Stmt& stmt, ast::ArrayName array)
{
  advance(); // '['
  ast::AssignElement node;
  node.array = array;
  node.index_end = tok().location; // the first token of the index: see ast.h
  node.index = parse_expression().expr;
  expect(TokenKind::RightBracket, "Right bracket expected");
  advance();
  expect(TokenKind::Assign, "Assign mark expected");
  advance();
  node.value = parse_expression().expr;
  expect(TokenKind::Semicolon, "Semicolon expected");
  advance();
  stmt.node = std::move(node);
}

void Parser::parse_array_literal(ast::Stmt& stmt, ast::ArrayName array, int count)
{
  expect(TokenKind::LeftBracket, "Left bracket expected");
  if (count < 1)
  {
    // s[0] in the header: the original would store one value into no cell.
    fail(tok(), "Wrong number of items in array");
  }
  ast::AssignArray node;
  node.array = array;
  for (int i = 0; i < count; ++i)
  {
    if (i > 0)
    {
      expect(TokenKind::Comma, "Comma expected");
    }
    advance(); // '[' or ','
    double sign = 1.0;
    if (kind() == TokenKind::Minus)
    {
      sign = -1.0;
      advance();
    }
    else if (kind() == TokenKind::Plus)
    {
      advance();
    }
    expect(TokenKind::Number, "Real number expected");
    node.values.push_back(tok().value * sign);
    advance();
  }
  expect(TokenKind::RightBracket, "Right bracket expected");
  advance();
  expect(TokenKind::Semicolon, "Semicolon expected");
  advance();
  stmt.node = std::move(node);
}

void Parser::parse_s_statement(ast::Stmt& stmt)
{
  const ast::ArrayName array{ ast::ArrayKind::S, -1, tok().location };
  advance();
  if (kind() == TokenKind::LeftBracket)
  {
    parse_element_assignment(stmt, array);
  }
  else if (kind() == TokenKind::Assign)
  {
    advance();
    parse_array_literal(stmt, array, object_->s_dim);
  }
  else
  {
    fail(tok(), "Left bracket or assign mark expected");
  }
}

void Parser::parse_identifier_statement(ast::Stmt& stmt)
{
  const std::string name = tok().text;
  const auto found = names_.find(name);
  if (found != names_.end() && found->second.kind == NameKind::Array)
  {
    const int index = found->second.index;
    const ast::ArrayName array{ ast::ArrayKind::Local, index, tok().location };
    advance();
    if (kind() == TokenKind::LeftBracket)
    {
      parse_element_assignment(stmt, array);
    }
    else if (kind() == TokenKind::Assign)
    {
      advance();
      parse_array_literal(stmt, array, object_->arrays[static_cast<std::size_t>(index)].size);
    }
    else
    {
      fail(tok(), "Left bracket or assign mark expected");
    }
    return;
  }

  // A scalar exists from its first assignment in the text, declared before its value is
  // parsed (so `q = q + 1;` as the first assignment is accepted, failing at run time).
  int scalar = 0;
  if (found == names_.end())
  {
    scalar = static_cast<int>(object_->scalars.size());
    object_->scalars.push_back(name);
    names_.emplace(name, LocalName{ NameKind::Scalar, scalar });
  }
  else
  {
    scalar = found->second.index;
  }
  advance();
  expect(TokenKind::Assign, "Assign mark expected");
  advance();
  ast::AssignScalar node;
  node.scalar = scalar;
  node.value = parse_expression().expr;
  expect(TokenKind::Semicolon, "Semicolon expected");
  advance();
  stmt.node = std::move(node);
}

Parsed Parser::parse_condition()
{
  Nest nest(*this);
  Parsed lhs = parse_comparison();
  while (kind() == TokenKind::And || kind() == TokenKind::Or)
  {
    const ast::LogicOp op = kind() == TokenKind::And ? ast::LogicOp::And : ast::LogicOp::Or;
    const SourceLocation where = tok().location;
    advance();
    Parsed rhs = parse_comparison();
    const int depth = 1 + std::max(lhs.depth, rhs.depth);
    check_depth(depth);
    lhs.expr = make(where, ast::LogicExpr{ op, std::move(lhs.expr), std::move(rhs.expr) });
    lhs.depth = depth;
  }
  return lhs;
}

bool Parser::comparison_op(TokenKind k, ast::CompareOp& op)
{
  switch (k)
  {
    case TokenKind::Assign:
      op = ast::CompareOp::Eq;
      return true;
    case TokenKind::NotEqual:
      op = ast::CompareOp::Ne;
      return true;
    case TokenKind::Less:
      op = ast::CompareOp::Lt;
      return true;
    case TokenKind::LessEqual:
      op = ast::CompareOp::Le;
      return true;
    case TokenKind::Greater:
      op = ast::CompareOp::Gt;
      return true;
    case TokenKind::GreaterEqual:
      op = ast::CompareOp::Ge;
      return true;
    default:
      return false;
  }
}

Parsed Parser::parse_comparison()
{
  Parsed lhs = parse_bool_factor();
  ast::CompareOp op{};
  while (comparison_op(kind(), op))
  {
    const SourceLocation where = tok().location;
    advance();
    Parsed rhs = parse_bool_factor();
    const int depth = 1 + std::max(lhs.depth, rhs.depth);
    check_depth(depth);
    lhs.expr = make(where, ast::CompareExpr{ op, std::move(lhs.expr), std::move(rhs.expr) });
    lhs.depth = depth;
  }
  return lhs;
}

Parsed Parser::parse_bool_factor()
{
  Nest nest(*this);
  if (kind() == TokenKind::Not)
  {
    const SourceLocation where = tok().location;
    advance();
    Parsed operand = parse_bool_factor();
    check_depth(operand.depth + 1);
    return Parsed{ make(where, ast::NotExpr{ std::move(operand.expr) }), operand.depth + 1 };
  }
  if (kind() == TokenKind::LeftParen)
  {
    advance();
    Parsed inner = parse_condition();
    expect(TokenKind::RightParen, "Right parenthes expected");
    advance();
    return inner;
  }
  return parse_expression();
}

} // namespace frep::parsing
