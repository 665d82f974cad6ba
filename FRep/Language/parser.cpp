// Recursive-descent parser for HyperFun. It follows the original's int_parse_N.c step by step
// (which token it reads next and what it checks there), so the first error is found at the same
// token and reported with the original's message. After an error the parser resynchronizes at a
// statement, object or file level and goes on to report further errors; the original itself
// stops caring after the first one.
#include "parser.h"

#include "Language/detail/parser_class.h"

#include <iterator>
#include <memory>
#include <utility>

namespace frep
{

using parsing::Parser;

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
    diagnostics.insert(diagnostics.end(),
      std::make_move_iterator(found.begin()),
      std::make_move_iterator(found.end()));
  }
  shared.program->first_own_object = static_cast<int>(shared.program->objects.size());
  std::vector<Diagnostic> found = Parser(text, std::move(file_name), options, shared).run();
  diagnostics.insert(diagnostics.end(),
    std::make_move_iterator(found.begin()),
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
