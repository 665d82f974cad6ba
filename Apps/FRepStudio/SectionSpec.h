// Which 3-D section of a model a request is about: the model, its parameters, the values of the
// coordinates beyond x1..x3 and the box of x1..x3. The mesher's, the spreadsheet cells' and the
// ray caster's requests are each a SectionSpec plus what they need to draw it, so one section
// passes from one to another by a plain copy of this part.
#pragma once

#include "Compiler/model.h"

#include <array>
#include <memory>
#include <vector>

namespace frepstudio
{

struct SectionSpec
{
  std::shared_ptr<const frep::Model> model;
  int s_dim = 1;                              ///< the model's s[] size (attributes)
  std::vector<double> parameters;             ///< a[1..]
  std::vector<double> fixed_values;           ///< x4..xn (the coordinates beyond the first three)
  std::array<double, 3> lo{ -10, -10, -10 };  ///< the box of x1..x3 (its cut faces are capped)
  std::array<double, 3> hi{ 10, 10, 10 };
};

} // namespace frepstudio
