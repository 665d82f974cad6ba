// The HyperFun parser's class (parser.cpp runs it): its state and its members, declared
// here and defined in files by grammar level: parser_core.cpp (tokens, diagnostics),
// parser_objects.cpp (the file, objects, headers, bodies and declarations),
// parser_statements.cpp (statements and conditions), parser_expressions.cpp (expressions and
// calls). Private to the engine.
#pragma once

#include "Language/parser.h"

#include "Language/detail/lexer.h"

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace frep::parsing
{

// Array sizes above this are refused (the original would overflow HF_round or the stack).
inline constexpr double kMaxArraySize = 1'000'000;
// Total of the local array sizes of one object.
inline constexpr long long kMaxLocalItems = 10'000'000;
// After this many diagnostics the parser stops (binary garbage would give one per byte).
inline constexpr std::size_t kMaxDiagnostics = 100;

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

/// `text` with every byte outside printable ASCII (and `"` and `\`) as \xNN, for messages.
[[gnu::visibility("hidden")]] std::string printable(std::string_view text);

// Hidden: the members are called across the parser_*.cpp files of the shared engine library;
// default visibility would make each call interposable (no inlining under -fPIC), which
// measured 10-40 % slower parsing than the one-file class in an anonymous namespace.
class [[gnu::visibility("hidden")]] Parser
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

  std::string describe(const Token& t) const;

  // ---- diagnostics ---------------------------------------------------------------------------

  void report_message(SourceLocation where, std::string message);

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

  void expect(TokenKind wanted, std::string_view message);

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

  [[noreturn]] void fail_too_deep();

  void check_depth(int depth);

  // ---- file and objects ----------------------------------------------------------------------

  void parse_file();

  /// Skips at least one token, then up to the next object header (or the end).
  void skip_to_next_object();

  void parse_object();

  void skip_object_after_header_error();

  /// Skips to just after the '}' closing the current body (bodies contain no other braces), or
  /// to the next object header.
  void skip_to_object_end();

  /// A size in the header: a number literal, rounded with HF_round (0 is accepted there, as in
  /// the original).
  int header_size();

  void parse_header(ast::Object& object);

  // ---- body ----------------------------------------------------------------------------------

  bool object_has_errors() const { return diagnostics_.size() > object_errors_; }

  void parse_body(ast::Object& object);

  void parse_final_assignment(ast::Object& object);

  /// After a failed statement: continue after the next ';', but do not run past the end of the
  /// enclosing block or object.
  void recover_statement();

  void parse_array_declaration();

  // ---- statements ----------------------------------------------------------------------------

  /// Statements up to a token that cannot start one (the object's own name included).
  void parse_statements(ast::Block& block);

  ast::Stmt parse_statement();

  ast::IfStmt parse_if();

  ast::WhileStmt parse_while();

  /// `[`, the index expression, `]`, `=`, the value, `;` (the current token is the '[').
  void parse_element_assignment(ast::Stmt& stmt, ast::ArrayName array);

  /// `[ lit, ... ]` with exactly `count` signed literals, then `;` (the current token should be
  /// the '[').
  void parse_array_literal(ast::Stmt& stmt, ast::ArrayName array, int count);

  void parse_s_statement(ast::Stmt& stmt);

  void parse_identifier_statement(ast::Stmt& stmt);

  // ---- conditions ----------------------------------------------------------------------------

  static ast::ExprPtr make(SourceLocation where, auto node)
  {
    auto expr = std::make_unique<ast::Expr>();
    expr->location = where;
    expr->node = std::move(node);
    return expr;
  }

  /// cond ::= cmp { (and | or) cmp }  -- one level, left-associative
  Parsed parse_condition();

  static bool comparison_op(TokenKind k, ast::CompareOp& op);

  /// cmp ::= bfactor { relop bfactor }  -- chainable, left-associative
  Parsed parse_comparison();

  /// bfactor ::= not bfactor | '(' cond ')' | expr  -- a leading '(' always opens a condition
  Parsed parse_bool_factor();

  // ---- expressions ---------------------------------------------------------------------------

  static bool additive_op(TokenKind k, ast::BinaryOp& op);

  Parsed binary(SourceLocation where, ast::BinaryOp op, Parsed lhs, Parsed rhs);

  /// expr ::= term { (+ - | & \ @) term }  -- all one level, left-associative
  Parsed parse_expression();

  /// term ::= pfactor { (* /) pfactor }
  Parsed parse_term();

  /// pfactor ::= unary { ^ unary }  -- LEFT-associative in the original
  Parsed parse_power();

  /// unary ::= (+ | - | ~) unary | primary  -- binds tighter than ^
  Parsed parse_unary();

  /// Where the original's postfix code of `expr` starts (see ElementExpr::index_end).
  static SourceLocation first_instruction(const ast::Expr& expr);

  /// `[ index ]` after the array name (the current token should be the '[').
  Parsed parse_element(const Token& name, ast::ArrayName array);

  /// A whole-array argument: x, a, s or a local array; its size in `size`.
  ast::ArrayName array_argument(int& size);

  Parsed parse_primary();

  Parsed parse_call();

  /// NAME(arg, ...) for a user function: arguments are parsed by the kinds it registered, and a
  /// wrong count or kind is named with its signature.
  Parsed parse_user_call(int index);

  /// OBJ(xarr, aarr [, sarr]) for an earlier object; sizes must match the callee's header.
  Parsed parse_object_call(int callee_index);
};

} // namespace frep::parsing
