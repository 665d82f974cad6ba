#include "Project/sweep_text.h"

#include "Language/names.h"
#include "Project/detail/path_text.h"
#include "Project/path_pieces.h"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace frep::project
{
namespace
{

using Point = std::array<double, 3>;

std::vector<PathPiece> path_pieces(const SweepPath& path)
{
  std::vector<std::vector<double>> points;
  for (const Point& p : path.points)
    points.emplace_back(p.begin(), p.end());
  return path.curve == SweepPath::Curve::Polyline ? polyline_pieces(points, path.closed)
                                                   : catmull_rom_pieces(points, path.closed);
}

// Whether some tangent of the path is within 5 degrees of z (then the frames' up is y).
bool steep(const std::vector<PathPiece>& pieces)
{
  for (const PathPiece& piece : pieces)
    for (const double u : { 0.0, 0.25, 0.5, 0.75, 1.0 })
    {
      double d[3], length = 0;
      for (int a = 0; a < 3; ++a)
      {
        d[a] = piece_slope(piece[a], u);
        length += d[a] * d[a];
      }
      if (length > 0 && std::fabs(d[2]) / std::sqrt(length) > std::cos(5.0 * M_PI / 180.0))
        return true;
    }
  return false;
}

} // namespace

std::string moved_point_text(const SweepPath& path)
{
  const std::vector<PathPiece> pieces = path_pieces(path);
  const bool tangent = path.orientation == SweepPath::Orientation::Tangent;
  std::string out = "  array mp[3];\n" +
                    detail::path_position_text(pieces, "x[4]", { "mcx", "mcy", "mcz" });
  out += "  mvx = x[1] - mcx;\n  mvy = x[2] - mcy;\n  mvz = x[3] - mcz;\n";
  if (!tangent)
    return out + "  mp[1] = mvx;\n  mp[2] = mvy;\n  mp[3] = mvz;\n";
  out += detail::path_slope_text(pieces, { "mdx", "mdy", "mdz" });
  const bool y_up = steep(pieces);
  // z' = d / |d|; x' = up x z' / |..|; y' = z' x x'.
  out += "  ml = sqrt(mdx*mdx + mdy*mdy + mdz*mdz);\n  mzx = mdx/ml;\n  mzy = mdy/ml;\n"
         "  mzz = mdz/ml;\n";
  out += y_up ? "  mxx = mzz;\n  mxy = 0;\n  mxz = -mzx;\n" // (0,1,0) x z'
              : "  mxx = -mzy;\n  mxy = mzx;\n  mxz = 0;\n"; // (0,0,1) x z'
  out += "  mk = sqrt(mxx*mxx + mxy*mxy + mxz*mxz);\n  mxx = mxx/mk;\n  mxy = mxy/mk;\n"
         "  mxz = mxz/mk;\n";
  out += "  myx = mzy*mxz - mzz*mxy;\n  myy = mzz*mxx - mzx*mxz;\n  myz = mzx*mxy - mzy*mxx;\n";
  return out + "  mp[1] = mvx*mxx + mvy*mxy + mvz*mxz;\n  mp[2] = mvx*myx + mvy*myy + mvz*myz;\n"
               "  mp[3] = mvx*mzx + mvy*mzy + mvz*mzz;\n";
}

namespace
{

std::string check(const std::string& name, const std::string& profile, int a_dim,
  const SweepPath& path)
{
  if (!is_identifier(name) || !is_identifier(profile))
    return "the sweep's and the profile's names must be identifiers (got '" + name + "', '" +
           profile + "')";
  if (name == profile)
    return "the sweep cannot be named like its profile ('" + name + "')";
  if (a_dim < 1)
    return "the profile's a[] size must be at least 1";
  return sweep_path_error(path);
}

} // namespace

std::string sweep_path_error(const SweepPath& path)
{
  const std::size_t need = path.closed ? 3 : 2;
  if (path.points.size() < need)
    return "a" + std::string(path.closed ? " closed" : "n open") + " path needs at least " +
           std::to_string(need) + " points (got " + std::to_string(path.points.size()) + ")";
  for (std::size_t i = 0; i < path.points.size(); ++i)
  {
    for (const double v : path.points[i])
      if (!std::isfinite(v))
        return "path point " + std::to_string(i + 1) + " is not finite";
    const Point& next = path.points[(i + 1) % path.points.size()];
    if ((i + 1 < path.points.size() || path.closed) && next == path.points[i])
      return "path points " + std::to_string(i + 1) + " and " +
             std::to_string((i + 1) % path.points.size() + 1) + " are the same (no direction)";
  }
  return {};
}

SweepText write_sweep(const std::string& name, const std::string& profile, int profile_a_dim,
  const SweepPath& path)
{
  SweepText result;
  if (const std::string why = check(name, profile, profile_a_dim, path); !why.empty())
  {
    result.diagnostics.push_back(Diagnostic{ "<sweep>", {}, why });
    return result;
  }
  const std::string curve = path.curve == SweepPath::Curve::Polyline ? "polyline" : "catmull-rom";
  const std::string turn = path.orientation == SweepPath::Orientation::Fixed ? "fixed" : "tangent";
  result.text = "-- " + name + ": the profile " + profile + " moved along a " +
                (path.closed ? "closed " : "") + curve + " path of " +
                std::to_string(path.points.size()) + " points (" + turn +
                " orientation) as x4 goes 0 -> 1;\n-- projected along x4 (frepkit mesh --project "
                "x4=0:1) it is the volume the profile sweeps. Written by frepkit sweep.\n" +
                name + "(x[4], a[" + std::to_string(profile_a_dim) + "])\n{\n" +
                moved_point_text(path) + "  " + name + " = " + profile + "(mp, a);\n}\n";
  return result;
}

bool sweep_curve_from_name(const std::string& text, SweepPath::Curve& curve)
{
  if (text == "polyline")
    curve = SweepPath::Curve::Polyline;
  else if (text == "catmull-rom")
    curve = SweepPath::Curve::CatmullRom;
  else
    return false;
  return true;
}

bool sweep_orientation_from_name(const std::string& text, SweepPath::Orientation& orientation)
{
  if (text == "fixed")
    orientation = SweepPath::Orientation::Fixed;
  else if (text == "tangent")
    orientation = SweepPath::Orientation::Tangent;
  else
    return false;
  return true;
}

} // namespace frep::project
