// The Parser's tokens and diagnostics (detail/parser_class.h).
#include "Language/detail/parser_class.h"

#include <cstdio>
#include <string>

namespace frep::parsing
{

std::string printable(std::string_view text)
{
  std::string out;
  for (const char c : text)
  {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f && c != '"' && c != '\\')
    {
      out.push_back(c);
    }
    else
    {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02x", u);
      out += buffer;
    }
  }
  return out;
}

std::string Parser::describe(const Token& t) const
{
  const std::string_view source =
    text_.substr(std::min(t.offset, text_.size()), std::min<std::size_t>(t.length, 40));
  switch (t.kind)
  {
    case TokenKind::End:
      return "end of file";
    case TokenKind::Identifier:
      return "\"" + t.text + "\"";
    case TokenKind::Function:
      return "function name \"" + t.text + "\"";
    case TokenKind::Number:
      return "number \"" + printable(source) + "\"";
    case TokenKind::String:
      return "string \"" + printable(t.text) + "\"";
    case TokenKind::Illegal:
      switch (t.error)
      {
        case LexError::UnknownCharacter:
          return "unknown character \"" + printable(source) + "\"";
        case LexError::BadNumber:
          return "malformed number \"" + printable(source) + "\"";
        case LexError::LongIdentifier:
          return "identifier longer than 255 characters";
        case LexError::LongComment:
          return "comment longer than 256 characters";
        case LexError::UnterminatedString:
          return "unterminated string";
        case LexError::None:
          break;
      }
      return "illegal token";
    default:
      return token_kind_name(t.kind);
  }
}

void Parser::report_message(SourceLocation where, std::string message)
{
  diagnostics_.push_back(Diagnostic{ file_, where, std::move(message) });
  if (diagnostics_.size() >= kMaxDiagnostics)
  {
    throw TooManyErrors{};
  }
}

void Parser::expect(TokenKind wanted, std::string_view message)
{
  if (kind() != wanted)
  {
    fail(tok(), message);
  }
}

void Parser::fail_too_deep()
{
  report_message(tok().location,
    "Nesting too deep: more than " + std::to_string(max_depth_) +
      " levels of expressions, conditions or statements");
  throw ParseFailure{};
}

void Parser::check_depth(int depth)
{
  if (depth > max_depth_)
  {
    fail_too_deep();
  }
}

} // namespace frep::parsing
