#include "Project/detail/path_text.h"

#include <cmath>
#include <cstdio>

namespace frep::project::detail
{
namespace
{

std::string u_name(std::size_t piece)
{
  return "mu" + std::to_string(piece + 1);
}

// c(u) - c(0) as text, or "" when it is 0 (a coordinate the piece does not move). A cubic is
// written about its middle, s = u - 1/2: c(u) - c(0) = (c(1/2) - c(0)) + s (d1 + s (d2 + s d3)),
// whose enclosure over a box of s near s0 is wider than the true range by about
// w (2 |d2 s0| + 3 |d3| s0^2), a quarter of the powers of u's (|s0| <= 1/2): a point's search
// needs about a third fewer boxes along the animation's Catmull-Rom path.
std::string rise(const std::array<double, 4>& c, const std::string& u)
{
  if (c[2] == 0.0 && c[3] == 0.0)
    return c[1] == 0.0 ? std::string() : u + "*" + hf_literal(c[1]);
  const double d0 = piece_value(c, 0.5) - c[0], d1 = piece_slope(c, 0.5);
  const double d2 = c[2] + 1.5 * c[3], d3 = c[3];
  const std::string s = "(" + u + " - 0.5)";
  return hf_literal(d0) + " + " + s + "*(" + hf_literal(d1) + " + " + s + "*(" + hf_literal(d2) +
         " + " + s + "*" + hf_literal(d3) + "))";
}

// c'(u) - c'(0) as text, or "".
std::string slope_rise(const std::array<double, 4>& c, const std::string& u)
{
  if (c[2] == 0.0 && c[3] == 0.0)
    return {};
  if (c[3] == 0.0)
    return u + "*" + hf_literal(2 * c[2]);
  return u + "*(" + hf_literal(2 * c[2]) + " + " + u + "*" + hf_literal(3 * c[3]) + ")";
}

std::string slope(const std::array<double, 4>& c, const std::string& u)
{
  const std::string r = slope_rise(c, u);
  return r.empty() ? hf_literal(c[1]) : hf_literal(c[1]) + " + " + r;
}

// Whether the path's slope is continuous where piece i - 1 meets piece i.
bool smooth_joint(const PathPiece& before, const PathPiece& after)
{
  for (std::size_t a = 0; a < after.size(); ++a)
  {
    const double left = piece_slope(before[a], 1.0), right = after[a][1];
    if (std::fabs(left - right) > 1e-9 * (1.0 + std::fabs(right)))
      return false;
  }
  return true;
}

} // namespace

std::string hf_literal(double v)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.9f", std::fabs(v));
  return v < 0 ? std::string("(-") + text + ")" : std::string(text);
}

std::string path_position_text(const std::vector<PathPiece>& pieces, const std::string& parameter,
  const std::vector<std::string>& names)
{
  const std::size_t n = pieces.size();
  std::string out = "  mt = min(max(" + parameter + ", 0), 1);\n  ms = mt*" +
                    std::to_string(n) + ";\n";
  for (std::size_t i = 0; i < n; ++i)
    out += "  " + u_name(i) + " = min(max(ms - " + std::to_string(i) + ", 0), 1);\n";
  for (std::size_t a = 0; a < names.size(); ++a)
  {
    out += "  " + names[a] + " = " + hf_literal(pieces[0][a][0]) + ";\n";
    for (std::size_t i = 0; i < n; ++i)
      if (const std::string r = rise(pieces[i][a], u_name(i)); !r.empty())
        out += "  " + names[a] + " = " + names[a] + " + " + r + ";\n";
  }
  return out;
}

std::string path_slope_text(
  const std::vector<PathPiece>& pieces, const std::vector<std::string>& names)
{
  std::string out;
  for (std::size_t a = 0; a < names.size(); ++a)
  {
    out += "  " + names[a] + " = " + slope(pieces[0][a], u_name(0)) + ";\n";
    for (std::size_t i = 1; i < pieces.size(); ++i)
    {
      if (!smooth_joint(pieces[i - 1], pieces[i]))
        out += "  if ms >= " + std::to_string(i) + " then\n    " + names[a] + " = " +
               slope(pieces[i][a], u_name(i)) + ";\n  endif;\n";
      else if (const std::string r = slope_rise(pieces[i][a], u_name(i)); !r.empty())
        out += "  " + names[a] + " = " + names[a] + " + " + r + ";\n";
    }
  }
  return out;
}

} // namespace frep::project::detail
