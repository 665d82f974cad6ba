// A model file (.hf, or .vm: the Prospero Challenge's tape format) -> FRepKit's tape with every
// coordinate free, a[] = 0: what FRepKit evaluates, and what tape_to_libfive hands to libfive.
#pragma once

#include "Compiler/tape.h"

#include <memory>
#include <string>

namespace peers
{

struct LoadedModel
{
  std::shared_ptr<const frep::Tape> tape;
  int x_dim = 0;
};

/// Throws std::runtime_error with FRepKit's diagnostics (file:line:col) on failure.
/// `object` as hfp -o: that object, else the first (empty: my_model, else the first).
LoadedModel load_model(const std::string& path, const std::string& object);

} // namespace peers
