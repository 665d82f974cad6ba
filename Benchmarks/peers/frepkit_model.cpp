#include "frepkit_model.h"

#include "Compiler/load_model.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace peers
{

LoadedModel load_model(const std::string& path, const std::string& object)
{
  frep::LoadOptions options;
  options.object = object;
  const frep::LoadedModel compiled = frep::load_model(frep::ModelSource::file(path), options);
  if (!compiled.ok())
  {
    throw std::runtime_error(compiled.message());
  }
  LoadedModel loaded;
  loaded.tape = compiled.model->tape();
  loaded.x_dim = compiled.model->x_dim();
  return loaded;
}

} // namespace peers
