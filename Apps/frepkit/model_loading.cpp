#include "model_loading.h"

#include "Language/parser.h"
#include "Language/vm_reader.h"
#include "user_error.h"

#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

namespace frepkit
{

LoadedProgram load_program(const std::string& path, const UserInputs& inputs)
{
  frep::ParseOptions parse_options;
  parse_options.user_functions = load_user_inputs(inputs);
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw UserError(path + ": cannot open the model file");
  }
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
  {
    throw UserError(path + ": cannot read the model file");
  }
  // .vm tapes (the Prospero Challenge's format) read as a one-object HyperFun program (they
  // call no user function).
  frep::ParseResult parsed = frep::is_vm_file(path) ? frep::parse_vm(text, path)
                                                    : frep::parse_program(text, path, parse_options);
  return LoadedProgram{ path, parsed.program, std::move(parsed.diagnostics) };
}

std::string describe_object(const frep::ast::Object& object)
{
  std::ostringstream out;
  out << object.name << "(x[" << object.x_dim << "], a[" << object.a_dim << "], s[" << object.s_dim
      << "])";
  return out.str();
}

int choose_object(const LoadedProgram& loaded, const std::optional<std::string>& requested)
{
  const frep::ast::Program& program = *loaded.program;
  if (program.objects.empty())
  {
    throw UserError(loaded.path + ": the file defines no object");
  }
  if (requested)
  {
    const int found = frep::ast::find_object(program, *requested);
    if (found < 0)
    {
      std::string names;
      for (const frep::ast::Object& object : program.objects)
      {
        names += names.empty() ? "" : ", ";
        names += object.name;
      }
      throw UserError(
        loaded.path + ": no object named '" + *requested + "' (objects: " + names + ")");
    }
    return found;
  }
  return frep::ast::select_default_object(program);
}

void require_parsed(const LoadedProgram& loaded)
{
  if (loaded.program)
  {
    return;
  }
  std::cerr << frep::format_diagnostics(loaded.diagnostics);
  throw UserError(loaded.path + ": " + std::to_string(loaded.diagnostics.size()) +
                  (loaded.diagnostics.size() == 1 ? " error" : " errors"));
}

std::shared_ptr<const frep::Model> compile_object(const LoadedProgram& loaded, int object_index)
{
  frep::Model::CompileResult compiled = frep::Model::compile(loaded.program, object_index);
  if (!compiled.model)
  {
    std::cerr << frep::format_diagnostics(compiled.diagnostics);
    throw UserError(loaded.path + ": the object cannot be compiled");
  }
  return compiled.model;
}

void warn_extra_parameters(const frep::ast::Object& object, std::size_t given)
{
  if (given > static_cast<std::size_t>(object.a_dim))
  {
    std::cerr << "frepkit: warning: " << given << " parameters given, " << object.name << " has a["
              << object.a_dim << "]: the extra ones are ignored\n";
  }
}

} // namespace frepkit
