#include "Compiler/load_model.h"

#include "Language/parser.h"
#include "Language/user_library.h"
#include "Language/vm_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>

namespace frep
{
namespace
{

bool has_extension(const std::string& name, std::string_view extension)
{
  if (name.size() < extension.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < extension.size(); ++i)
  {
    const auto c = static_cast<unsigned char>(name[name.size() - extension.size() + i]);
    if (std::tolower(c) != extension[i])
    {
      return false;
    }
  }
  return true;
}

/// The file's bytes (any content, even binary), or a diagnostic naming it.
std::optional<std::string> read_file(const std::string& path, const char* what,
  std::vector<Diagnostic>& diagnostics)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    diagnostics.push_back(
      Diagnostic{ path, {}, std::string("cannot open the ") + what + ": " + std::generic_category().message(errno) });
    return std::nullopt;
  }
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
  {
    diagnostics.push_back(Diagnostic{ path, {}, std::string("cannot read the ") + what });
    return std::nullopt;
  }
  return text;
}

/// The registry the model may call: options.functions plus every shared library's functions
/// (null when there are none); the HyperFun library files' texts go to `parse`.
bool gather_libraries(const LoadOptions& options, ParseOptions& parse,
  std::vector<Diagnostic>& diagnostics)
{
  std::shared_ptr<UserFunctionRegistry> registry;
  for (const std::string& path : options.libraries)
  {
    if (has_extension(path, ".hf"))
    {
      std::optional<std::string> text = read_file(path, "library file", diagnostics);
      if (!text)
      {
        return false;
      }
      parse.libraries.push_back(SourceText{ path, std::move(*text) });
      continue;
    }
    if (!registry)
    {
      registry = options.functions ? std::make_shared<UserFunctionRegistry>(*options.functions)
                                   : std::make_shared<UserFunctionRegistry>();
    }
    if (const UserLibraryResult r = load_user_library(path, *registry); !r.ok())
    {
      diagnostics.push_back(Diagnostic{ path, {}, r.error });
      return false;
    }
  }
  parse.user_functions = registry ? registry : options.functions;
  return true;
}

std::string object_names(const ast::Program& program)
{
  std::string names;
  for (const ast::Object& object : program.objects)
  {
    names += names.empty() ? "" : ", ";
    names += object.name;
  }
  return names;
}

} // namespace

LoadedProgram load_program(const ModelSource& source, const LoadOptions& options)
{
  LoadedProgram loaded;
  loaded.file = source.name;
  std::optional<std::string> text = source.text;
  if (!text)
  {
    text = read_file(source.name, "model file", loaded.diagnostics);
    if (!text)
    {
      return loaded;
    }
  }
  ParseResult parsed;
  if (is_vm_file(source.name))
  {
    // A tape calls nothing: libraries and functions have no use there.
    parsed = parse_vm(*text, source.name);
  }
  else
  {
    ParseOptions parse;
    parse.accept_carriage_return = options.accept_carriage_return;
    if (!gather_libraries(options, parse, loaded.diagnostics))
    {
      return loaded;
    }
    parsed = parse_program(*text, source.name, parse);
  }
  loaded.program = std::move(parsed.program);
  loaded.diagnostics = std::move(parsed.diagnostics);
  return loaded;
}

int choose_object(const LoadedProgram& loaded, const std::string& requested,
  std::vector<Diagnostic>& diagnostics)
{
  if (!loaded.program)
  {
    return -1;
  }
  const ast::Program& program = *loaded.program;
  if (ast::own_object_count(program) <= 0)
  {
    diagnostics.push_back(Diagnostic{ loaded.file, {}, "the file defines no object" });
    return -1;
  }
  if (requested.empty())
  {
    return ast::select_default_object(program);
  }
  const int found = ast::find_object(program, requested);
  if (found < 0)
  {
    diagnostics.push_back(Diagnostic{ loaded.file, {},
      "no object named '" + requested + "' (objects: " + object_names(program) + ")" });
  }
  return found;
}

LoadedModel compile_object(const LoadedProgram& loaded, const LoadOptions& options)
{
  LoadedModel result;
  result.file = loaded.file;
  result.program = loaded.program;
  result.diagnostics = loaded.diagnostics;
  if (!loaded.program)
  {
    return result;
  }
  result.object = choose_object(loaded, options.object, result.diagnostics);
  if (result.object < 0)
  {
    return result;
  }
  Model::CompileResult compiled = Model::compile(loaded.program, result.object, options.compile);
  if (!compiled.model)
  {
    result.diagnostics.insert(result.diagnostics.end(), compiled.diagnostics.begin(),
      compiled.diagnostics.end());
    if (compiled.diagnostics.empty())
    {
      const ast::Object& object = loaded.program->objects[static_cast<std::size_t>(result.object)];
      result.diagnostics.push_back(Diagnostic{ object.file.empty() ? loaded.file : object.file,
        object.location, "the object '" + object.name + "' cannot be compiled" });
    }
    return result;
  }
  result.model = std::move(compiled.model);
  return result;
}

LoadedModel load_model(const ModelSource& source, const LoadOptions& options)
{
  return compile_object(load_program(source, options), options);
}

std::string describe_object(const ast::Object& object)
{
  std::ostringstream out;
  out << object.name << "(x[" << object.x_dim << "], a[" << object.a_dim << "], s[" << object.s_dim
      << "])";
  return out.str();
}

std::string extra_parameters_warning(const std::string& object_name, int a_dim, std::size_t given)
{
  if (given <= static_cast<std::size_t>(std::max(a_dim, 0)))
  {
    return {};
  }
  return std::to_string(given) + " parameters given, " + object_name + " has a[" +
         std::to_string(a_dim) + "]: the extra ones are ignored";
}

} // namespace frep
