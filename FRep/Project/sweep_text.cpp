#include "Project/sweep_text.h"

#include "Language/names.h"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace frep::project
{
namespace
{

using Point = std::array<double, 3>;

// A number as a HyperFun literal (fixed notation: an exponent is a syntax error).
std::string literal(double v)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.9f", std::fabs(v));
  return v < 0 ? std::string("(-") + text + ")" : std::string(text);
}

// The control points of segment i: P0..P3 (Catmull-Rom's neighbours; a polyline uses P1, P2).
std::array<Point, 4> controls(const SweepPath& path, std::size_t i)
{
  const std::vector<Point>& p = path.points;
  const std::size_t n = p.size();
  const auto at = [&](long k) -> Point
  {
    if (path.closed)
      return p[static_cast<std::size_t>((k % static_cast<long>(n) + static_cast<long>(n)) %
                                        static_cast<long>(n))];
    if (k < 0) // mirrored: 2 p0 - p1
      return { 2 * p[0][0] - p[1][0], 2 * p[0][1] - p[1][1], 2 * p[0][2] - p[1][2] };
    if (k >= static_cast<long>(n))
      return { 2 * p[n - 1][0] - p[n - 2][0], 2 * p[n - 1][1] - p[n - 2][1],
        2 * p[n - 1][2] - p[n - 2][2] };
    return p[static_cast<std::size_t>(k)];
  };
  const long k = static_cast<long>(i);
  return { at(k - 1), at(k), at(k + 1), at(k + 2) };
}

// c(u) and c'(u) of one segment as polynomial coefficients per axis: c = sum c[j] u^j.
struct Segment
{
  std::array<std::array<double, 4>, 3> c{};
};

Segment segment(const SweepPath& path, std::size_t i)
{
  const std::array<Point, 4> q = controls(path, i);
  Segment s;
  for (int a = 0; a < 3; ++a)
  {
    if (path.curve == SweepPath::Curve::Polyline)
      s.c[a] = { q[1][a], q[2][a] - q[1][a], 0.0, 0.0 };
    else // uniform Catmull-Rom
      s.c[a] = { q[1][a], 0.5 * (q[2][a] - q[0][a]),
        0.5 * (2 * q[0][a] - 5 * q[1][a] + 4 * q[2][a] - q[3][a]),
        0.5 * (-q[0][a] + 3 * q[1][a] - 3 * q[2][a] + q[3][a]) };
  }
  return s;
}

std::string polynomial(const std::array<double, 4>& c, bool derivative)
{
  if (derivative)
    return literal(c[1]) + " + mu*(" + literal(2 * c[2]) + " + mu*" + literal(3 * c[3]) + ")";
  return literal(c[0]) + " + mu*(" + literal(c[1]) + " + mu*(" + literal(c[2]) + " + mu*" +
         literal(c[3]) + "))";
}

// Whether some tangent of the path is within 5 degrees of z (then the frames' up is y).
bool steep(const SweepPath& path, std::size_t segments)
{
  for (std::size_t i = 0; i < segments; ++i)
  {
    const Segment s = segment(path, i);
    for (const double u : { 0.0, 0.25, 0.5, 0.75, 1.0 })
    {
      double d[3], length = 0;
      for (int a = 0; a < 3; ++a)
      {
        d[a] = s.c[a][1] + u * (2 * s.c[a][2] + u * 3 * s.c[a][3]);
        length += d[a] * d[a];
      }
      if (length > 0 && std::fabs(d[2]) / std::sqrt(length) > std::cos(5.0 * M_PI / 180.0))
        return true;
    }
  }
  return false;
}

std::string body(const std::string& name, const std::string& profile, const SweepPath& path)
{
  const std::size_t n = path.points.size(), segments = path.closed ? n : n - 1;
  const bool tangent = path.orientation == SweepPath::Orientation::Tangent;
  std::string out = "  array mp[3];\n  mt = min(max(x[4], 0), 1);\n  ms = mt*" +
                    std::to_string(segments) + ";\n  mi = floor(ms);\n  if mi > " +
                    std::to_string(segments - 1) + " then\n    mi = " +
                    std::to_string(segments - 1) + ";\n  endif;\n  mu = ms - mi;\n";
  out += "  mcx = 0;\n  mcy = 0;\n  mcz = 0;\n  mdx = 0;\n  mdy = 0;\n  mdz = 1;\n";
  for (std::size_t i = 0; i < segments; ++i)
  {
    const Segment s = segment(path, i);
    out += "  if mi = " + std::to_string(i) + " then\n";
    const char* axes = "xyz";
    for (int a = 0; a < 3; ++a)
      out += std::string("    mc") + axes[a] + " = " + polynomial(s.c[a], false) + ";\n";
    for (int a = 0; tangent && a < 3; ++a)
      out += std::string("    md") + axes[a] + " = " + polynomial(s.c[a], true) + ";\n";
    out += "  endif;\n";
  }
  out += "  mvx = x[1] - mcx;\n  mvy = x[2] - mcy;\n  mvz = x[3] - mcz;\n";
  if (!tangent)
    return out + "  mp[1] = mvx;\n  mp[2] = mvy;\n  mp[3] = mvz;\n  " + name + " = " + profile +
           "(mp, a);\n";
  const bool y_up = steep(path, segments);
  // z' = d / |d|; x' = up x z' / |..|; y' = z' x x'.
  out += "  ml = sqrt(mdx*mdx + mdy*mdy + mdz*mdz);\n  mzx = mdx/ml;\n  mzy = mdy/ml;\n"
         "  mzz = mdz/ml;\n";
  out += y_up ? "  mxx = mzz;\n  mxy = 0;\n  mxz = -mzx;\n" // (0,1,0) x z'
              : "  mxx = -mzy;\n  mxy = mzx;\n  mxz = 0;\n"; // (0,0,1) x z'
  out += "  mk = sqrt(mxx*mxx + mxy*mxy + mxz*mxz);\n  mxx = mxx/mk;\n  mxy = mxy/mk;\n"
         "  mxz = mxz/mk;\n";
  out += "  myx = mzy*mxz - mzz*mxy;\n  myy = mzz*mxx - mzx*mxz;\n  myz = mzx*mxy - mzy*mxx;\n";
  out += "  mp[1] = mvx*mxx + mvy*mxy + mvz*mxz;\n  mp[2] = mvx*myx + mvy*myy + mvz*myz;\n"
         "  mp[3] = mvx*mzx + mvy*mzy + mvz*mzz;\n";
  return out + "  " + name + " = " + profile + "(mp, a);\n";
}

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

} // namespace

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
                body(name, profile, path) + "}\n";
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
