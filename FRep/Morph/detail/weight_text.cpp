#include "Morph/detail/weight_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <sstream>

namespace frep::morph::weight_text
{
namespace
{

// Names of the axis x[c]'s scalars: mt (t clamped), ms (t (n - 1)), mu (the place in a
// segment), mw_i (the weights); the B-spline's mb_r, ml_j, mr_j, mq, mv (Cox-de Boor).
std::string v(const char* what, int c)
{
  return std::string(what) + std::to_string(c);
}
std::string v(const char* what, int c, int i)
{
  return v(what, c) + "_" + std::to_string(i);
}

std::string indent(int depth)
{
  return std::string(static_cast<std::size_t>(2 * depth), ' ');
}

// Segment i of Linear or Catmull-Rom, as lattice_weights.cpp's linear() and catmull_rom().
std::string segment(int c, int n, int i, Interpolation scheme, int depth)
{
  const std::string u = v("mu", c), in = indent(depth);
  std::string out = in + u + " = " + v("ms", c) + " - " + std::to_string(i) + ";\n";
  if (scheme == Interpolation::Linear)
  {
    out += in + v("mw", c, i) + " = 1 - " + u + ";\n";
    out += in + v("mw", c, i + 1) + " = " + u + ";\n";
    return out;
  }
  const std::string terms[4] = {
    "0.5*" + u + "*(-1 + " + u + "*(2 - " + u + "))",
    "0.5*(2 + " + u + "*" + u + "*(-5 + 3*" + u + "))",
    "0.5*" + u + "*(1 + " + u + "*(4 - 3*" + u + "))",
    "0.5*" + u + "*" + u + "*(" + u + " - 1)",
  };
  std::map<int, std::string> node; // the end segments repeat the end node: its terms add up
  for (int k = 0; k < 4; ++k)
  {
    const int at = std::clamp(i - 1 + k, 0, n - 1);
    node[at] += (node[at].empty() ? "" : " + ") + terms[k];
  }
  for (const auto& [at, sum] : node)
    out += in + v("mw", c, at) + " = " + sum + ";\n";
  return out;
}

// Knot k of the clamped uniform B-spline of degree p over n nodes, as text.
std::string knot(int k, int n, int p)
{
  if (k <= p)
    return "0";
  if (k >= n)
    return "1";
  return "(" + std::to_string(k - p) + "/" + std::to_string(n - p) + ")";
}

// The basis on knot span `span`, as lattice_weights.cpp's b_spline() (Cox-de Boor, unrolled).
std::string span_basis(int c, int n, int span, int depth)
{
  const int p = std::min(3, n - 1);
  const std::string in = indent(depth), t = v("mt", c), q = v("mq", c), saved = v("mv", c);
  std::string out = in + v("mb", c, 0) + " = 1;\n";
  for (int j = 1; j <= p; ++j)
  {
    out += in + v("ml", c, j) + " = " + t + " - " + knot(span + 1 - j, n, p) + ";\n";
    out += in + v("mr", c, j) + " = " + knot(span + j, n, p) + " - " + t + ";\n";
    out += in + saved + " = 0;\n";
    for (int r = 0; r < j; ++r)
    {
      out += in + q + " = " + v("mb", c, r) + "/(" + v("mr", c, r + 1) + " + " + v("ml", c, j - r) +
             ");\n";
      out += in + v("mb", c, r) + " = " + saved + " + " + v("mr", c, r + 1) + "*" + q + ";\n";
      out += in + saved + " = " + v("ml", c, j - r) + "*" + q + ";\n";
    }
    out += in + v("mb", c, j) + " = " + saved + ";\n";
  }
  for (int r = 0; r <= p; ++r)
    out += in + v("mw", c, span - p + r) + " = " + v("mb", c, r) + ";\n";
  return out;
}

// The chain "if <first test> then <first> else if ... else <last> endif; ...": `count` pieces,
// piece i chosen by test(i) (the last one needs none).
template<typename Test, typename Piece>
std::string chain(int count, int depth, const Test& test, const Piece& piece)
{
  std::string out;
  for (int i = 0; i + 1 < count; ++i)
  {
    out += indent(depth + i) + "if " + test(i) + " then\n" + piece(i, depth + i + 1) +
           indent(depth + i) + "else\n";
  }
  out += piece(count - 1, depth + count);
  for (int i = count - 2; i >= 0; --i)
    out += indent(depth + i) + "endif;\n";
  return out;
}

std::string interior(int c, int n, Interpolation scheme, int depth)
{
  if (scheme == Interpolation::BSpline)
  {
    const int p = std::min(3, n - 1);
    return chain(
      n - p,
      depth,
      [&](int i) { return v("mt", c) + " < " + knot(p + i + 1, n, p); },
      [&](int i, int at) { return span_basis(c, n, p + i, at); });
  }
  std::string out =
    indent(depth) + v("ms", c) + " = " + v("mt", c) + "*" + std::to_string(n - 1) + ";\n";
  return out + chain(
                 n - 1,
                 depth,
                 [&](int i) { return v("ms", c) + " < " + std::to_string(i + 1); },
                 [&](int i, int at) { return segment(c, n, i, scheme, at); });
}

// A number as a HyperFun literal: fixed notation (an exponent like e-05 is a syntax error, and
// the literal is read as digits over powers of 10 anyway: these are measurements, not exact).
std::string literal(double value)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.6f", std::fabs(value));
  return value < 0 ? std::string("(-") + text + ")" : std::string(text);
}

// u's remapping (timing.h's timing_curve), as text.
std::string curve_text(const Timing& timing, const std::string& u)
{
  switch (timing.curve)
  {
    case TimingCurve::Linear:
      return u;
    case TimingCurve::Ease:
      return u + "*" + u + "*(3 - 2*" + u + ")";
    case TimingCurve::EaseIn:
      return u + "*" + u;
    case TimingCurve::EaseOut:
      return u + "*(2 - " + u + ")";
    case TimingCurve::Hold:
      break;
  }
  return "min(max((" + u + " - " + literal(timing.hold / 2.0) + ")/" +
         literal(1.0 - timing.hold) + ", 0), 1)";
}

// t timed (timing.h's timed_parameter), for 0 < t < 1: mi the segment, mu the place in it.
std::string timing_statements(int c, int n, const Timing& timing, int depth)
{
  if (timing.curve == TimingCurve::Linear)
    return {};
  const std::string in = indent(depth), t = v("mt", c), s = v("ms", c), i = v("mi", c),
                    u = v("mu", c), last = std::to_string(n - 1), before = std::to_string(n - 2);
  return in + "-- timed: " + timing_name(timing) + " between neighbouring keys\n" + in + s +
         " = " + t + "*" + last + ";\n" + in + i + " = floor(" + s + ");\n" + in + "if " + i +
         " > " + before + " then\n" + in + "  " + i + " = " + before + ";\n" + in + "endif;\n" +
         in + u + " = " + s + " - " + i + ";\n" + in + u + " = " + curve_text(timing, u) + ";\n" +
         in + t + " = (" + i + " + " + u + ")/" + last + ";\n";
}

// The blend of the sub-lattice of axes 0..a at the higher axes' `offset`, as morph_text.h says.
std::string blend(int a, std::size_t offset, int d, const std::vector<int>& lattice)
{
  if (a < 0)
    return "mk" + std::to_string(offset);
  std::size_t stride = 1;
  for (int b = 0; b < a; ++b)
    stride *= static_cast<std::size_t>(lattice[static_cast<std::size_t>(b)]);
  std::string out;
  for (int i = 0; i < lattice[static_cast<std::size_t>(a)]; ++i)
  {
    const std::string part =
      blend(a - 1, offset + static_cast<std::size_t>(i) * stride, d, lattice);
    out += (i ? " + " : "") + (a == 0 ? part : "(" + part + ")") + "*" + v("mw", d + 1 + a, i);
  }
  return out;
}

// Key k's nodes' weights joined by `glue` ("*": the lattice weight; or a test per weight).
std::string key_weights(std::size_t k,
  int d,
  const std::vector<int>& lattice,
  const std::string& glue,
  const std::function<std::string(const std::string&)>& each)
{
  std::string joined;
  const std::vector<int> nodes = lattice_indices(k, lattice);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    joined += (a ? glue : "") + each(v("mw", d + 1 + static_cast<int>(a), nodes[a]));
  return joined;
}

// The moving frame (the keys' centroids, and sizes, blended with their weights) and each key's
// point my<k>[1..d]: where the key would be had it travelled (and grown) into the frame; at a
// corner (weight 1) x itself, so the corners stay the keys exactly.
std::string frame_statements(int d,
  Alignment alignment,
  const std::vector<KeyFrame>& frames)
{
  std::string out = "  -- the moving frame: the keys' centroids" +
                    std::string(alignment == Alignment::CentroidAndSize ? " and sizes" : "") +
                    ", blended with their weights\n";
  const auto blended = [&](const std::function<double(const KeyFrame&)>& of)
  {
    std::string sum;
    for (std::size_t k = 0; k < frames.size(); ++k)
      sum +=
        (k ? " + " : "") + std::string("mW") + std::to_string(k) + "*" + literal(of(frames[k]));
    return sum;
  };
  for (int i = 0; i < d; ++i)
    out += "  mc" + std::to_string(i + 1) + " = " +
           blended([i](const KeyFrame& f) { return f.centroid[static_cast<std::size_t>(i)]; }) +
           ";\n";
  if (alignment == Alignment::CentroidAndSize)
    out += "  msz = " + blended([](const KeyFrame& f) { return f.size; }) + ";\n";
  for (std::size_t k = 0; k < frames.size(); ++k)
  {
    const std::string my = "my" + std::to_string(k), W = "mW" + std::to_string(k);
    out += "  if " + W + " >= 1 then\n";
    for (int i = 1; i <= d; ++i)
      out += "    " + my + "[" + std::to_string(i) + "] = x[" + std::to_string(i) + "];\n";
    out += "  else\n";
    for (int i = 1; i <= d; ++i)
    {
      const std::string c = literal(frames[k].centroid[static_cast<std::size_t>(i - 1)]);
      out +=
        "    " + my + "[" + std::to_string(i) + "] = " + c + " + (x[" + std::to_string(i) +
        "] - mc" + std::to_string(i) + ")" +
        (alignment == Alignment::CentroidAndSize ? "*(" + literal(frames[k].size) + "/msz)" : "") +
        ";\n";
    }
    out += "  endif;\n";
  }
  return out;
}

// mW<k>, each key's lattice weight (the product of its nodes' axis weights); with key weights,
// times the key's own weight mg<k> (evaluated only where the key counts) and normalised to sum
// to 1. At a node the node's key has mg*1/(mg*1 + 0 + ...) = 1 exactly, the others 0.
std::string key_weight_statements(int d,
  const std::vector<int>& lattice,
  const std::vector<std::string>& expressions)
{
  const std::size_t keys = expressions.size();
  std::size_t count = 1;
  for (const int n : lattice)
    count *= static_cast<std::size_t>(n);
  std::string out = "  -- each key's lattice weight\n";
  for (std::size_t k = 0; k < count; ++k)
    out += "  mW" + std::to_string(k) + " = " +
           key_weights(k, d, lattice, "*", [](const std::string& w) { return w; }) + ";\n";
  if (keys == 0)
    return out;
  out += "  -- times the keys' own weights (at least 0.001), normalised to sum to 1\n";
  std::string sum;
  for (std::size_t k = 0; k < keys; ++k)
  {
    const std::string g = "mg" + std::to_string(k), W = "mW" + std::to_string(k);
    if (expressions[k].empty())
      out += "  " + g + " = 1;\n";
    else
      out += "  " + g + " = 0;\n  if " + W + " < 0 or " + W + " > 0 then\n    " + g +
             " = max(" + expressions[k] + ", 0.001);\n  endif;\n";
    sum += (k ? " + " : "") + g + "*" + W;
  }
  out += "  msum = " + sum + ";\n";
  for (std::size_t k = 0; k < keys; ++k)
    out += "  mW" + std::to_string(k) + " = mg" + std::to_string(k) + "*mW" + std::to_string(k) +
           "/msum;\n";
  return out;
}

// The blend with key weights: sum of mW<k> mk<k> (mW normalised by key_weight_statements).
std::string weighted_blend(std::size_t keys)
{
  std::string out;
  for (std::size_t k = 0; k < keys; ++k)
    out += (k ? " + " : "") + std::string("mW") + std::to_string(k) + "*mk" + std::to_string(k);
  return out;
}

// Key k's value normalised by distance: F, plus the sampled distance beyond the band on F's own
// side, so the sign (F >= 0 or not) is F's exactly: inside, F + max(D - band, 0) >= F >= 0;
// outside, F + min(D + band, 0) <= F < 0.
std::string normalised_call(std::size_t k,
  const std::string& key,
  const std::string& point,
  const KeyNormal& normal)
{
  const std::string mk = "mk" + std::to_string(k), md = "md" + std::to_string(k);
  const std::string band = literal(normal.band);
  return "    " + mk + " = " + key + "(" + point + ", a);\n    " + md + " = " + normal.function +
         "(" + point + ");\n    if " + mk + " >= 0 then\n      " + mk + " = " + mk + " + max(" +
         md + " - " + band + ", 0);\n    else\n      " + mk + " = " + mk + " + min(" + md + " + " +
         band + ", 0);\n    endif;\n";
}

} // namespace

