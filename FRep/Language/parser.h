// The HyperFun parser: text -> resolved AST, or every diagnostic found.
#pragma once

#include "ast.h"
#include "diagnostic.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace frep
{

/// A HyperFun text and the file name its diagnostics and run-time errors name.
struct SourceText
{
  std::string file;
  std::string text;
};

struct ParseOptions
{
  /// Accept CR as whitespace (a CRLF file). The original rejects it on Unix; we accept it by
  /// default (a documented deviation). false reproduces the original.
  bool accept_carriage_return = true;
  /// Deepest nesting of expressions/conditions/statements before the parser refuses the file
  /// with a clear error (protects every recursive pass from stack overflow). It is the depth
  /// of the tree, so a flat chain `a | b | c ...` counts one level per operator: 2000 allows
  /// chains of about a thousand terms and needs well under 1 MB of stack in every pass.
  int max_nesting_depth = 2000;
  /// User functions the program may call by name (user_functions.h); kept by the program.
  std::shared_ptr<const UserFunctionRegistry> user_functions;
  /// HyperFun library files (the paper's "user's own library written in HyperFun"): parsed
  /// first, in this order, into the same program, so the file calls their objects like its own
  /// earlier objects. Names are unique across all of them; diagnostics name the library file.
  std::vector<SourceText> libraries;
};

struct ParseResult
{
  /// Set when the text parsed without error (it may hold zero objects: "parse none").
  std::shared_ptr<const ast::Program> program;
  /// Every error found; the first is the one the original reports (same line, and the same
  /// column and message wherever we can match them). Empty when program is set.
  std::vector<Diagnostic> diagnostics;

  bool ok() const { return program != nullptr; }
};

/// Parses a whole file. `file_name` is used in diagnostics only.
ParseResult parse_program(std::string_view text, std::string file_name,
  const ParseOptions& options = {});

} // namespace frep
