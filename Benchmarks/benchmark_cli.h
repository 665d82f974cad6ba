// What the hand-run benchmark programs that take a model file share: comma-separated numbers
// from an option, and a model file (.hf or .vm, as frepkit reads them) compiled to its default
// object's tape.
#pragma once

#include "Compiler/model.h"
#include "Compiler/tape.h"

#include <memory>
#include <string>
#include <vector>

namespace frep::bench
{

/// "1,2.5,-3" -> {1, 2.5, -3} (std::stod's errors as exceptions).
std::vector<double> comma_numbers(const std::string& text);

/// The model file's default object, compiled; null with the diagnostics printed to stderr.
std::shared_ptr<const Model> compile_model_file(const std::string& path);

} // namespace frep::bench