std::vector<int> lattice_indices(std::size_t k, const std::vector<int>& lattice)
{
  std::vector<int> nodes;
  for (const int n : lattice)
  {
    nodes.push_back(static_cast<int>(k % static_cast<std::size_t>(n)));
    k /= static_cast<std::size_t>(n);
  }
  return nodes;
}

std::string node_value(int i, int n)
{
  std::ostringstream out;
  out.precision(4);
  out << static_cast<double>(i) / (n - 1);
  return out.str();
}

std::string axis_statements(int c, int n, Interpolation scheme, const Timing& timing)
{
  const std::string t = v("mt", c);
  std::string out = "  -- the weights along x[" + std::to_string(c) + "] (" + std::to_string(n) +
                    " nodes, " + std::string(interpolation_name(scheme)) + ")\n";
  out += "  " + t + " = x[" + std::to_string(c) + "];\n";
  for (int i = 0; i < n; ++i)
    out += "  " + v("mw", c, i) + " = 0;\n";
  out += "  if " + t + " <= 0 then\n    " + v("mw", c, 0) + " = 1;\n  else\n";
  out += "    if " + t + " >= 1 then\n      " + v("mw", c, n - 1) + " = 1;\n    else\n";
  out += timing_statements(c, n, timing, 3);
  out += interior(c, n, scheme, 3);
  out += "    endif;\n  endif;\n";
  return out;
}

