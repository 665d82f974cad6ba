// The 3-D (or 2-D) section of an n-D model at the sliders' values: the one specialisation that
// the live view's meshes, the spreadsheet's cells and the ray-cast pictures all draw.
#pragma once

#include "Compiler/model.h"

#include <memory>
#include <vector>

namespace frepstudio
{

/// `model` with a[] = `parameters` and x4.. = `fixed_values` (a missing value is 0); x1..x3 stay
/// free. Throws what Model::specialise throws.
std::shared_ptr<const frep::Tape> section_tape(const frep::Model& model,
  const std::vector<double>& parameters,
  const std::vector<double>& fixed_values);

} // namespace frepstudio
