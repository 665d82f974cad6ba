// Recursive-descent parser for HyperFun. It follows the original's int_parse_N.c step by step
// (which token it reads next and what it checks there), so the first error is found at the same
// token and reported with the original's message. After an error the parser resynchronizes at a
// statement, object or file level and goes on to report further errors; the original itself
// stops caring after the first one.
#include "parser.h"

#include "Language/detail/lexer.h"
#include "Language/detail/number_literal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <utility>

namespace frep
{
namespace
{

// Array sizes above this are refused (the original would overflow HF_round or the stack).
constexpr double kMaxArraySize = 1'000'000;
// Total of the local array sizes of one object.
constexpr long long kMaxLocalItems = 10'000'000;
// After this many diagnostics the parser stops (binary garbage would give one per byte).
constexpr std::size_t kMaxDiagnostics = 100;

/// Thrown after a diagnostic to abandon the current statement / header; caught where the parser
/// resynchronizes.
struct ParseFailure
{
};

/// Thrown when there are too many diagnostics to go on.
struct TooManyErrors
{
};

/// An expression and the depth of its tree (bounded so every recursive pass over the AST,
/// including destruction, stays far from stack overflow).
struct Parsed
{
  ast::ExprPtr expr;
  int depth = 1;
};

enum class NameKind
{
  Scalar,
  Array
};

struct LocalName
{
  NameKind kind = NameKind::Scalar;
  int index = -1; ///< Object::scalars or Object::arrays
};

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

class Parser
{
public:
  /// The objects read so far from the files parsed before this one (library files), and the
  /// index of each name; each file's parser adds its objects to the same program.
  struct Shared
  {
    std::shared_ptr<ast::Program> program;
    std::unordered_map<std::string, int> object_index; ///< first object of each name
  };

  Parser(std::string_view text, std::string file, const ParseOptions& options, Shared& shared)
    : text_(text)
    , tokens_(tokenize(text, LexerOptions{ options.accept_carriage_return }))
    , file_(std::move(file))
    , max_depth_(std::max(1, options.max_nesting_depth))
    , program_(shared.program)
    , object_index_(shared.object_index)
  {
  }

  /// Parses the whole file into the shared program; returns its diagnostics.
  std::vector<Diagnostic> run()
  {
    try
    {
      parse_file();
    }
    catch (const TooManyErrors&)
    {
      diagnostics_.push_back(
        Diagnostic{ file_, tok().location, "Too many errors; parsing stopped" });
    }
    return std::move(diagnostics_);
  }

private:
  std::string_view text_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  std::string file_;
  int max_depth_;
  std::vector<Diagnostic> diagnostics_;
  std::shared_ptr<ast::Program> program_;
  std::unordered_map<std::string, int>& object_index_; ///< first object of each name

  // State of the object being parsed.
  ast::Object* object_ = nullptr;
  std::unordered_map<std::string, LocalName> names_;
  long long local_items_ = 0;
  int block_depth_ = 0;
  int nesting_ = 0;               ///< current recursion depth of the descent
  std::size_t object_errors_ = 0; ///< diagnostics_.size() when the object started

  // ---- tokens --------------------------------------------------------------------------------

