#include "check_command.h"

#include "Compiler/model.h"
#include "model_loading.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace frepkit
{

CLI::App* add_check_command(CLI::App& app, CheckOptions& options)
{
  CLI::App* check = app.add_subcommand("check",
    "Parse and check a HyperFun model: print every diagnostic as file:line:col, list the "
    "objects with their x/a/s dimensions and how each is evaluated.");
  check->add_option("model", options.model, "HyperFun model file (.hf)")->required();
  check->add_option("-o,--object", options.object,
    "Object to mark as selected (case-insensitive); default: my_model, else the first");
  add_user_input_options(check, options.user);
  return check;
}

int run_check(const CheckOptions& options)
{
  const frep::LoadedProgram loaded = load_program(options.model, options.user);
  if (!loaded.program)
  {
    std::cerr << frep::format_diagnostics(loaded.diagnostics);
    std::cerr << options.model << ": " << loaded.diagnostics.size()
              << (loaded.diagnostics.size() == 1 ? " error" : " errors") << '\n';
    return 1;
  }
  const frep::ast::Program& program = *loaded.program;
  const int selected = choose_object(loaded, options.object);
  std::cout << options.model << ": ok, " << program.objects.size()
            << (program.objects.size() == 1 ? " object" : " objects") << '\n';
  for (std::size_t i = 0; i < program.objects.size(); ++i)
  {
    const frep::ast::Object& object = program.objects[i];
    std::cout << (static_cast<int>(i) == selected ? "* " : "  ") << frep::describe_object(object);
    if (!object.s_declared)
    {
      std::cout << "  (s[1] implicit, as in HyperFun: the header declares no s[])";
    }
    if (static_cast<int>(i) < program.first_own_object)
    {
      std::cout << "  from library " << object.file;
    }
    const frep::Model::CompileResult compiled =
      frep::Model::compile(loaded.program, static_cast<int>(i));
    if (!compiled.model)
    {
      std::cout << "  not compiled: "
                << (compiled.diagnostics.empty() ? std::string("unknown reason")
                                                 : compiled.diagnostics.front().message);
    }
    else if (!compiled.model->is_compiled())
    {
      std::cout << "  interpreted (" << compiled.model->fallback_reason() << ")";
    }
    else
    {
      const auto tape = compiled.model->tape();
      std::cout << "  compiled: " << tape->code.size() << " instructions";
    }
    std::cout << '\n';
  }
  return 0;
}

} // namespace frepkit
