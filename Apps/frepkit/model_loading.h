// Reading and parsing a model file and choosing its object, shared by the subcommands.
#pragma once

#include "Compiler/model.h"
#include "Language/ast.h"
#include "Language/diagnostic.h"
#include "user_inputs.h"

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

namespace frepkit
{

struct LoadedProgram
{
  std::string path;
  std::shared_ptr<const frep::ast::Program> program;
  std::vector<frep::Diagnostic> diagnostics; ///< parse errors (program is null then)
};

/// Reads `path` as bytes (any content, even binary) and parses it. Throws UserError when the
/// file cannot be read; parse errors are returned in diagnostics.
/// `inputs`: the user libraries and shapes the model may call (--library, --shape).
LoadedProgram load_program(const std::string& path, const UserInputs& inputs = {});

/// The object to evaluate: `requested` (case-insensitive), else my_model, else the first object
/// (the original's rule). A requested name that does not exist is a UserError listing the
/// objects (the original silently fell back; a typo should not evaluate the wrong object).
/// Throws UserError when the file defines no object.
int choose_object(const LoadedProgram& loaded, const std::optional<std::string>& requested);

/// Throws UserError after printing every parse diagnostic (file:line:col) on standard error
/// when the program did not parse.
void require_parsed(const LoadedProgram& loaded);

/// Compiles the chosen object; a failure prints the compiler's diagnostics and throws UserError.
std::shared_ptr<const frep::Model> compile_object(const LoadedProgram& loaded, int object_index);

/// Prints a warning when more a[] values are given than the object has.
void warn_extra_parameters(const frep::ast::Object& object, std::size_t given);

/// "name(x[3], a[1], s[1])"
std::string describe_object(const frep::ast::Object& object);

} // namespace frepkit
