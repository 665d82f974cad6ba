// Fuzz harness (a): the HyperFun parser and checker on arbitrary text. Properties: nothing
// crashes; a refused text has at least one diagnostic, each with a message and a position inside
// the text (or none); an accepted program passes the structural validation the interpreter
// relies on (semantics::validate_object_graph throws only on ASTs the parser never produces),
// and its default object is one of its objects.
#include "Language/parser.h"
#include "Semantics/detail/ast_validation.h"
#include "fuzz_check.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // Both the default (CR accepted) and the original's strict mode.
  for (const bool accept_cr : { true, false })
  {
    frep::ParseOptions options;
    options.accept_carriage_return = accept_cr;
    const frep::ParseResult result = frep::parse_program(text, "fuzz.hf", options);
    if (!result.ok())
    {
      FUZZ_CHECK(!result.diagnostics.empty(), "a refused text has a diagnostic");
      const int lines = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
      for (const frep::Diagnostic& d : result.diagnostics)
      {
        FUZZ_CHECK(!d.message.empty(), "every diagnostic has a message");
        FUZZ_CHECK(!d.location.valid() || d.location.line <= lines,
          "a diagnostic's line is inside the text");
        FUZZ_CHECK(!d.format().empty(), "a diagnostic formats");
      }
      continue;
    }
    FUZZ_CHECK(result.diagnostics.empty(), "an accepted text has no diagnostic");
    const frep::ast::Program& program = *result.program;
    for (std::size_t i = 0; i < program.objects.size(); ++i)
    {
      try
      {
        frep::semantics::validate_object_graph(program, static_cast<int>(i));
      }
      catch (const std::invalid_argument& e)
      {
        std::fprintf(stderr, "validation: %s\n", e.what());
        FUZZ_CHECK(false, "the parser's output passes validate_object_graph");
      }
    }
    if (!program.objects.empty())
    {
      const int selected = frep::ast::select_default_object(program);
      FUZZ_CHECK(selected >= 0 && selected < static_cast<int>(program.objects.size()),
        "the default object is one of the program's objects");
    }
  }
  return 0;
}
