// Tokens of the HyperFun scanner (the original's general.h token codes, minus comments, which
// the lexer drops like HF_get_token does).
#pragma once

#include "Language/function_table.h"
#include "Language/source_location.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace frep
{

enum class TokenKind : std::uint8_t
{
  Illegal, ///< a lexical error; Token::error says which (the parser reports what it expected)
  End,     ///< end of text (or a NUL byte, where the original's C string ends)
  // reserved words
  Array,
  If,
  Then,
  Else,
  EndIf,
  While,
  Loop,
  EndLoop,
  And,
  Or,
  Not,
  Xor,
  X,
  A,
  S, ///< the reserved array names x, a, s
  // punctuation and operators
  Assign,   ///< =  (assignment and equality)
  NotEqual, ///< /=
  Less,
  LessEqual,
  Greater,
  GreaterEqual,
  LeftParen,
  RightParen,
  LeftBracket,
  RightBracket,
  LeftBrace,
  RightBrace,
  Power,
  Plus,
  Minus,
  Tilde,
  Slash,
  Star,
  Ampersand, ///< &
  Bar,       ///< |
  Backslash, ///< '\'
  At,        ///< @
  Comma,
  Semicolon,
  // with a payload
  Number,    ///< value in Token::value
  String,    ///< contents in Token::text
  Function,  ///< builtin or library function name; id in Token::function
  Identifier ///< lower-cased name in Token::text
};

/// Why a token is Illegal.
enum class LexError : std::uint8_t
{
  None,
  UnknownCharacter,  ///< a byte no token starts with (also CR when it is not accepted)
  BadNumber,         ///< 05, 1e0, 1e, lone '.', ...
  LongIdentifier,    ///< more than 255 characters
  LongComment,       ///< more than 256 characters after "--"
  UnterminatedString ///< no closing '"' on the line, or longer than 255 characters
};

struct Token
{
  TokenKind kind = TokenKind::End;
  SourceLocation location;                ///< first byte of the token
  std::size_t offset = 0;                 ///< byte offset of the first byte
  std::size_t length = 0;                 ///< bytes consumed (for messages)
  std::string text;                       ///< identifier (lower-case) / string contents
  double value = 0;                       ///< Number: the value the original's scanner computes
  FunctionId function = FunctionId::Sqrt; ///< Function
  LexError error = LexError::None;        ///< Illegal
};

/// Human-readable spelling of a token kind for messages ("\"then\"", "';'", "number", ...).
const char* token_kind_name(TokenKind kind);

} // namespace frep
