#include "benchmark_cli.h"

#include "Compiler/load_model.h"

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
  const LoadedModel loaded = load_model(ModelSource::file(path));
  std::cerr << loaded.message();
  return loaded.model;
}

} // namespace frep::bench
