#include "Language/detail/lexer.h"

#include "Language/detail/number_literal.h"

#include <array>
#include <utility>

namespace frep
{
namespace
{

// The original's MAX_LENGTH_OF_STRING: comments may hold this many characters after "--";
// identifiers and strings must stay below it (its buffer also holds the terminating NUL).
constexpr std::size_t kMaxLexemLength = 256;

bool is_alpha(char c)
{
  // The original calls isalpha on (signed) char in the C locale: bytes >= 0x80 are not letters.
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

bool is_digit(char c)
{
  return c >= '0' && c <= '9';
}

char to_lower(char c)
{
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

struct ReservedWord
{
  std::string_view spelling;
  TokenKind kind;
};

constexpr std::array<ReservedWord, 15> kReserved = { {
  { "a", TokenKind::A },
  { "s", TokenKind::S },
  { "x", TokenKind::X },
  { "and", TokenKind::And },
  { "or", TokenKind::Or },
  { "not", TokenKind::Not },
  { "xor", TokenKind::Xor },
  { "array", TokenKind::Array },
  { "if", TokenKind::If },
  { "then", TokenKind::Then },
  { "else", TokenKind::Else },
  { "endif", TokenKind::EndIf },
  { "while", TokenKind::While },
  { "loop", TokenKind::Loop },
  { "endloop", TokenKind::EndLoop },
} };

} // namespace

const char* token_kind_name(TokenKind kind)
{
  switch (kind)
  {
    case TokenKind::Illegal:
      return "illegal token";
    case TokenKind::End:
      return "end of file";
    case TokenKind::Array:
      return "\"array\"";
    case TokenKind::If:
      return "\"if\"";
    case TokenKind::Then:
      return "\"then\"";
    case TokenKind::Else:
      return "\"else\"";
    case TokenKind::EndIf:
      return "\"endif\"";
    case TokenKind::While:
      return "\"while\"";
    case TokenKind::Loop:
      return "\"loop\"";
    case TokenKind::EndLoop:
      return "\"endloop\"";
    case TokenKind::And:
      return "\"and\"";
    case TokenKind::Or:
      return "\"or\"";
    case TokenKind::Not:
      return "\"not\"";
    case TokenKind::Xor:
      return "\"xor\"";
    case TokenKind::X:
      return "\"x\"";
    case TokenKind::A:
      return "\"a\"";
    case TokenKind::S:
      return "\"s\"";
    case TokenKind::Assign:
      return "\"=\"";
    case TokenKind::NotEqual:
      return "\"/=\"";
    case TokenKind::Less:
      return "\"<\"";
    case TokenKind::LessEqual:
      return "\"<=\"";
    case TokenKind::Greater:
      return "\">\"";
    case TokenKind::GreaterEqual:
      return "\">=\"";
    case TokenKind::LeftParen:
      return "\"(\"";
    case TokenKind::RightParen:
      return "\")\"";
    case TokenKind::LeftBracket:
      return "\"[\"";
    case TokenKind::RightBracket:
      return "\"]\"";
    case TokenKind::LeftBrace:
      return "\"{\"";
    case TokenKind::RightBrace:
      return "\"}\"";
    case TokenKind::Power:
      return "\"^\"";
    case TokenKind::Plus:
      return "\"+\"";
    case TokenKind::Minus:
      return "\"-\"";
    case TokenKind::Tilde:
      return "\"~\"";
    case TokenKind::Slash:
      return "\"/\"";
    case TokenKind::Star:
      return "\"*\"";
    case TokenKind::Ampersand:
      return "\"&\"";
    case TokenKind::Bar:
      return "\"|\"";
    case TokenKind::Backslash:
      return "\"\\\"";
    case TokenKind::At:
      return "\"@\"";
    case TokenKind::Comma:
      return "\",\"";
    case TokenKind::Semicolon:
      return "\";\"";
    case TokenKind::Number:
      return "number";
    case TokenKind::String:
      return "string";
    case TokenKind::Function:
      return "function name";
    case TokenKind::Identifier:
      return "identifier";
  }
  return "token";
}

Lexer::Lexer(std::string_view text, LexerOptions options)
  : text_(text)
  , options_(options)
{
}

char Lexer::peek(std::size_t ahead) const
{
  // Past the end reads as NUL, like the original's ASCIIZ program string.
  return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
}

void Lexer::advance(std::size_t count)
{
  for (std::size_t k = 0; k < count && pos_ < text_.size(); ++k)
  {
    if (text_[pos_] == '\n')
    {
      ++line_;
      column_ = 1;
    }
    else
    {
      ++column_;
    }
    ++pos_;
  }
}

void Lexer::skip_whitespace()
{
  for (;;)
  {
    const char c = peek();
    if (c == ' ' || c == '\n' || c == '\t' || (c == '\r' && options_.accept_carriage_return))
    {
      advance();
    }
    else
    {
      return;
    }
  }
}

Token Lexer::next()
{
  for (;;)
  {
    bool is_comment = false;
    Token token = next_raw(is_comment);
    if (!is_comment)
    {
      return token;
    }
  }
}

/// A "--" comment to the end of the line (is_comment set), or an over-long one (Illegal).
Token Lexer::scan_comment(Token token, bool& is_comment)
{
  advance(2);
  std::size_t count = 0;
  while (peek() != '\n' && peek() != '\0')
  {
    // With CR accepted, the CR of a CRLF line end is not part of the comment's length.
    const bool line_end_cr =
      peek() == '\r' && peek(1) == '\n' && options_.accept_carriage_return;
    if (!line_end_cr && count >= kMaxLexemLength)
    {
      // The original stops reading after 256 characters and rejects the token; skip the
      // rest of the line so the next token starts on the next line.
      while (peek() != '\n' && peek() != '\0')
      {
        advance();
      }
      token.kind = TokenKind::Illegal;
      token.error = LexError::LongComment;
      token.length = pos_ - token.offset;
      return token;
    }
    if (!line_end_cr)
    {
      ++count;
    }
    advance();
  }
  is_comment = true;
  token.kind = TokenKind::End;
  return token;
}

/// A "..." string on one line, or an unterminated one (Illegal).
Token Lexer::scan_string(Token token)
{
  advance();
  std::string contents;
  while (
    peek() != '"' && peek() != '\0' && peek() != '\n' && contents.size() < kMaxLexemLength - 1)
  {
    contents.push_back(peek());
    advance();
  }
  if (peek() != '"')
  {
    token.kind = TokenKind::Illegal;
    token.error = LexError::UnterminatedString;
    token.length = pos_ - token.offset;
    return token;
  }
  advance();
  token.kind = TokenKind::String;
  token.text = std::move(contents);
  token.length = pos_ - token.offset;
  return token;
}

/// A number literal (the original's forms), or a malformed one (Illegal).
Token Lexer::scan_number(Token token)
{
  const NumberLiteral literal = scan_number_literal(text_, pos_);
  advance(literal.length);
  token.length = literal.length;
  if (literal.ok)
  {
    token.kind = TokenKind::Number;
    token.value = literal.value;
  }
  else
  {
    token.kind = TokenKind::Illegal;
    token.error = LexError::BadNumber;
  }
  return token;
}

/// A name, lower-cased: a reserved word, a library function or an identifier; an over-long one
/// is Illegal.
Token Lexer::scan_word(Token token)
{
  std::string name;
  while (is_alpha(peek()) || is_digit(peek()) || peek() == '_')
  {
    name.push_back(to_lower(peek()));
    advance();
  }
  token.length = name.size();
  token.text = name;
  // The original's buffer holds 255 characters plus the terminator; 256 overflows it (undefined
  // behaviour there), longer is rejected: refuse both.
  if (name.size() >= kMaxLexemLength)
  {
    token.kind = TokenKind::Illegal;
    token.error = LexError::LongIdentifier;
    return token;
  }
  for (const ReservedWord& word : kReserved)
  {
    if (word.spelling == name)
    {
      token.kind = word.kind;
      return token;
    }
  }
  if (const std::optional<FunctionId> function = find_function(name))
  {
    token.kind = TokenKind::Function;
    token.function = *function;
    return token;
  }
  token.kind = TokenKind::Identifier;
  return token;
}

Token Lexer::next_raw(bool& is_comment)
{
  skip_whitespace();
  Token token;
  token.location = SourceLocation{ line_, column_ };
  token.offset = pos_;
  const char c = peek();

  auto simple = [&](TokenKind kind, std::size_t length)
  {
    advance(length);
    token.kind = kind;
    token.length = length;
    return token;
  };

  switch (c)
  {
    case '\0':
      // A NUL byte ends the program as it ends the original's C string.
      token.kind = TokenKind::End;
      return token;
    case '^':
      return simple(TokenKind::Power, 1);
    case '+':
      return simple(TokenKind::Plus, 1);
    case '~':
      return simple(TokenKind::Tilde, 1);
    case '*':
      return simple(TokenKind::Star, 1);
    case '&':
      return simple(TokenKind::Ampersand, 1);
    case '|':
      return simple(TokenKind::Bar, 1);
    case '\\':
      return simple(TokenKind::Backslash, 1);
    case '@':
      return simple(TokenKind::At, 1);
    case ',':
      return simple(TokenKind::Comma, 1);
    case ';':
      return simple(TokenKind::Semicolon, 1);
    case '=':
      return simple(TokenKind::Assign, 1);
    case '(':
      return simple(TokenKind::LeftParen, 1);
    case ')':
      return simple(TokenKind::RightParen, 1);
    case '[':
      return simple(TokenKind::LeftBracket, 1);
    case ']':
      return simple(TokenKind::RightBracket, 1);
    case '{':
      return simple(TokenKind::LeftBrace, 1);
    case '}':
      return simple(TokenKind::RightBrace, 1);
    case '/':
      return peek(1) == '=' ? simple(TokenKind::NotEqual, 2) : simple(TokenKind::Slash, 1);
    case '<':
      return peek(1) == '=' ? simple(TokenKind::LessEqual, 2) : simple(TokenKind::Less, 1);
    case '>':
      return peek(1) == '=' ? simple(TokenKind::GreaterEqual, 2) : simple(TokenKind::Greater, 1);
    case '-':
      if (peek(1) != '-')
      {
        return simple(TokenKind::Minus, 1);
      }
      return scan_comment(std::move(token), is_comment);
    case '"':
      return scan_string(std::move(token));
    default:
      break;
  }

  if (is_digit(c) || c == '.')
  {
    return scan_number(std::move(token));
  }
  if (is_alpha(c))
  {
    return scan_word(std::move(token));
  }

  // Any other byte (including CR when not accepted, form feed, '#', '!', bytes >= 0x80).
  advance();
  token.kind = TokenKind::Illegal;
  token.error = LexError::UnknownCharacter;
  token.length = 1;
  return token;
}

std::vector<Token> tokenize(std::string_view text, LexerOptions options)
{
  Lexer lexer(text, options);
  std::vector<Token> tokens;
  for (;;)
  {
    tokens.push_back(lexer.next());
    if (tokens.back().kind == TokenKind::End)
    {
      return tokens;
    }
  }
}

} // namespace frep
