#include "Project/sweep_model.h"

namespace frep::project
{
namespace
{

// The profile's coordinate k (0-based) as a model of x[4].
LoadedModel moved_coordinate(const SweepPath& path, int k)
{
  const std::string text = "frep_moved(x[4], a[1])\n{\n" + moved_point_text(path) +
                           "  frep_moved = mp[" + std::to_string(k + 1) + "];\n}\n";
  return load_model(ModelSource::from_text(text, "<sweep coordinate " + std::to_string(k + 1) + ">"));
}

} // namespace

LoadedModel sweep_model(const Operand& profile, const SweepPath& path)
{
  LoadedModel result;
  result.file = "<sweep>";
  std::string why = profile.model ? sweep_path_error(path) : std::string("no profile");
  if (why.empty())
  {
    int free = 0;
    for (int c = 0; c < profile.model->x_dim(); ++c)
      free += c >= static_cast<int>(profile.specialisation.fixed.size()) ||
              !profile.specialisation.fixed[static_cast<std::size_t>(c)];
    if (free != 3)
      why = "the profile must have 3 free coordinates (" + profile.model->name() + " has " +
            std::to_string(free) + ")";
  }
  if (!why.empty())
  {
    result.diagnostics.push_back(Diagnostic{ result.file, {}, why });
    return result;
  }
  std::vector<CoordinateFunction> coordinates;
  for (int k = 0; k < 3; ++k)
  {
    LoadedModel g = moved_coordinate(path, k);
    if (!g.ok()) // the text is ours: a failure here is a bug, reported rather than hidden
    {
      result.diagnostics = g.diagnostics;
      return result;
    }
    coordinates.push_back(CoordinateFunction{ -1, Operand{ g.model, {} } });
  }
  const CombineResult composed = compose(profile, std::move(coordinates), 4);
  if (!composed.ok())
  {
    result.diagnostics.push_back(Diagnostic{ result.file, {}, composed.error });
    return result;
  }
  result.model = composed.model;
  return result;
}

} // namespace frep::project
