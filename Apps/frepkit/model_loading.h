// frepkit's side of loading a model: the engine's one loading call (Compiler/load_model.h) with
// the command line's --library, --shape and --object, its diagnostics printed and turned into a
// UserError (exit code 1).
#pragma once

#include "Compiler/load_model.h"
#include "user_inputs.h"

#include <cstddef>
#include <optional>
#include <string>

namespace frepkit
{

/// The engine's load options for --library (HyperFun .hf files and shared libraries), --shape
/// and --object.
frep::LoadOptions load_options(const UserInputs& inputs,
  const std::optional<std::string>& object = std::nullopt);

/// Loads and compiles the model (frep::load_model): the object `object` names, else the default
/// (my_model, else the first). On failure prints every diagnostic (file:line:col) on standard
/// error and throws UserError. Warns when more a[] values are given than the object has.
frep::LoadedModel load_model(const std::string& path, const UserInputs& inputs,
  const std::optional<std::string>& object, std::size_t parameter_count = 0);

/// Reads and parses only (check, eval and hfp look at the program themselves). A file or library
/// that cannot be read is a UserError; parse errors are returned in diagnostics.
frep::LoadedProgram load_program(const std::string& path, const UserInputs& inputs = {});

/// Prints every parse diagnostic and throws UserError when the program did not parse.
void require_parsed(const frep::LoadedProgram& loaded);

/// The object `requested` names, else the default; UserError when there is none (the message
/// lists the objects).
int choose_object(const frep::LoadedProgram& loaded, const std::optional<std::string>& requested);

/// Prints a warning when more a[] values are given than the object has.
void warn_extra_parameters(const frep::ast::Object& object, std::size_t given);

} // namespace frepkit
