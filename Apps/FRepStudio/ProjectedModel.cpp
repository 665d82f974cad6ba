#include "ProjectedModel.h"

namespace frepstudio
{
namespace
{

bool same(const std::vector<frep::project::CoordinateRange>& a,
  const std::vector<frep::project::CoordinateRange>& b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].coordinate != b[i].coordinate || a[i].lo != b[i].lo || a[i].hi != b[i].hi)
      return false;
  return true;
}

} // namespace

std::shared_ptr<const frep::Model> ProjectedModel::get(
  const std::shared_ptr<const frep::Model>& model,
  const std::vector<frep::project::CoordinateRange>& axes, const std::vector<double>& parameters,
  std::string& error)
{
  error.clear();
  if (axes.empty() || !model)
    return model;
  if (projected_ && model == source_ && same(axes, axes_) && parameters == parameters_)
    return projected_;
  frep::project::ProjectionOptions options;
  options.parameters = parameters;
  options.keep_coordinates = true; // the sliders keep numbering the model's coordinates
  const frep::LoadedModel loaded = frep::project::project(model, axes, options);
  if (!loaded.ok())
  {
    error = loaded.message();
    projected_.reset();
    return nullptr;
  }
  source_ = model;
  axes_ = axes;
  parameters_ = parameters;
  projected_ = loaded.model;
  return projected_;
}

} // namespace frepstudio
