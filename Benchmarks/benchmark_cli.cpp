#include "benchmark_cli.h"

#include "Language/parser.h"
#include "Language/vm_reader.h"

#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

namespace frep::bench
{

std::vector<double> comma_numbers(const std::string& text)
{
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    out.push_back(std::stod(item));
  }
  return out;
}

std::shared_ptr<const Model> compile_model_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    std::cerr << path << ": cannot open\n";
    return nullptr;
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const ParseResult parsed = is_vm_file(path) ? parse_vm(text, path) : parse_program(text, path);
  if (!parsed.ok())
  {
    std::cerr << format_diagnostics(parsed.diagnostics);
    return nullptr;
  }
  const auto compiled = Model::compile(parsed.program, ast::select_default_object(*parsed.program));
  if (!compiled.model)
  {
    std::cerr << format_diagnostics(compiled.diagnostics);
  }
  return compiled.model;
}

} // namespace frep::bench
