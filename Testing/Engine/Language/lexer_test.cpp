// Lexer: token kinds, positions, case folding, reserved words, limits, CR handling.
#include "Language/detail/lexer.h"

#include <gtest/gtest.h>

#include <string>

namespace frep
{
namespace
{

std::vector<TokenKind> kinds(std::string_view text, LexerOptions options = {})
{
  std::vector<TokenKind> out;
  for (const Token& t : tokenize(text, options))
  {
    out.push_back(t.kind);
  }
  return out;
}

TEST(Lexer, OperatorsAndPunctuation)
{
  using K = TokenKind;
  EXPECT_EQ(kinds("+ - * / ^ ~ | & \\ @ = /= < <= > >= ( ) [ ] { } , ;"),
    (std::vector<K>{ K::Plus,
      K::Minus,
      K::Star,
      K::Slash,
      K::Power,
      K::Tilde,
      K::Bar,
      K::Ampersand,
      K::Backslash,
      K::At,
      K::Assign,
      K::NotEqual,
      K::Less,
      K::LessEqual,
      K::Greater,
      K::GreaterEqual,
      K::LeftParen,
      K::RightParen,
      K::LeftBracket,
      K::RightBracket,
      K::LeftBrace,
      K::RightBrace,
      K::Comma,
      K::Semicolon,
      K::End }));
}

TEST(Lexer, ReservedWordsAndIdentifiersAreCaseInsensitive)
{
  const auto tokens = tokenize("IF Then ELSE endIF While LOOP EndLoop AND or NOT xor ARRAY X a S "
                               "MyVar hfSPHERE Sqrt");
  using K = TokenKind;
  const std::vector<K> expected{ K::If,
    K::Then,
    K::Else,
    K::EndIf,
    K::While,
    K::Loop,
    K::EndLoop,
    K::And,
    K::Or,
    K::Not,
    K::Xor,
    K::Array,
    K::X,
    K::A,
    K::S,
    K::Identifier,
    K::Function,
    K::Function,
    K::End };
  ASSERT_EQ(tokens.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
  {
    EXPECT_EQ(tokens[i].kind, expected[i]) << i;
  }
  EXPECT_EQ(tokens[15].text, "myvar");
  EXPECT_EQ(tokens[16].function, FunctionId::Sphere);
  EXPECT_EQ(tokens[17].function, FunctionId::Sqrt);
}

TEST(Lexer, LinesAndColumns)
{
  const auto tokens = tokenize("ab\n\t cd -- comment\n  +");
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[0].location, (SourceLocation{ 1, 1 }));
  EXPECT_EQ(tokens[1].location, (SourceLocation{ 2, 3 })); // TAB counts one column
  EXPECT_EQ(tokens[2].location, (SourceLocation{ 3, 3 }));
  EXPECT_EQ(tokens[3].kind, TokenKind::End);
  EXPECT_EQ(tokens[3].location, (SourceLocation{ 3, 4 }));
}

TEST(Lexer, DoubleMinusStartsAComment)
{
  using K = TokenKind;
  EXPECT_EQ(kinds("3--2\n4"), (std::vector<K>{ K::Number, K::Number, K::End }));
  EXPECT_EQ(kinds("3 - -2"), (std::vector<K>{ K::Number, K::Minus, K::Minus, K::Number, K::End }));
}

TEST(Lexer, CommentLengthLimit)
{
  const std::string ok = "--" + std::string(256, 'c') + "\nq";
  EXPECT_EQ(kinds(ok), (std::vector<TokenKind>{ TokenKind::Identifier, TokenKind::End }));
  const std::string too_long = "--" + std::string(257, 'c') + "\nq";
  const auto tokens = tokenize(too_long);
  ASSERT_GE(tokens.size(), 1u);
  EXPECT_EQ(tokens[0].kind, TokenKind::Illegal);
  EXPECT_EQ(tokens[0].error, LexError::LongComment);
  EXPECT_EQ(tokens[0].location, (SourceLocation{ 1, 1 }));
}

TEST(Lexer, IdentifierLengthLimit)
{
  const auto ok = tokenize("q" + std::string(254, 'z'));
  EXPECT_EQ(ok[0].kind, TokenKind::Identifier);
  EXPECT_EQ(ok[0].text.size(), 255u);
  const auto too_long = tokenize("q" + std::string(256, 'z') + " +");
  EXPECT_EQ(too_long[0].kind, TokenKind::Illegal);
  EXPECT_EQ(too_long[0].error, LexError::LongIdentifier);
  EXPECT_EQ(too_long[1].kind, TokenKind::Plus);
}

TEST(Lexer, IdentifierForms)
{
  const auto tokens = tokenize("a_1 _b 9z");
  EXPECT_EQ(tokens[0].kind, TokenKind::Identifier);
  EXPECT_EQ(tokens[0].text, "a_1");
  EXPECT_EQ(tokens[1].kind, TokenKind::Illegal); // identifiers start with a letter
  EXPECT_EQ(tokens[2].kind, TokenKind::Identifier);
  EXPECT_EQ(tokens[3].kind, TokenKind::Number); // "9z" is a number then a name
  EXPECT_EQ(tokens[4].kind, TokenKind::Identifier);
}

TEST(Lexer, CarriageReturn)
{
  using K = TokenKind;
  EXPECT_EQ(kinds("q\r\n;"), (std::vector<K>{ K::Identifier, K::Semicolon, K::End }));
  LexerOptions strict;
  strict.accept_carriage_return = false;
  const auto tokens = tokenize("q\r\n;", strict);
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[1].kind, K::Illegal);
  EXPECT_EQ(tokens[1].error, LexError::UnknownCharacter);
  EXPECT_EQ(tokens[1].location, (SourceLocation{ 1, 2 }));
  EXPECT_EQ(tokens[2].location, (SourceLocation{ 2, 1 }));
}

TEST(Lexer, UnknownCharacters)
{
  for (const char* text : { "#", "!", "\f", "`", "$", "\x80", "\xff" })
  {
    const auto tokens = tokenize(text);
    EXPECT_EQ(tokens[0].kind, TokenKind::Illegal) << text;
    EXPECT_EQ(tokens[0].error, LexError::UnknownCharacter) << text;
  }
}

TEST(Lexer, Strings)
{
  const auto tokens = tokenize("\"f.txt\" \"open\n");
  EXPECT_EQ(tokens[0].kind, TokenKind::String);
  EXPECT_EQ(tokens[0].text, "f.txt");
  EXPECT_EQ(tokens[1].kind, TokenKind::Illegal);
  EXPECT_EQ(tokens[1].error, LexError::UnterminatedString);
}

TEST(Lexer, NulEndsTheText)
{
  const std::string text("q\0+", 3);
  EXPECT_EQ(kinds(text), (std::vector<TokenKind>{ TokenKind::Identifier, TokenKind::End }));
}

TEST(Lexer, RejectedNumbers)
{
  for (const char* text : { "05", "007", "00", "1e0", "1e05", "1e-0", "1e", "1e+", ".", ".e5" })
  {
    const auto tokens = tokenize(text);
    EXPECT_EQ(tokens[0].kind, TokenKind::Illegal) << text;
    EXPECT_EQ(tokens[0].error, LexError::BadNumber) << text;
  }
  for (const char* text : { "0", "0.5", "1.", ".5", "1.e5", "2.5E+2", "0e5" })
  {
    const auto tokens = tokenize(text);
    EXPECT_EQ(tokens[0].kind, TokenKind::Number) << text;
    EXPECT_EQ(tokens[1].kind, TokenKind::End) << text;
  }
}

} // namespace
} // namespace frep
