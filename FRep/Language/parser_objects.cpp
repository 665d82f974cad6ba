// The Parser's file, objects, headers, bodies and array declarations (detail/parser_class.h).
#include "Language/detail/parser_class.h"

#include "Language/detail/number_literal.h"

#include <string>
#include <utility>

namespace frep::parsing
{

void Parser::parse_file()
{
  while (kind() != TokenKind::End)
  {
    if (kind() != TokenKind::Identifier)
    {
      report(tok(), "Body name expected");
      skip_to_next_object();
      continue;
    }
    parse_object();
  }
}

void Parser::skip_to_next_object()
{
  advance();
  while (kind() != TokenKind::End && !at_object_header())
  {
    advance();
  }
}

void Parser::parse_object()
{
  ast::Object object;
  object.name = tok().text;
  object.file = file_;
  object.location = tok().location;
  object_errors_ = diagnostics_.size();
  const auto earlier = object_index_.find(object.name);
  const bool unique = earlier == object_index_.end();
  if (!unique)
  {
    const ast::Object& other = program_->objects[static_cast<std::size_t>(earlier->second)];
    report(tok(),
      other.file == file_ ? std::string("Body name is not unique")
                          : "Body name is not unique (library file " + other.file +
                              " defines it at line " + std::to_string(other.location.line) + ")");
  }

  try
  {
    parse_header(object);
  }
  catch (const ParseFailure&)
  {
    skip_object_after_header_error();
    return;
  }

  parse_body(object);
  if (unique)
  {
    object_index_.emplace(object.name, static_cast<int>(program_->objects.size()));
    program_->objects.push_back(std::move(object));
  }
}

void Parser::skip_object_after_header_error()
{
  while (kind() != TokenKind::End && kind() != TokenKind::LeftBrace && !at_object_header())
  {
    advance();
  }
  if (kind() != TokenKind::LeftBrace)
  {
    return;
  }
  advance();
  skip_to_object_end();
}

void Parser::skip_to_object_end()
{
  while (kind() != TokenKind::End && kind() != TokenKind::RightBrace && !at_object_header())
  {
    advance();
  }
  if (kind() == TokenKind::RightBrace)
  {
    advance();
  }
}

int Parser::header_size()
{
  expect(TokenKind::Number, "Real number expected");
  const double value = tok().value;
  if (!(value <= kMaxArraySize))
  {
    fail(tok(), "Array size too large: at most 1000000 items are supported");
  }
  return hf_round_size(value);
}

void Parser::parse_header(ast::Object& object)
{
  advance(); // the name
  expect(TokenKind::LeftParen, "Left parenthes expected");
  advance();
  expect(TokenKind::X, "\"X\" expected");
  advance();
  expect(TokenKind::LeftBracket, "Left bracket expected");
  advance();
  object.x_dim = header_size();
  advance();
  expect(TokenKind::RightBracket, "Right bracket expected");
  advance();
  expect(TokenKind::Comma, "Comma expected");
  advance();
  expect(TokenKind::A, "\"A\" expected");
  advance();
  expect(TokenKind::LeftBracket, "Left bracket expected");
  advance();
  object.a_dim = header_size();
  advance();
  expect(TokenKind::RightBracket, "Right bracket expected");
  advance();
  if (kind() == TokenKind::RightParen)
  {
    object.s_dim = 1; // no s[..]: the original acts as if s[1] were declared
  }
  else
  {
    object.s_declared = true;
    expect(TokenKind::Comma, "Comma expected");
    advance();
    expect(TokenKind::S, "\"S\" expected");
    advance();
    expect(TokenKind::LeftBracket, "Left bracket expected");
    advance();
    object.s_dim = header_size();
    advance();
    expect(TokenKind::RightBracket, "Right bracket expected");
    advance();
    expect(TokenKind::RightParen, "Right parenthes expected");
  }
  advance();
  expect(TokenKind::LeftBrace, "Left brace expected");
  advance();
}

void Parser::parse_body(ast::Object& object)
{
  object_ = &object;
  names_.clear();
  local_items_ = 0;
  block_depth_ = 0;
  nesting_ = 0;

  while (kind() == TokenKind::Array)
  {
    try
    {
      parse_array_declaration();
    }
    catch (const ParseFailure&)
    {
      recover_statement();
    }
  }

  for (;;)
  {
    parse_statements(object.body);
    if (kind() == TokenKind::Identifier && tok().text == object.name)
    {
      parse_final_assignment(object);
      break;
    }
    if (kind() == TokenKind::End || kind() == TokenKind::RightBrace || at_object_header())
    {
      report(tok(), "Body name expected");
      if (kind() == TokenKind::RightBrace)
      {
        advance();
      }
      break;
    }
    // A token that cannot start a statement. After an earlier error, stray block keywords are
    // leftovers of a statement already reported.
    const bool leftover =
      object_has_errors() &&
      (kind() == TokenKind::Else || kind() == TokenKind::EndIf || kind() == TokenKind::EndLoop ||
        kind() == TokenKind::Then || kind() == TokenKind::Loop);
    if (!leftover)
    {
      report(tok(), "Body name expected");
    }
    advance();
    recover_statement();
  }
  object_ = nullptr;
}

void Parser::parse_final_assignment(ast::Object& object)
{
  try
  {
    object.result_location = tok().location;
    advance();
    expect(TokenKind::Assign, "Assign mark expected");
    advance();
    object.result = parse_expression().expr;
    expect(TokenKind::Semicolon, "Semicolon expected");
    advance();
    expect(TokenKind::RightBrace, "Right brace expected");
    advance();
  }
  catch (const ParseFailure&)
  {
    skip_to_object_end();
  }
}

void Parser::recover_statement()
{
  for (;;)
  {
    switch (kind())
    {
      case TokenKind::Semicolon:
        advance();
        return;
      case TokenKind::End:
      case TokenKind::RightBrace:
        return;
      case TokenKind::Else:
      case TokenKind::EndIf:
      case TokenKind::EndLoop:
        if (block_depth_ > 0)
        {
          return;
        }
        break;
      default:
        if (at_object_header())
        {
          return;
        }
        break;
    }
    advance();
  }
}

void Parser::parse_array_declaration()
{
  do
  {
    advance(); // "array" or ','
    expect(TokenKind::Identifier, "Identifier expected");
    ast::LocalArray array;
    array.name = tok().text;
    array.location = tok().location;
    advance();
    expect(TokenKind::LeftBracket, "Left bracket expected");
    advance();
    expect(TokenKind::Number, "Real number expected");
    const double value = tok().value;
    if (!(value <= kMaxArraySize))
    {
      fail(tok(), "Array size too large: at most 1000000 items are supported");
    }
    array.size = hf_round_size(value);
    if (array.size < 1)
    {
      fail(tok(), "Array size must be greater zero");
    }
    if (local_items_ + array.size > kMaxLocalItems)
    {
      fail(tok(), "Local arrays too large: at most 10000000 items in all are supported");
    }
    advance();
    expect(TokenKind::RightBracket, "Right bracket expected");
    local_items_ += array.size;
    // Duplicate names are accepted like in the original; lookups find the first.
    const int index = static_cast<int>(object_->arrays.size());
    names_.emplace(array.name, LocalName{ NameKind::Array, index });
    object_->arrays.push_back(std::move(array));
    advance();
  } while (kind() == TokenKind::Comma);
  expect(TokenKind::Semicolon, "Semicolon expected");
  advance();
}

} // namespace frep::parsing
