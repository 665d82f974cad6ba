#include "model_loading.h"

#include "user_error.h"

#include <iostream>

namespace frepkit
{
namespace
{

/// One message without a position (a file that cannot be read, no such object) is the error
/// itself; anything else is printed in full (file:line:col) and counted.
[[noreturn]] void fail(const std::string& path, const std::vector<frep::Diagnostic>& diagnostics)
{
  if (diagnostics.size() == 1 && !diagnostics.front().location.valid())
  {
    throw UserError(diagnostics.front().file + ": " + diagnostics.front().message);
  }
  std::cerr << frep::format_diagnostics(diagnostics);
  throw UserError(path + ": " + std::to_string(diagnostics.size()) +
                  (diagnostics.size() == 1 ? " error" : " errors"));
}

} // namespace

frep::LoadOptions load_options(const UserInputs& inputs, const std::optional<std::string>& object)
{
  frep::LoadOptions options;
  options.object = object.value_or(std::string());
  options.libraries = inputs.libraries;
  options.functions = load_shape_inputs(inputs);
  return options;
}

frep::LoadedModel load_model(const std::string& path, const UserInputs& inputs,
  const std::optional<std::string>& object, std::size_t parameter_count)
{
  frep::LoadedModel loaded =
    frep::load_model(frep::ModelSource::file(path), load_options(inputs, object));
  if (!loaded.ok())
  {
    fail(path, loaded.diagnostics);
  }
  warn_extra_parameters(loaded.program->objects[static_cast<std::size_t>(loaded.object)],
    parameter_count);
  return loaded;
}

frep::LoadedProgram load_program(const std::string& path, const UserInputs& inputs)
{
  frep::LoadedProgram loaded = frep::load_program(frep::ModelSource::file(path), load_options(inputs));
  // Reading failed (the file or a library): no text was parsed, so there is nothing to report
  // position by position.
  if (!loaded.ok() && !loaded.diagnostics.empty() && !loaded.diagnostics.front().location.valid())
  {
    fail(path, loaded.diagnostics);
  }
  return loaded;
}

void require_parsed(const frep::LoadedProgram& loaded)
{
  if (!loaded.ok())
  {
    fail(loaded.file, loaded.diagnostics);
  }
}

int choose_object(const frep::LoadedProgram& loaded, const std::optional<std::string>& requested)
{
  std::vector<frep::Diagnostic> diagnostics;
  const int index = frep::choose_object(loaded, requested.value_or(std::string()), diagnostics);
  if (index < 0)
  {
    fail(loaded.file, diagnostics);
  }
  return index;
}

void warn_extra_parameters(const frep::ast::Object& object, std::size_t given)
{
  if (const std::string warning = frep::extra_parameters_warning(object.name, object.a_dim, given);
      !warning.empty())
  {
    std::cerr << "frepkit: warning: " << warning << '\n';
  }
}

} // namespace frepkit
