#include "SectionTape.h"

#include <optional>

namespace frepstudio
{

std::shared_ptr<const frep::Tape> section_tape(const frep::Model& model,
  const std::vector<double>& parameters,
  const std::vector<double>& fixed_values)
{
  frep::Specialisation specialisation;
  specialisation.parameters = parameters;
  const int x_dim = model.x_dim();
  specialisation.fixed.assign(static_cast<std::size_t>(std::max(x_dim, 0)), std::nullopt);
  for (int i = 3; i < x_dim; ++i)
  {
    const std::size_t k = static_cast<std::size_t>(i - 3);
    specialisation.fixed[i] = k < fixed_values.size() ? fixed_values[k] : 0.0;
  }
  return model.specialise(specialisation);
}

} // namespace frepstudio
