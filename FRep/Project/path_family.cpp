#include "Project/path_family.h"

#include "Compiler/combine.h"
#include "Project/detail/path_text.h"

#include <set>

namespace frep::project
{
namespace
{

std::string family_error(const Model& model, const std::vector<int>& coordinates,
  const std::vector<PathPiece>& pieces)
{
  if (coordinates.empty())
    return "the path needs at least one of " + model.name() + "'s coordinates";
  std::set<int> seen;
  for (const int c : coordinates)
    if (c < 1 || c > model.x_dim() || !seen.insert(c).second)
      return "path coordinate x" + std::to_string(c) + " is not one of x1..x" +
             std::to_string(model.x_dim()) + " or is given twice";
  return path_pieces_error(pieces, coordinates.size());
}

// The path's coordinate k as a model of x[n + 1] (the composed model's coordinates).
LoadedModel path_coordinate(const std::vector<PathPiece>& pieces, std::size_t k, int n)
{
  std::vector<std::string> names(pieces.front().size());
  for (std::size_t a = 0; a < names.size(); ++a)
    names[a] = "mc" + std::to_string(a + 1);
  const std::string text = "frep_path(x[" + std::to_string(n + 1) + "], a[1])\n{\n" +
                           detail::path_position_text(pieces, "x[" + std::to_string(n + 1) + "]",
                             names) +
                           "  frep_path = " + names[k] + ";\n}\n";
  return load_model(ModelSource::from_text(text, "<path coordinate " + std::to_string(k + 1) + ">"));
}

} // namespace

LoadedModel path_family(std::shared_ptr<const Model> model, const std::vector<int>& path_coordinates,
  const std::vector<PathPiece>& pieces, const std::vector<double>& parameters)
{
  LoadedModel result;
  result.file = "<path family>";
  const std::string why =
    model ? family_error(*model, path_coordinates, pieces) : std::string("no model");
  if (!why.empty())
  {
    result.diagnostics.push_back(Diagnostic{ result.file, {}, why });
    return result;
  }
  const int n = model->x_dim();
  std::vector<CoordinateFunction> coordinates(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c)
    coordinates[static_cast<std::size_t>(c)].coordinate = c;
  for (std::size_t k = 0; k < path_coordinates.size(); ++k)
  {
    LoadedModel g = path_coordinate(pieces, k, n);
    if (!g.ok()) // the text is ours: a failure here is a bug, reported rather than hidden
    {
      result.diagnostics = g.diagnostics;
      return result;
    }
    coordinates[static_cast<std::size_t>(path_coordinates[k] - 1)] =
      CoordinateFunction{ -1, Operand{ g.model, {} } };
  }
  Operand outer{ model, {} };
  outer.specialisation.parameters = parameters;
  const CombineResult composed = compose(std::move(outer), std::move(coordinates), n + 1);
  if (!composed.ok())
  {
    result.diagnostics.push_back(Diagnostic{ result.file, {}, composed.error });
    return result;
  }
  result.model = composed.model;
  return result;
}

} // namespace frep::project
