// write_path_family (sweep_text.h): a model driven along a path through some of its own
// coordinates, as HyperFun text.
#include "Project/sweep_text.h"

#include "Language/names.h"
#include "Project/detail/path_text.h"

#include <set>

namespace frep::project
{
namespace
{

std::string check(const std::string& name, const std::string& source, int x_dim, int a_dim,
  const std::vector<int>& coordinates, const std::vector<PathPiece>& pieces)
{
  if (!is_identifier(name) || !is_identifier(source) || name == source)
    return "the family's and the source's names must be different identifiers (got '" + name +
           "', '" + source + "')";
  if (a_dim < 1)
    return "the source's a[] size must be at least 1";
  std::set<int> seen;
  for (const int c : coordinates)
    if (c < 1 || c > x_dim || !seen.insert(c).second)
      return "path coordinate x" + std::to_string(c) + " is not one of x1..x" +
             std::to_string(x_dim) + " or is given twice";
  if (coordinates.empty())
    return "the path needs at least one of the source's coordinates";
  return path_pieces_error(pieces, coordinates.size());
}

} // namespace

SweepText write_path_family(const std::string& name, const std::string& source, int x_dim,
  int a_dim, const std::vector<int>& coordinates, const std::vector<PathPiece>& pieces)
{
  SweepText result;
  if (const std::string why = check(name, source, x_dim, a_dim, coordinates, pieces);
      !why.empty())
  {
    result.diagnostics.push_back(Diagnostic{ "<path family>", {}, why });
    return result;
  }
  const std::string t = "x[" + std::to_string(x_dim + 1) + "]";
  std::vector<std::string> path_names;
  for (std::size_t k = 0; k < coordinates.size(); ++k)
    path_names.push_back("mc" + std::to_string(k + 1));
  // Arrays are declared before any statement (the language's rule).
  std::string body = "  array mq[" + std::to_string(x_dim) + "];\n" +
                     detail::path_position_text(pieces, t, path_names);
  std::string on;
  for (int c = 1; c <= x_dim; ++c)
  {
    std::string value = "x[" + std::to_string(c) + "]";
    for (std::size_t k = 0; k < coordinates.size(); ++k)
      if (coordinates[k] == c)
        value = path_names[k];
    body += "  mq[" + std::to_string(c) + "] = " + value + ";\n";
  }
  for (const int c : coordinates)
    on += (on.empty() ? "x" : ", x") + std::to_string(c);
  result.text = "-- " + name + ": " + source + " along a path of " +
                std::to_string(pieces.size()) + " pieces through (" + on + ") as " + t +
                " goes 0 -> 1 (" + on + " of its own are read by nothing);\n-- projected along " + t +
                " it is the union of every shape on the path.\n" + name + "(x[" +
                std::to_string(x_dim + 1) + "], a[" + std::to_string(a_dim) + "])\n{\n" + body +
                "  " + name + " = " + source + "(mq, a);\n}\n";
  return result;
}

} // namespace frep::project
