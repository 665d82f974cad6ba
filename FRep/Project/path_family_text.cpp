// write_path_family (sweep_text.h): a model driven along a polyline through some of its own
// coordinates, as HyperFun text.
#include "Project/sweep_text.h"

#include "Language/names.h"

#include <cmath>
#include <cstdio>
#include <set>

namespace frep::project
{
namespace
{

std::string literal(double v) // fixed notation: an exponent is a syntax error in HyperFun
{
  char text[64];
  std::snprintf(text, sizeof text, "%.9f", std::fabs(v));
  return v < 0 ? std::string("(-") + text + ")" : std::string(text);
}

std::string check(const std::string& name, const std::string& source, int x_dim, int a_dim,
  const std::vector<int>& coordinates, const std::vector<std::vector<double>>& points)
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
  if (coordinates.empty() || static_cast<int>(coordinates.size()) >= x_dim)
    return "the path needs at least one of the source's coordinates and must leave one";
  if (points.size() < 2)
    return "a path needs at least 2 points (got " + std::to_string(points.size()) + ")";
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (points[i].size() != coordinates.size())
      return "path point " + std::to_string(i + 1) + " has " + std::to_string(points[i].size()) +
             " values, the path " + std::to_string(coordinates.size()) + " coordinates";
    for (const double v : points[i])
      if (!std::isfinite(v))
        return "path point " + std::to_string(i + 1) + " is not finite";
  }
  return {};
}

// The segment i's point: p_i + mu (p_{i+1} - p_i), one scalar per path coordinate (mc1, mc2..).
std::string segments_text(const std::vector<std::vector<double>>& points, bool closed)
{
  const std::size_t n = points.size(), segments = closed ? n : n - 1;
  std::string out = "  mt = min(max(x[" + std::string("T") + "], 0), 1);\n";
  out += "  ms = mt*" + std::to_string(segments) + ";\n  mi = floor(ms);\n  if mi > " +
         std::to_string(segments - 1) + " then\n    mi = " + std::to_string(segments - 1) +
         ";\n  endif;\n  mu = ms - mi;\n";
  for (std::size_t k = 0; k < points[0].size(); ++k)
    out += "  mc" + std::to_string(k + 1) + " = " + literal(points[0][k]) + ";\n";
  for (std::size_t i = 0; i < segments; ++i)
  {
    const std::vector<double>& p = points[i];
    const std::vector<double>& q = points[(i + 1) % n];
    out += "  if mi = " + std::to_string(i) + " then\n";
    for (std::size_t k = 0; k < p.size(); ++k)
      out += "    mc" + std::to_string(k + 1) + " = " + literal(p[k]) + " + mu*" +
             literal(q[k] - p[k]) + ";\n";
    out += "  endif;\n";
  }
  return out;
}

} // namespace

SweepText write_path_family(const std::string& name, const std::string& source, int x_dim,
  int a_dim, const std::vector<int>& coordinates, const std::vector<std::vector<double>>& points,
  bool closed)
{
  SweepText result;
  if (const std::string why = check(name, source, x_dim, a_dim, coordinates, points);
      !why.empty())
  {
    result.diagnostics.push_back(Diagnostic{ "<path family>", {}, why });
    return result;
  }
  const int m = x_dim - static_cast<int>(coordinates.size()), t = m + 1;
  // Arrays are declared before any statement (the language's rule).
  std::string body = "  array mq[" + std::to_string(x_dim) + "];\n" + segments_text(points, closed);
  body.replace(body.find("x[T]"), 4, "x[" + std::to_string(t) + "]");
  int free = 0;
  for (int c = 1; c <= x_dim; ++c)
  {
    int on_path = 0;
    for (std::size_t k = 0; k < coordinates.size(); ++k)
      if (coordinates[k] == c)
        on_path = static_cast<int>(k) + 1;
    body += "  mq[" + std::to_string(c) + "] = " +
            (on_path ? "mc" + std::to_string(on_path) : "x[" + std::to_string(++free) + "]") +
            ";\n";
  }
  std::string on;
  for (const int c : coordinates)
    on += (on.empty() ? "x" : ", x") + std::to_string(c);
  result.text = "-- " + name + ": " + source + " along a " + (closed ? "closed " : "") +
                "polyline of " + std::to_string(points.size()) + " points through (" + on +
                ") as x" + std::to_string(t) + " goes 0 -> 1;\n-- projected along x" +
                std::to_string(t) + " it is the union of every shape on the path.\n" + name +
                "(x[" + std::to_string(t) + "], a[" + std::to_string(a_dim) + "])\n{\n" + body +
                "  " + name + " = " + source + "(mq, a);\n}\n";
  return result;
}

} // namespace frep::project
