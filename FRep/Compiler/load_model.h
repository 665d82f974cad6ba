// Loading a model: the one call every tool, filter and binding uses to turn a model file (or
// text) into a compiled model. It reads the file, picks the language by the name's extension
// (".vm": a tape of the field's benchmark format, anything else HyperFun), loads the libraries
// the model may call (HyperFun library files and shared libraries), parses, chooses the object
// and compiles it. Bad input is never an exception: everything that went wrong comes back as
// diagnostics (file:line:col where there is a position), worded the same for every caller.
#pragma once

#include "Compiler/model.h"
#include "Language/ast.h"
#include "Language/diagnostic.h"
#include "Language/user_functions.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace frep
{

/// Where a model comes from: a file, or text held in memory with the name its diagnostics use.
struct ModelSource
{
  /// The file's path, or the name of in-memory text ("<string>" by default). Its extension
  /// chooses the language either way: ".vm" (any case) is a tape, anything else HyperFun.
  std::string name;
  /// The model's text; nullopt: read the file `name`.
  std::optional<std::string> text;

  static ModelSource file(std::string path) { return ModelSource{ std::move(path), std::nullopt }; }
  static ModelSource from_text(std::string text, std::string name = "<string>")
  {
    return ModelSource{ std::move(name), std::move(text) };
  }
};

struct LoadOptions
{
  /// The object to compile (any case); empty: the default object, `my_model` among the file's
  /// own objects, else its first (the original's rule). A name that does not exist is an error
  /// listing the objects (the original silently fell back: a typo should not evaluate the wrong
  /// object).
  std::string object;
  /// Libraries the model may call. A ".hf" file (any case) is a HyperFun library: its objects
  /// are called like the file's own earlier objects (the paper's "user's own library written in
  /// HyperFun"). Anything else is a shared library implementing frepkit_user.h, whose functions
  /// the model calls by name (Documentation/user-functions.md).
  std::vector<std::string> libraries;
  /// Further functions the model may call (external shapes, functions registered in C++ or
  /// Python); the shared libraries' functions are added to a copy of it.
  std::shared_ptr<const UserFunctionRegistry> functions;
  /// Accept CR as whitespace (a CRLF file); false reproduces the original, which rejects it.
  bool accept_carriage_return = true;
  CompileOptions compile;
};

/// The text parsed, with every library: what tools that look at all objects need.
struct LoadedProgram
{
  std::string file; ///< ModelSource::name
  /// Null when anything failed (diagnostics say what).
  std::shared_ptr<const ast::Program> program;
  std::vector<Diagnostic> diagnostics;

  bool ok() const { return program != nullptr; }
};

struct LoadedModel
{
  std::string file; ///< ModelSource::name
  /// Set once the text parsed, even when choosing or compiling the object failed.
  std::shared_ptr<const ast::Program> program;
  int object = -1; ///< index of the chosen object in program->objects, -1 if none
  /// Null when anything failed (diagnostics say what).
  std::shared_ptr<const Model> model;
  std::vector<Diagnostic> diagnostics;

  bool ok() const { return model != nullptr; }
  /// Every diagnostic, one per line (format_diagnostics).
  std::string message() const { return format_diagnostics(diagnostics); }
};

/// Reads, parses (with the libraries), chooses the object and compiles it.
LoadedModel load_model(const ModelSource& source, const LoadOptions& options = {});

/// Reads and parses (with the libraries) without choosing or compiling an object.
LoadedProgram load_program(const ModelSource& source, const LoadOptions& options = {});

/// Chooses `options.object` in a parsed program and compiles it (load_model's last stages).
LoadedModel compile_object(const LoadedProgram& loaded, const LoadOptions& options = {});

/// The object `requested` names (any case; empty: the default object), or -1 with the reason in
/// `diagnostics`: the file defines no object, or no object has that name (the message lists them).
int choose_object(const LoadedProgram& loaded, const std::string& requested,
  std::vector<Diagnostic>& diagnostics);

/// "name(x[3], a[1], s[1])". The original gives every object s[] (s[1] when the header names
/// none), so s[1] is listed for those too.
std::string describe_object(const ast::Object& object);

/// The warning for more a[] values than the object has ("" when there are not too many):
/// "3 parameters given, ball has a[1]: the extra ones are ignored".
std::string extra_parameters_warning(const std::string& object_name, int a_dim, std::size_t given);

} // namespace frep
