#include "frepkit_model.h"

#include "Compiler/model.h"
#include "Language/diagnostic.h"
#include "Language/parser.h"
#include "Language/vm_reader.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace peers
{

LoadedModel load_model(const std::string& path, const std::string& object)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw std::runtime_error("cannot read " + path);
  }
  std::ostringstream text;
  text << in.rdbuf();
  const frep::ParseResult parsed =
    frep::is_vm_file(path) ? frep::parse_vm(text.str(), path) : frep::parse_program(text.str(), path);
  if (!parsed.ok())
  {
    throw std::runtime_error(frep::format_diagnostics(parsed.diagnostics));
  }
  const int index = object.empty() ? frep::ast::select_default_object(*parsed.program)
                                   : frep::ast::select_object(*parsed.program, object);
  if (index < 0)
  {
    throw std::runtime_error(path + ": no object");
  }
  const frep::Model::CompileResult compiled = frep::Model::compile(parsed.program, index);
  if (!compiled.model)
  {
    throw std::runtime_error(frep::format_diagnostics(compiled.diagnostics));
  }
  LoadedModel loaded;
  loaded.tape = compiled.model->tape();
  loaded.x_dim = compiled.model->x_dim();
  return loaded;
}

} // namespace peers
