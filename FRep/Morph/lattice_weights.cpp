#include "Morph/lattice_weights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace frep::morph
{
namespace
{

constexpr std::size_t kMaxKeys = std::size_t(1) << 20; // a lattice larger than this is a mistake

// The segment [i, i + 1] of an axis of n nodes holding t in [0, 1], and t's place u in it.
// At a node (s an integer) u is exactly 0, at t = 1 the last segment with u exactly 1.
void segment_of(int n, double t, int& i, double& u)
{
  const double s = t * static_cast<double>(n - 1);
  i = std::min(static_cast<int>(std::floor(s)), n - 2);
  u = s - static_cast<double>(i);
}

void linear(std::vector<double>& w, double t)
{
  int i;
  double u;
  segment_of(static_cast<int>(w.size()), t, i, u);
  w[static_cast<std::size_t>(i)] = 1.0 - u;
  w[static_cast<std::size_t>(i) + 1] += u;
}

// Written so that u = 0 gives exactly (0, 1, 0, 0) and u = 1 exactly (0, 0, 1, 0).
void catmull_rom(std::vector<double>& w, double t)
{
  const int n = static_cast<int>(w.size());
  int i;
  double u;
  segment_of(n, t, i, u);
  const double before = 0.5 * u * (-1.0 + u * (2.0 - u));
  const double from = 0.5 * (2.0 + u * u * (-5.0 + 3.0 * u));
  const double to = 0.5 * u * (1.0 + u * (4.0 - 3.0 * u));
  const double after = 0.5 * u * u * (u - 1.0);
  const auto at = [&](int k) -> double&
  { return w[static_cast<std::size_t>(std::clamp(k, 0, n - 1))]; };
  at(i - 1) += before;
  at(i) += from;
  at(i + 1) += to;
  at(i + 2) += after;
}

// The clamped uniform B-spline basis of degree p = min(3, n - 1) by Cox-de Boor (Piegl and
// Tiller's BasisFuns). The ends are set exactly by the caller.
void b_spline(std::vector<double>& w, double t)
{
  const int n = static_cast<int>(w.size());
  const int p = std::min(3, n - 1);
  std::vector<double> knots; // p + 1 zeros, the inner knots, p + 1 ones
  knots.assign(static_cast<std::size_t>(p) + 1, 0.0);
  for (int j = 1; j < n - p; ++j)
  {
    knots.push_back(static_cast<double>(j) / static_cast<double>(n - p));
  }
  knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, 1.0);
  int span = p; // knots[span] <= t < knots[span + 1]
  while (span < n - 1 && t >= knots[static_cast<std::size_t>(span) + 1])
  {
    ++span;
  }
  std::vector<double> basis(static_cast<std::size_t>(p) + 1, 0.0);
  std::vector<double> left(basis.size()), right(basis.size());
  basis[0] = 1.0;
  for (int j = 1; j <= p; ++j)
  {
    left[static_cast<std::size_t>(j)] = t - knots[static_cast<std::size_t>(span + 1 - j)];
    right[static_cast<std::size_t>(j)] = knots[static_cast<std::size_t>(span + j)] - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r)
    {
      const double temp =
        basis[static_cast<std::size_t>(r)] /
        (right[static_cast<std::size_t>(r + 1)] + left[static_cast<std::size_t>(j - r)]);
      basis[static_cast<std::size_t>(r)] = saved + right[static_cast<std::size_t>(r + 1)] * temp;
      saved = left[static_cast<std::size_t>(j - r)] * temp;
    }
    basis[static_cast<std::size_t>(j)] = saved;
  }
  for (int r = 0; r <= p; ++r)
  {
    w[static_cast<std::size_t>(span - p + r)] = basis[static_cast<std::size_t>(r)];
  }
}

} // namespace

std::optional<Interpolation> interpolation_from_name(std::string_view name)
{
  if (name == "linear")
    return Interpolation::Linear;
  if (name == "catmull-rom")
    return Interpolation::CatmullRom;
  if (name == "b-spline")
    return Interpolation::BSpline;
  return std::nullopt;
}

std::string_view interpolation_name(Interpolation scheme)
{
  switch (scheme)
  {
    case Interpolation::Linear:
      return "linear";
    case Interpolation::CatmullRom:
      return "catmull-rom";
    case Interpolation::BSpline:
      return "b-spline";
  }
  return "linear";
}

std::vector<double> axis_weights(Interpolation scheme, int nodes, double t)
{
  if (nodes < 2 || static_cast<std::size_t>(nodes) > kMaxKeys)
  {
    throw std::invalid_argument("a lattice axis needs 2 to " + std::to_string(kMaxKeys) +
                                " nodes (this one has " + std::to_string(nodes) + ")");
  }
  std::vector<double> w(static_cast<std::size_t>(nodes), 0.0);
  if (std::isnan(t))
  {
    std::fill(w.begin(), w.end(), std::numeric_limits<double>::quiet_NaN());
    return w;
  }
  t = std::clamp(t, 0.0, 1.0);
  if (t == 0.0 || t == 1.0) // the end keys, exactly, in every scheme
  {
    w[t == 0.0 ? 0 : w.size() - 1] = 1.0;
    return w;
  }
  switch (scheme)
  {
    case Interpolation::Linear:
      linear(w, t);
      break;
    case Interpolation::CatmullRom:
      catmull_rom(w, t);
      break;
    case Interpolation::BSpline:
      b_spline(w, t);
      break;
  }
  return w;
}

std::vector<double> lattice_weights(Interpolation scheme,
  std::span<const int> nodes,
  std::span<const double> t)
{
  if (nodes.empty() || nodes.size() != t.size())
  {
    throw std::invalid_argument("a lattice needs one parameter per axis (" +
                                std::to_string(nodes.size()) + " axes, " +
                                std::to_string(t.size()) + " parameters)");
  }
  std::size_t keys = 1;
  for (const int n : nodes)
  {
    if (n < 2 || keys * static_cast<std::size_t>(n) > kMaxKeys)
    {
      (void)axis_weights(scheme, n, 0.0); // the axis's own message for n < 2
      throw std::invalid_argument("a lattice of more than " + std::to_string(kMaxKeys) + " keys");
    }
    keys *= static_cast<std::size_t>(n);
  }
  std::vector<double> w = axis_weights(scheme, nodes[0], t[0]);
  for (std::size_t a = 1; a < nodes.size(); ++a) // the first axis fastest
  {
    const std::vector<double> along = axis_weights(scheme, nodes[a], t[a]);
    std::vector<double> next;
    next.reserve(w.size() * along.size());
    for (const double outer : along)
    {
      for (const double inner : w)
      {
        next.push_back(inner * outer);
      }
    }
    w = std::move(next);
  }
  return w;
}

} // namespace frep::morph