std::string body(const Body& spec)
{
  const std::vector<std::string>& keys = spec.keys;
  const bool aligned = spec.alignment != Alignment::None && spec.frames.size() == keys.size();
  const bool weighted = spec.key_weights.size() == keys.size() &&
                        std::any_of(spec.key_weights.begin(),
                          spec.key_weights.end(),
                          [](const std::string& e) { return !e.empty(); });
  std::string out = "  array mx[" + std::to_string(spec.d) + "]";
  for (std::size_t k = 0; aligned && k < keys.size(); ++k)
    out += ", my" + std::to_string(k) + "[" + std::to_string(spec.d) + "]";
  out += ";\n";
  for (int k = 1; k <= spec.d; ++k)
    out += "  mx[" + std::to_string(k) + "] = x[" + std::to_string(k) + "];\n";
  for (std::size_t a = 0; a < spec.lattice.size(); ++a)
    out += axis_statements(
      spec.d + 1 + static_cast<int>(a), spec.lattice[a], spec.scheme, spec.timing);
  if (aligned || weighted)
    out += key_weight_statements(
      spec.d, spec.lattice, weighted ? spec.key_weights : std::vector<std::string>{});
  if (aligned)
    out += frame_statements(spec.d, spec.alignment, spec.frames);
  out += "  -- the keys, each called where its weight is not 0\n";
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    // Exact tests: HyperFun's /= has a tolerance of 1e-6.
    const std::string test = key_weights(k,
      spec.d,
      spec.lattice,
      " and ",
      [](const std::string& w) { return "(" + w + " < 0 or " + w + " > 0)"; });
    const std::string mk = "mk" + std::to_string(k);
    const std::string point = aligned ? "my" + std::to_string(k) : std::string("mx");
    const std::string scale = aligned && spec.alignment == Alignment::CentroidAndSize
                                ? "*(msz/" + literal(spec.frames[k].size) + ")"
                                : std::string();
    out += "  " + mk + " = 0;\n  if " + test + " then\n";
    if (spec.normals.size() == keys.size())
      out += normalised_call(k, keys[k], point, spec.normals[k]) +
             (scale.empty() ? std::string() : "    " + mk + " = " + mk + scale + ";\n");
    else
      out += "    " + mk + " = " + keys[k] + "(" + point + ", a)" + scale + ";\n";
    out += "  endif;\n";
  }
  const std::string blended = weighted
                                ? weighted_blend(keys.size())
                                : blend(static_cast<int>(spec.lattice.size()) - 1, 0, spec.d, spec.lattice);
  out += "  " + spec.name + " = " + blended + ";\n";
  return out;
}

} // namespace frep::morph::weight_text