  const Token& tok() const { return tokens_[pos_]; }
  const Token& peek(std::size_t ahead) const
  {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  TokenKind kind() const { return tok().kind; }
  void advance()
  {
    if (pos_ + 1 < tokens_.size())
    {
      ++pos_;
    }
  }

  /// "name ( x [" starts an object header (used to resynchronize after errors).
  bool at_object_header() const
  {
    return kind() == TokenKind::Identifier && peek(1).kind == TokenKind::LeftParen &&
           peek(2).kind == TokenKind::X && peek(3).kind == TokenKind::LeftBracket;
  }

  std::string describe(const Token& t) const
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

  // ---- diagnostics ---------------------------------------------------------------------------

  void report_message(SourceLocation where, std::string message)
  {
    diagnostics_.push_back(Diagnostic{ file_, where, std::move(message) });
    if (diagnostics_.size() >= kMaxDiagnostics)
    {
      throw TooManyErrors{};
    }
  }

  /// The original's message followed by what was found.
  void report(const Token& at, std::string_view message)
  {
    report_message(at.location, std::string(message) + " (found " + describe(at) + ")");
  }

  [[noreturn]] void fail(const Token& at, std::string_view message)
  {
    report(at, message);
    throw ParseFailure{};
  }

  void expect(TokenKind wanted, std::string_view message)
  {
    if (kind() != wanted)
    {
      fail(tok(), message);
    }
  }

  /// Guards one level of recursive descent.
  class Nest
  {
  public:
    explicit Nest(Parser& parser)
      : parser_(parser)
    {
      if (parser_.nesting_ >= parser_.max_depth_)
      {
        parser_.fail_too_deep();
      }
      ++parser_.nesting_;
    }
    ~Nest() { --parser_.nesting_; }
    Nest(const Nest&) = delete;
    Nest& operator=(const Nest&) = delete;

  private:
    Parser& parser_;
  };

  [[noreturn]] void fail_too_deep()
  {
    report_message(tok().location,
      "Nesting too deep: more than " + std::to_string(max_depth_) +
        " levels of expressions, conditions or statements");
    throw ParseFailure{};
  }

  void check_depth(int depth)
  {
    if (depth > max_depth_)
    {
      fail_too_deep();
    }
  }

  // ---- file and objects ----------------------------------------------------------------------

  void parse_file()
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

  /// Skips at least one token, then up to the next object header (or the end).
  void skip_to_next_object()
  {
    advance();
    while (kind() != TokenKind::End && !at_object_header())
    {
      advance();
    }
  }

  void parse_object()
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
      report(tok(), other.file == file_ ? std::string("Body name is not unique")
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

  void skip_object_after_header_error()
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

  /// Skips to just after the '}' closing the current body (bodies contain no other braces), or
  /// to the next object header.
  void skip_to_object_end()
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

  /// A size in the header: a number literal, rounded with HF_round (0 is accepted there, as in
  /// the original).
  int header_size()
  {
    expect(TokenKind::Number, "Real number expected");
    const double value = tok().value;
    if (!(value <= kMaxArraySize))
    {
      fail(tok(), "Array size too large: at most 1000000 items are supported");
    }
    return hf_round_size(value);
  }

  void parse_header(ast::Object& object)
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

  // ---- body ----------------------------------------------------------------------------------

  bool object_has_errors() const { return diagnostics_.size() > object_errors_; }

  void parse_body(ast::Object& object)
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

  void parse_final_assignment(ast::Object& object)
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

  /// After a failed statement: continue after the next ';', but do not run past the end of the
  /// enclosing block or object.
  void recover_statement()
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

  void parse_array_declaration()
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

  // ---- statements ----------------------------------------------------------------------------

  /// Statements up to a token that cannot start one (the object's own name included).
  void parse_statements(ast::Block& block)
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

  ast::Stmt parse_statement()
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

  ast::IfStmt parse_if()
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

  ast::WhileStmt parse_while()
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

  /// `[`, the index expression, `]`, `=`, the value, `;` (the current token is the '[').
  void parse_element_assignment(ast::Stmt& stmt, ast::ArrayName array)
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

  /// `[ lit, ... ]` with exactly `count` signed literals, then `;` (the current token should be
  /// the '[').
  void parse_array_literal(ast::Stmt& stmt, ast::ArrayName array, int count)
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

  void parse_s_statement(ast::Stmt& stmt)
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

  void parse_identifier_statement(ast::Stmt& stmt)
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

  // ---- conditions ----------------------------------------------------------------------------

  static ast::ExprPtr make(SourceLocation where, auto node)
  {
    auto expr = std::make_unique<ast::Expr>();
    expr->location = where;
    expr->node = std::move(node);
    return expr;
  }

  /// cond ::= cmp { (and | or) cmp }  -- one level, left-associative
  Parsed parse_condition()
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

  static bool comparison_op(TokenKind k, ast::CompareOp& op)
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

  /// cmp ::= bfactor { relop bfactor }  -- chainable, left-associative
  Parsed parse_comparison()
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

  /// bfactor ::= not bfactor | '(' cond ')' | expr  -- a leading '(' always opens a condition
  Parsed parse_bool_factor()
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

  // ---- expressions ---------------------------------------------------------------------------

  static bool additive_op(TokenKind k, ast::BinaryOp& op)
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

  Parsed binary(SourceLocation where, ast::BinaryOp op, Parsed lhs, Parsed rhs)
  {
    const int depth = 1 + std::max(lhs.depth, rhs.depth);
    check_depth(depth);
    return Parsed{ make(where, ast::BinaryExpr{ op, std::move(lhs.expr), std::move(rhs.expr) }),
      depth };
  }

  /// expr ::= term { (+ - | & \ @) term }  -- all one level, left-associative
  Parsed parse_expression()
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

  /// term ::= pfactor { (* /) pfactor }
  Parsed parse_term()
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

  /// pfactor ::= unary { ^ unary }  -- LEFT-associative in the original
  Parsed parse_power()
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

  /// unary ::= (+ | - | ~) unary | primary  -- binds tighter than ^
  Parsed parse_unary()
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

  /// Where the original's postfix code of `expr` starts (see ElementExpr::index_end).
  static SourceLocation first_instruction(const ast::Expr& expr)
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

  /// `[ index ]` after the array name (the current token should be the '[').
  Parsed parse_element(const Token& name, ast::ArrayName array)
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

  /// A whole-array argument: x, a, s or a local array; its size in `size`.
  ast::ArrayName array_argument(int& size)
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

  Parsed parse_primary()
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
              fail(t, "Unknown function '" + t.text +
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

  Parsed parse_call()
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

  /// NAME(arg, ...) for a user function: arguments are parsed by the kinds it registered, and a
  /// wrong count or kind is named with its signature.
  Parsed parse_user_call(int index)
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
      report_message(where, "Function " + function.name + " takes " + std::to_string(arity) +
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
        if (k != TokenKind::X && k != TokenKind::A && k != TokenKind::S &&
            k != TokenKind::Identifier)
        {
          fail(tok(), "Argument " + std::to_string(i + 1) + " of " + signature +
              " must be an array name");
        }
        int size = 0;
        node.args.emplace_back(array_argument(size));
        const int wanted = static_cast<std::size_t>(i) < function.array_sizes.size()
          ? function.array_sizes[static_cast<std::size_t>(i)]
          : 0;
        if (wanted > 0 && size != wanted)
        {
          fail(tok(), "Argument " + std::to_string(i + 1) + " of " + signature + " must have " +
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

  /// OBJ(xarr, aarr [, sarr]) for an earlier object; sizes must match the callee's header.
  Parsed parse_object_call(int callee_index)
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
};

} // namespace

ParseResult parse_program(std::string_view text, std::string file_name, const ParseOptions& options)
{
  Parser::Shared shared;
  shared.program = std::make_shared<ast::Program>();
  shared.program->file = file_name;
  shared.program->user_functions = options.user_functions;
  std::vector<Diagnostic> diagnostics;
  for (const SourceText& library : options.libraries)
  {
    std::vector<Diagnostic> found = Parser(library.text, library.file, options, shared).run();
    diagnostics.insert(diagnostics.end(), std::make_move_iterator(found.begin()),
      std::make_move_iterator(found.end()));
  }
  shared.program->first_own_object = static_cast<int>(shared.program->objects.size());
  std::vector<Diagnostic> found = Parser(text, std::move(file_name), options, shared).run();
  diagnostics.insert(diagnostics.end(), std::make_move_iterator(found.begin()),
    std::make_move_iterator(found.end()));
  ParseResult result;
  if (diagnostics.empty())
  {
    result.program = std::move(shared.program);
  }
  else
  {
    result.diagnostics = std::move(diagnostics);
  }
  return result;
}

} // namespace frep
