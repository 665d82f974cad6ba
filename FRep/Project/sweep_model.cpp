#include "Project/sweep_model.h"

#include "Project/path_pieces.h"

#include <algorithm>
#include <cmath>

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

// The least and greatest value of the cubic c over u in [0, 1]: its ends and the roots of c'.
Interval cubic_range(const std::array<double, 4>& c)
{
  Interval r{ std::min(c[0], piece_value(c, 1.0)), std::max(c[0], piece_value(c, 1.0)) };
  const auto at = [&](double u)
  {
    if (u > 0.0 && u < 1.0)
    {
      r.lo = std::min(r.lo, piece_value(c, u));
      r.hi = std::max(r.hi, piece_value(c, u));
    }
  };
  const double a = 3 * c[3], b = 2 * c[2], k = c[1]; // c'(u) = a u^2 + b u + k
  if (a == 0.0)
  {
    if (b != 0.0)
      at(-k / b);
    return r;
  }
  const double d = b * b - 4 * a * k;
  if (d >= 0.0)
  {
    at((-b - std::sqrt(d)) / (2 * a));
    at((-b + std::sqrt(d)) / (2 * a));
  }
  return r;
}

} // namespace

std::array<Interval, 3> sweep_bounds(const SweepPath& path, const std::array<Interval, 3>& profile_box)
{
  std::vector<std::vector<double>> points;
  for (const auto& p : path.points)
    points.emplace_back(p.begin(), p.end());
  const std::vector<PathPiece> pieces = path.curve == SweepPath::Curve::Polyline
                                          ? polyline_pieces(points, path.closed)
                                          : catmull_rom_pieces(points, path.closed);
  std::array<Interval, 3> centre{ Interval{ INFINITY, -INFINITY }, Interval{ INFINITY, -INFINITY },
    Interval{ INFINITY, -INFINITY } };
  for (const PathPiece& piece : pieces)
    for (std::size_t a = 0; a < 3; ++a)
    {
      const Interval r = cubic_range(piece[a]);
      centre[a] = { std::min(centre[a].lo, r.lo), std::max(centre[a].hi, r.hi) };
    }
  double radius = 0.0; // a turned profile: anywhere within its farthest corner's distance
  for (std::size_t a = 0; a < 3; ++a)
    radius += std::max(profile_box[a].lo * profile_box[a].lo, profile_box[a].hi * profile_box[a].hi);
  radius = std::sqrt(radius);
  std::array<Interval, 3> box;
  for (std::size_t a = 0; a < 3; ++a)
    box[a] = path.orientation == SweepPath::Orientation::Tangent
               ? Interval{ centre[a].lo - radius, centre[a].hi + radius }
               : Interval{ centre[a].lo + profile_box[a].lo, centre[a].hi + profile_box[a].hi };
  return box;
}

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
