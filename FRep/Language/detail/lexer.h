// The HyperFun lexer: the original's int_scanner.c token rules, with FRepKit's optional
// acceptance of CR as whitespace. The scanner is context-free, so the whole text is tokenized
// up front; the parser then has free lookahead.
#pragma once

#include "Language/detail/token.h"

#include <string_view>
#include <vector>

namespace frep
{

struct LexerOptions
{
  /// CR counts as whitespace (one column); false makes it an unknown character, as the original.
  bool accept_carriage_return = true;
};

class Lexer
{
public:
  explicit Lexer(std::string_view text, LexerOptions options = {});

  /// The next token; comments are skipped. Returns End forever at the end of the text.
  Token next();

private:
  std::string_view text_;
  LexerOptions options_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;

  char peek(std::size_t ahead = 0) const;
  void advance(std::size_t count = 1);
  void skip_whitespace();
  Token next_raw(bool& is_comment);
  // The longer tokens of next_raw, each from its first character on (`token` has its position).
  Token scan_comment(Token token, bool& is_comment);
  Token scan_string(Token token);
  Token scan_number(Token token);
  Token scan_word(Token token);
};

/// Tokenizes the whole text; the last token is always End.
std::vector<Token> tokenize(std::string_view text, LexerOptions options = {});

} // namespace frep
