// The mapping file's reader: load_mapping, section by section, every problem reported at its
// place in the document. The writer is mapping_json_writer.cpp.
#include "Mapping/mapping_json.h"

#include "Mapping/detail/mapping_json_names.h"
#include "Mapping/colour_maps.h"
#include "Mapping/path.h"
#include "Mapping/unit_map.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

namespace frep::mapping
{
namespace
{

using namespace json_names;

// Limits that keep a typo from asking for absurd amounts of memory later.
constexpr int max_resolution = 8192;
constexpr int max_picture_size = 16384;
constexpr int max_voice = 63;
constexpr std::size_t max_node_values = 10000;

std::string join(const std::string& place, std::string_view key)
{
  return place.empty() ? std::string(key) : place + "." + std::string(key);
}

std::string at(const std::string& place, std::size_t index)
{
  return place + "[" + std::to_string(index) + "]";
}

// The typed field access every section reader shares: each helper checks one JSON value,
// reports a problem at its place in the document ("coordinates.x4[0].range", "render.width")
// and then returns nullopt; the errors are collected in order.
class Reader
{
public:
  std::vector<PlanError> errors;

  void error(std::string place, std::string message)
  {
    errors.push_back({ std::move(place), std::move(message) });
  }

  /// j must be an object whose keys are all in `allowed`.
  bool object(const Json& j,
    const std::string& place,
    std::initializer_list<std::string_view> allowed)
  {
    if (!j.is_object())
    {
      error(place, std::string("expected an object, found ") + j.type_name());
      return false;
    }
    for (const auto& item : j.items())
    {
      if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
      {
        std::string list;
        for (std::string_view a : allowed)
        {
          list += (list.empty() ? "" : ", ") + std::string(a);
        }
        error(
          join(place, item.key()), "unknown key \"" + item.key() + "\" (expected " + list + ")");
      }
    }
    return true;
  }

  /// j[key], or null after reporting it missing at place.key ("missing (expected ...)").
  const Json* required(const Json& j,
    const std::string& place,
    std::string_view key,
    std::string_view expected)
  {
    const auto it = j.find(std::string(key));
    if (it == j.end())
    {
      error(join(place, key),
        "missing" +
          (expected.empty() ? std::string() : " (expected " + std::string(expected) + ")"));
      return nullptr;
    }
    return &*it;
  }

  std::optional<double> number(const Json& j, const std::string& place)
  {
    if (!j.is_number())
    {
      error(place, std::string("expected a number, found ") + j.type_name());
      return std::nullopt;
    }
    const double v = j.get<double>();
    if (!std::isfinite(v))
    {
      error(place, "expected a finite number");
      return std::nullopt;
    }
    return v;
  }

  std::optional<double> positive(const Json& j, const std::string& place)
  {
    const std::optional<double> v = number(j, place);
    if (v && !(*v > 0))
    {
      error(place, "must be > 0");
      return std::nullopt;
    }
    return v;
  }

  std::optional<int> integer(const Json& j, const std::string& place, int lo, int hi)
  {
    const std::optional<double> v = number(j, place);
    if (!v)
    {
      return std::nullopt;
    }
    if (*v != std::floor(*v))
    {
      error(place, "expected a whole number");
      return std::nullopt;
    }
    if (*v < lo || *v > hi)
    {
      error(place, "must be from " + std::to_string(lo) + " to " + std::to_string(hi));
      return std::nullopt;
    }
    return static_cast<int>(*v);
  }

  std::optional<bool> boolean(const Json& j, const std::string& place)
  {
    if (!j.is_boolean())
    {
      error(place, std::string("expected true or false, found ") + j.type_name());
      return std::nullopt;
    }
    return j.get<bool>();
  }

  std::optional<std::string> string(const Json& j, const std::string& place)
  {
    if (!j.is_string())
    {
      error(place, std::string("expected a string, found ") + j.type_name());
      return std::nullopt;
    }
    return j.get<std::string>();
  }

  template<typename E, std::size_t N>
  std::optional<E> choice(const Json& j,
    const std::string& place,
    std::string_view what,
    const Name<E> (&names)[N])
  {
    const std::optional<std::string> s = string(j, place);
    if (!s)
    {
      return std::nullopt;
    }
    for (const auto& n : names)
    {
      if (n.name == *s)
      {
        return n.value;
      }
    }
    error(place,
      "unknown " + std::string(what) + " \"" + *s + "\" (expected " + name_list(names) + ")");
    return std::nullopt;
  }

  std::optional<std::vector<double>> numbers(const Json& j, const std::string& place)
  {
    if (!j.is_array())
    {
      error(place, std::string("expected an array of numbers, found ") + j.type_name());
      return std::nullopt;
    }
    std::vector<double> values;
    bool ok = true;
    for (std::size_t k = 0; k < j.size(); ++k)
    {
      const std::optional<double> v = number(j[k], at(place, k));
      ok = ok && v.has_value();
      values.push_back(v.value_or(0.0));
    }
    return ok ? std::optional(values) : std::nullopt;
  }

  template<std::size_t N>
  std::optional<std::array<double, N>> fixed_numbers(const Json& j, const std::string& place)
  {
    const std::optional<std::vector<double>> v = numbers(j, place);
    if (!v)
    {
      return std::nullopt;
    }
    if (v->size() != N)
    {
      error(
        place, "expected " + std::to_string(N) + " numbers, found " + std::to_string(v->size()));
      return std::nullopt;
    }
    std::array<double, N> a{};
    std::copy(v->begin(), v->end(), a.begin());
    return a;
  }

  /// [lo, hi]; a range must have lo < hi, a target may run either way.
  std::optional<Interval> interval(const Json& j, const std::string& place, bool increasing)
  {
    const auto v = fixed_numbers<2>(j, place);
    if (!v)
    {
      return std::nullopt;
    }
    if (increasing && !((*v)[0] < (*v)[1]))
    {
      error(place, "lo must be < hi");
      return std::nullopt;
    }
    return Interval{ (*v)[0], (*v)[1] };
  }

  std::optional<std::array<double, 3>> rgb(const Json& j, const std::string& place)
  {
    const auto v = fixed_numbers<3>(j, place);
    if (v && std::any_of(v->begin(), v->end(), [](double c) { return c < 0 || c > 1; }))
    {
      error(place, "colour components must be in [0, 1]");
      return std::nullopt;
    }
    return v;
  }
};

// Reads j[key] with `read` into `out` when the key is present.
template<typename T, typename F>
void optional_key(const Json& j, std::string_view key, const std::string& place, T& out, F read)
{
  const auto it = j.find(std::string(key));
  if (it != j.end())
  {
    if (auto v = read(*it, join(place, key)))
    {
      out = *v;
    }
  }
}

// --- curves -------------------------------------------------------------------------------------

// A curve by name: "linear" or "ease-in-out".
std::optional<Curve> read_curve_name(Reader& r, const std::string& s, const std::string& place)
{
  Curve curve;
  if (s == "linear")
  {
    return curve;
  }
  if (s == "ease-in-out")
  {
    curve.kind = Curve::Kind::EaseInOut;
    return curve;
  }
  r.error(place,
    "unknown curve \"" + s +
      "\" (expected linear, ease-in-out, or an object with kind power, table or expression)");
  return std::nullopt;
}

// { "kind": "power", "exponent": e }
bool read_power_curve(Reader& r, const Json& j, const std::string& place, Curve& curve)
{
  r.object(j, place, { "kind", "exponent" });
  curve.kind = Curve::Kind::Power;
  const Json* e = r.required(j, place, "exponent", "");
  const std::optional<double> v = e ? r.number(*e, join(place, "exponent")) : std::nullopt;
  curve.exponent = v.value_or(curve.exponent);
  return v.has_value();
}

// { "kind": "table", "points": [[u, v], ...] }
bool read_table_curve(Reader& r, const Json& j, const std::string& place, Curve& curve)
{
  r.object(j, place, { "kind", "points" });
  curve.kind = Curve::Kind::Table;
  const auto p = j.find("points");
  const std::string pp = join(place, "points");
  if (p == j.end() || !p->is_array())
  {
    r.error(pp, p == j.end() ? "missing" : "expected an array of [u, v] pairs");
    return false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < p->size(); ++i)
  {
    const auto point = r.fixed_numbers<2>((*p)[i], at(pp, i));
    ok = ok && point.has_value();
    curve.table.push_back(point.value_or(std::array<double, 2>{}));
  }
  return ok;
}

// { "kind": "expression", "expression": "..." }
bool read_expression_curve(Reader& r, const Json& j, const std::string& place, Curve& curve)
{
  r.object(j, place, { "kind", "expression" });
  curve.kind = Curve::Kind::Expression;
  const Json* e = r.required(j, place, "expression", "");
  const std::optional<std::string> s = e ? r.string(*e, join(place, "expression")) : std::nullopt;
  curve.expression = s.value_or("");
  return s.has_value();
}

// The curve kinds that take a value, with the key a curve error belongs to.
struct CurveKind
{
  std::string_view name;
  std::string_view detail_key;
  bool (*read)(Reader&, const Json&, const std::string&, Curve&);
};
constexpr CurveKind curve_kinds[] = {
  { "power", "exponent", read_power_curve },
  { "table", "points", read_table_curve },
  { "expression", "expression", read_expression_curve },
};

std::optional<Curve> read_curve(Reader& r, const Json& j, const std::string& place)
{
  if (j.is_string())
  {
    return read_curve_name(r, j.get<std::string>(), place);
  }
  if (!j.is_object())
  {
    r.error(place, std::string("expected a curve name or object, found ") + j.type_name());
    return std::nullopt;
  }
  const Json* kind = r.required(j, place, "kind", "linear, ease-in-out, power, table, expression");
  const std::optional<std::string> k = kind ? r.string(*kind, join(place, "kind")) : std::nullopt;
  if (!k)
  {
    return std::nullopt;
  }
  Curve curve;
  if (*k == "linear" || *k == "ease-in-out")
  {
    r.object(j, place, { "kind" });
    curve.kind = *k == "linear" ? Curve::Kind::Linear : Curve::Kind::EaseInOut;
    return curve;
  }
  for (const CurveKind& c : curve_kinds)
  {
    if (c.name != *k)
    {
      continue;
    }
    if (!c.read(r, j, place, curve))
    {
      return std::nullopt;
    }
    // The curve itself: exponent > 0, a table from u = 0 to 1, an expression that compiles.
    const UnitCurve::Result checked = UnitCurve::make(curve);
    if (!checked.ok())
    {
      r.error(join(place, c.detail_key), checked.error);
      return std::nullopt;
    }
    return curve;
  }
  r.error(join(place, "kind"),
    "unknown curve kind \"" + *k + "\" (expected linear, ease-in-out, power, table, expression)");
  return std::nullopt;
}

// --- channels -----------------------------------------------------------------------------------

// Node values from "step" over the range, lo to hi inclusive. The last value is hi exactly
// when (hi - lo) / step is a whole number up to 1e-9 (0.1 steps would otherwise drift past it).
std::optional<std::vector<double>> step_values(Reader& r,
  Interval range,
  double step,
  const std::string& place)
{
  if (!(step > 0))
  {
    r.error(place, "must be > 0");
    return std::nullopt;
  }
  const double count = (range.hi - range.lo) / step;
  if (!(count < static_cast<double>(max_node_values)))
  {
    r.error(place, "more than " + std::to_string(max_node_values) + " node values");
    return std::nullopt;
  }
  const double whole = std::round(count);
  const bool exact = std::abs(count - whole) <= 1e-9 * std::max(1.0, whole);
  const auto n = static_cast<std::size_t>(exact ? whole : std::floor(count));
  std::vector<double> values;
  for (std::size_t k = 0; k <= n; ++k)
  {
    values.push_back(range.lo + static_cast<double>(k) * step);
  }
  if (exact)
  {
    values.back() = range.hi;
  }
  return values;
}

// Every channel may have range, curve and target; the other keys depend on its type.
void check_channel_keys(Reader& r, const Json& j, const std::string& place, Channel::Type type)
{
  switch (type)
  {
    case Channel::Type::World:
      r.object(j, place, { "type", "range", "curve", "target", "axis" });
      break;
    case Channel::Type::Dynamic:
      r.object(j, place, { "type", "range", "curve", "target" });
      break;
    case Channel::Type::Spreadsheet:
      r.object(j, place, { "type", "range", "curve", "target", "axis", "step", "values" });
      break;
    case Channel::Type::Fixed:
      r.object(j, place, { "type", "range", "curve", "target", "value" });
      break;
    case Channel::Type::Colour:
      r.object(j, place, { "type", "range", "curve", "target", "colormap", "applies_to" });
      break;
    case Channel::Type::Transparency:
      r.object(j, place, { "type", "range", "curve", "target", "applies_to" });
      break;
    case Channel::Type::Transformation:
      r.object(j, place, { "type", "range", "curve", "target", "transform", "vector" });
      break;
    case Channel::Type::Audio:
      r.object(j, place, { "type", "range", "curve", "target", "parameter", "voice" });
      break;
    case Channel::Type::Projected: // no curve, no target: nothing is mapped
      r.object(j, place, { "type", "range", "tolerance" });
      break;
  }
}

// range, target and curve: the keys every channel type shares.
void read_channel_map(Reader& r, const Json& j, const std::string& place, Channel& c)
{
  optional_key(j,
    "range",
    place,
    c.range,
    [&](const Json& v, const std::string& p) { return r.interval(v, p, true); });
  optional_key(j,
    "target",
    place,
    c.target,
    [&](const Json& v, const std::string& p) { return r.interval(v, p, false); });
  optional_key(j,
    "curve",
    place,
    c.curve,
    [&](const Json& v, const std::string& p) { return read_curve(r, v, p); });
}

// "world": the axis of the world system (x, y, z; r, phi, z; r, theta, phi).
void read_world_channel(Reader& r,
  const Json& j,
  const std::string& place,
  WorldSystem system,
  Channel& c)
{
  const auto& axes = system == WorldSystem::Cartesian     ? cartesian_axes
                     : system == WorldSystem::Cylindrical ? cylindrical_axes
                                                          : spherical_axes;
  const std::string what = name_of(world_systems, system) + " axis";
  if (const Json* a = r.required(j, place, "axis", name_list(axes)))
  {
    if (auto v = r.choice(*a, join(place, "axis"), what, axes))
    {
      c.axis = *v;
    }
  }
}

// A spreadsheet channel's node values: "values", or "step" over the range.
void read_node_values(Reader& r, const Json& j, const std::string& place, Channel& c)
{
  const bool has_step = j.contains("step");
  const bool has_values = j.contains("values");
  if (has_step == has_values)
  {
    r.error(place,
      has_step ? "give either \"step\" or \"values\", not both"
               : "the node values are missing: give \"step\" (with a range) or \"values\"");
  }
  else if (has_values)
  {
    if (auto v = r.numbers(j["values"], join(place, "values")))
    {
      if (v->empty())
      {
        r.error(join(place, "values"), "at least one value is needed");
      }
      else if (v->size() > max_node_values)
      {
        r.error(join(place, "values"), "more than " + std::to_string(max_node_values) + " values");
      }
      c.values = *v;
    }
  }
  else if (auto step = r.number(j["step"], join(place, "step")))
  {
    if (!j.contains("range"))
    {
      r.error(join(place, "step"), "needs a \"range\" to step over");
    }
    else if (c.range)
    {
      if (auto v = step_values(r, *c.range, *step, join(place, "step")))
      {
        c.values = *v;
      }
    }
  }
}

// "spreadsheet": the grid axis and the node values.
void read_spreadsheet_channel(Reader& r, const Json& j, const std::string& place, Channel& c)
{
  if (const Json* a = r.required(j, place, "axis", "columns, rows, layers"))
  {
    if (auto v = r.choice(*a, join(place, "axis"), "spreadsheet axis", grid_axes))
    {
      c.grid_axis = *v;
    }
  }
  read_node_values(r, j, place, c);
}

// "fixed": the value.
void read_fixed_channel(Reader& r, const Json& j, const std::string& place, Channel& c)
{
  if (const Json* v = r.required(j, place, "value", ""))
  {
    if (auto x = r.number(*v, join(place, "value")))
    {
      c.value = *x;
    }
  }
}

// "projected": the tolerance (optional, > 0).
void read_projected_channel(Reader& r, const Json& j, const std::string& place, Channel& c)
{
  const auto t = j.find("tolerance");
  if (t == j.end())
  {
    return;
  }
  if (auto x = r.number(*t, join(place, "tolerance")))
  {
    if (*x > 0.0)
    {
      c.tolerance = *x;
    }
    else
    {
      r.error(join(place, "tolerance"), "must be > 0");
    }
  }
}

// "colour" (a colour map) and "transparency": what they apply to.
void read_photometric_channel(Reader& r, const Json& j, const std::string& place, Channel& c)
{
  if (c.type == Channel::Type::Colour)
  {
    optional_key(j,
      "colormap",
      place,
      c.colormap,
      [&](const Json& v, const std::string& p) -> std::optional<std::string>
      {
        auto s = r.string(v, p);
        if (s && !is_colour_channel_name(*s))
        {
          r.error(p, "unknown colour map \"" + *s + "\" (expected " + colour_channel_names() + ")");
          return std::nullopt;
        }
        return s;
      });
  }
  optional_key(j,
    "applies_to",
    place,
    c.applies_to,
    [&](const Json& v, const std::string& p)
    { return r.choice(v, p, "target of the channel", photometric_targets); });
}

// "transformation": the transform and its (non-zero) vector.
void read_transformation_channel(Reader& r, const Json& j, const std::string& place, Channel& c)
{
  optional_key(j,
    "transform",
    place,
    c.transform,
    [&](const Json& v, const std::string& p) { return r.choice(v, p, "transform", transforms); });
  optional_key(j,
    "vector",
    place,
    c.vector,
    [&](const Json& v, const std::string& p) -> std::optional<std::array<double, 3>>
    {
      auto a = r.fixed_numbers<3>(v, p);
      if (a && (*a)[0] == 0 && (*a)[1] == 0 && (*a)[2] == 0)
      {
        r.error(p, "the vector must not be zero");
        return std::nullopt;
      }
      return a;
    });
}

// "audio": the parameter and the voice.
void read_audio_channel(Reader& r, const Json& j, const std::string& place, Channel& c)
{
  optional_key(j,
    "parameter",
    place,
    c.audio_parameter,
    [&](const Json& v, const std::string& p)
    { return r.choice(v, p, "audio parameter", audio_parameters); });
  optional_key(j,
    "voice",
    place,
    c.voice,
    [&](const Json& v, const std::string& p) { return r.integer(v, p, 0, max_voice); });
}

std::optional<Channel> read_channel(Reader& r,
  const Json& j,
  const std::string& place,
  WorldSystem system)
{
  if (!j.is_object())
  {
    r.error(place, std::string("expected a channel object, found ") + j.type_name());
    return std::nullopt;
  }
  const Json* type = r.required(j, place, "type", name_list(channel_types));
  const std::optional<Channel::Type> t =
    type ? r.choice(*type, join(place, "type"), "type", channel_types) : std::nullopt;
  if (!t)
  {
    return std::nullopt;
  }
  Channel c;
  c.type = *t;
  const std::size_t errors_before = r.errors.size();
  check_channel_keys(r, j, place, c.type);
  read_channel_map(r, j, place, c);
  switch (c.type)
  {
    case Channel::Type::World:
      read_world_channel(r, j, place, system, c);
      break;
    case Channel::Type::Spreadsheet:
      read_spreadsheet_channel(r, j, place, c);
      break;
    case Channel::Type::Fixed:
      read_fixed_channel(r, j, place, c);
      break;
    case Channel::Type::Colour:
    case Channel::Type::Transparency:
      read_photometric_channel(r, j, place, c);
      break;
    case Channel::Type::Transformation:
      read_transformation_channel(r, j, place, c);
      break;
    case Channel::Type::Audio:
      read_audio_channel(r, j, place, c);
      break;
    case Channel::Type::Projected:
      read_projected_channel(r, j, place, c);
      break;
    case Channel::Type::Dynamic:
      break;
  }
  if (r.errors.size() != errors_before)
  {
    return std::nullopt;
  }
  return c;
}

// --- the animation's path
// -------------------------------------------------------------------------

// "coordinates": the names of the dynamic coordinates the path runs through.
void read_path_coordinates(Reader& r, const Json& j, const std::string& place, Path& path)
{
  const auto coords = j.find("coordinates");
  if (coords == j.end())
  {
    r.error(join(place, "coordinates"), "missing (the dynamic coordinates the path runs through)");
  }
  else if (!coords->is_array())
  {
    r.error(join(place, "coordinates"),
      std::string("expected an array of names, found ") + coords->type_name());
  }
  else
  {
    for (std::size_t k = 0; k < coords->size(); ++k)
    {
      if (auto s = r.string((*coords)[k], at(join(place, "coordinates"), k)))
      {
        path.coordinates.push_back(*s);
      }
    }
  }
}

// "points": one array of values per point.
void read_path_points(Reader& r, const Json& j, const std::string& place, Path& path)
{
  const auto points = j.find("points");
  const std::string pp = join(place, "points");
  if (points == j.end())
  {
    r.error(pp, "missing");
  }
  else if (!points->is_array())
  {
    r.error(pp, std::string("expected an array of points, found ") + points->type_name());
  }
  else
  {
    for (std::size_t k = 0; k < points->size(); ++k)
    {
      if (auto p = r.numbers((*points)[k], at(pp, k)))
      {
        path.points.push_back(*p);
      }
    }
  }
}

void read_path(Reader& r, const Json& j, const std::string& place, Path& path)
{
  if (!r.object(
        j, place, { "coordinates", "points", "interpolation", "closed", "timing", "key_times" }))
  {
    return;
  }
  const std::size_t errors_before = r.errors.size();
  read_path_coordinates(r, j, place, path);
  read_path_points(r, j, place, path);
  optional_key(j,
    "interpolation",
    place,
    path.interpolation,
    [&](const Json& v, const std::string& p)
    { return r.choice(v, p, "interpolation", interpolations); });
  optional_key(j,
    "closed",
    place,
    path.closed,
    [&](const Json& v, const std::string& p) { return r.boolean(v, p); });
  optional_key(j,
    "timing",
    place,
    path.timing,
    [&](const Json& v, const std::string& p) { return r.choice(v, p, "timing", timings); });
  optional_key(j,
    "key_times",
    place,
    path.key_times,
    [&](const Json& v, const std::string& p) { return r.numbers(v, p); });
  if (r.errors.size() != errors_before)
  {
    return;
  }
  // The path's own rules (2+ points of the right size, key times), with their places here.
  const SampledPath::Result sampled = SampledPath::make(path, 1);
  for (const PlanError& e : sampled.errors)
  {
    r.error(e.place.empty() ? place : join(place, e.place), e.message);
  }
}

// "line:column" of the character at 1-based byte position `byte` (nlohmann's count).
std::string line_column(const std::string& text, std::size_t byte)
{
  const std::size_t index = std::min(byte == 0 ? 0 : byte - 1, text.size());
  const std::size_t line =
    1 + static_cast<std::size_t>(
          std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(index), '\n'));
  const std::size_t newline = index == 0 ? std::string::npos : text.rfind('\n', index - 1);
  const std::size_t column = newline == std::string::npos ? index + 1 : index - newline;
  return std::to_string(line) + ":" + std::to_string(column);
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error at ...: " head.
std::string syntax_message(const std::string& what)
{
  const std::size_t head = what.find("parse error");
  if (head == std::string::npos)
  {
    return what;
  }
  const std::size_t colon = what.find(": ", head);
  return colon == std::string::npos ? what.substr(head) : what.substr(colon + 2);
}

// --- the document's sections
// ----------------------------------------------------------------------

// The parsed document; a duplicate key is reported in `r` (by name: the parser's callback does
// not know the path), a syntax error as the only error of `result` (then nullopt).
std::optional<Json> parse_document(Reader& r, const std::string& json_text, LoadResult& result)
{
  std::vector<std::set<std::string>> keys;
  const Json::parser_callback_t duplicates = [&](int, Json::parse_event_t event, Json& parsed)
  {
    if (event == Json::parse_event_t::object_start)
    {
      keys.emplace_back();
    }
    else if (event == Json::parse_event_t::object_end && !keys.empty())
    {
      keys.pop_back();
    }
    else if (event == Json::parse_event_t::key && !keys.empty() &&
             !keys.back().insert(parsed.get<std::string>()).second)
    {
      r.error("", "duplicate key \"" + parsed.get<std::string>() + "\"");
    }
    return true;
  };
  try
  {
    return Json::parse(json_text, duplicates);
  }
  catch (const Json::parse_error& e)
  {
    result.errors.push_back({ line_column(json_text, e.byte), syntax_message(e.what()) });
    return std::nullopt;
  }
  catch (const Json::out_of_range& e)
  {
    // A number too large for a double (406, "number overflow parsing '1e999'"): the parser
    // throws this instead of a parse_error (found by fuzzing; load_mapping must not throw). It
    // carries no position: the number's first occurrence in the text is the place.
    const std::string what = e.what();
    const std::size_t open = what.find('\'');
    const std::size_t close = what.rfind('\'');
    const std::size_t at = open < close
      ? json_text.find(what.substr(open + 1, close - open - 1))
      : std::string::npos;
    const std::size_t id_end = what.find("] ");
    result.errors.push_back({ at == std::string::npos ? std::string() : line_column(json_text, at + 1),
      id_end == std::string::npos ? what : what.substr(id_end + 2) });
    return std::nullopt;
  }
}

// "version", "object", "parameters".
void read_header(Reader& r, const Json& doc, Spec& spec)
{
  optional_key(doc,
    "version",
    "",
    spec.version,
    [&](const Json& v, const std::string& p) -> std::optional<int>
    {
      auto n = r.integer(v, p, 0, 1'000'000);
      if (n && *n != 1)
      {
        r.error(p, "unsupported version " + std::to_string(*n) + " (this build reads version 1)");
        return std::nullopt;
      }
      return n;
    });
  optional_key(doc,
    "object",
    "",
    spec.object,
    [&](const Json& v, const std::string& p) { return r.string(v, p); });
  optional_key(doc,
    "parameters",
    "",
    spec.parameters,
    [&](const Json& v, const std::string& p) { return r.numbers(v, p); });
}

// "world": system, resolution, iso.
void read_world(Reader& r, const Json& doc, WorldSettings& world)
{
  const auto w = doc.find("world");
  if (w == doc.end() || !r.object(*w, "world", { "system", "resolution", "iso" }))
  {
    return;
  }
  optional_key(*w,
    "system",
    "world",
    world.system,
    [&](const Json& v, const std::string& p)
    { return r.choice(v, p, "world system", world_systems); });
  optional_key(*w,
    "resolution",
    "world",
    world.resolution,
    [&](const Json& v, const std::string& p) { return r.integer(v, p, 2, max_resolution); });
  optional_key(*w,
    "iso",
    "world",
    world.iso,
    [&](const Json& v, const std::string& p) { return r.number(v, p); });
}

// "coordinates": the channels of each coordinate, in the file's order (the world channels'
// axis names depend on the world system, read before).
void read_coordinates(Reader& r, const Json& doc, Spec& spec)
{
  const auto coords = doc.find("coordinates");
  if (coords == doc.end())
  {
    r.error("coordinates", "missing (the channels of each coordinate)");
    return;
  }
  if (!coords->is_object())
  {
    r.error("coordinates", std::string("expected an object, found ") + coords->type_name());
    return;
  }
  for (const auto& item : coords->items())
  {
    const std::string place = join("coordinates", item.key());
    CoordinateMapping m;
    m.name = item.key();
    if (m.name.empty())
    {
      r.error(place, "a coordinate needs a name");
    }
    if (!item.value().is_array() || item.value().empty())
    {
      r.error(place,
        item.value().is_array()
          ? std::string("at least one channel is needed")
          : std::string("expected an array of channels, found ") + item.value().type_name());
      continue;
    }
    for (std::size_t k = 0; k < item.value().size(); ++k)
    {
      if (auto c = read_channel(r, item.value()[k], at(place, k), spec.world.system))
      {
        m.channels.push_back(*c);
      }
    }
    spec.coordinates.push_back(std::move(m));
  }
}

// "animation.ghost": resolution, tolerance.
void read_ghost(Reader& r, const Json& j, GhostSettings& ghost)
{
  if (!r.object(j, "animation.ghost", { "resolution", "tolerance" }))
  {
    return;
  }
  optional_key(j,
    "resolution",
    "animation.ghost",
    ghost.resolution,
    [&](const Json& v, const std::string& p) { return r.integer(v, p, 2, max_resolution); });
  optional_key(j,
    "tolerance",
    "animation.ghost",
    ghost.tolerance,
    [&](const Json& v, const std::string& p) { return r.positive(v, p); });
}

// "animation": duration, fps, path, ghost.
void read_animation(Reader& r, const Json& doc, AnimationSettings& animation)
{
  const auto a = doc.find("animation");
  if (a == doc.end() || !r.object(*a, "animation", { "duration", "fps", "path", "ghost" }))
  {
    return;
  }
  auto positive = [&](const Json& v, const std::string& p) { return r.positive(v, p); };
  optional_key(*a, "duration", "animation", animation.duration, positive);
  optional_key(*a, "fps", "animation", animation.fps, positive);
  if (const auto p = a->find("path"); p != a->end())
  {
    Path path;
    read_path(r, *p, "animation.path", path);
    animation.path = path;
  }
  if (const auto g = a->find("ghost"); g != a->end())
  {
    GhostSettings ghost;
    read_ghost(r, *g, ghost);
    animation.ghost = ghost;
  }
}

// "topology": resolution, bisections.
void read_topology(Reader& r, const Json& doc, std::optional<TopologySettings>& topology)
{
  const auto t = doc.find("topology");
  if (t == doc.end() || !r.object(*t, "topology", { "resolution", "bisections" }))
  {
    return;
  }
  TopologySettings settings;
  optional_key(*t,
    "resolution",
    "topology",
    settings.resolution,
    [&](const Json& v, const std::string& p) { return r.integer(v, p, 2, max_resolution); });
  optional_key(*t,
    "bisections",
    "topology",
    settings.bisections,
    [&](const Json& v, const std::string& p) { return r.integer(v, p, 0, 20); });
  topology = settings;
}

// "spreadsheet": cell_size, spacing, labels.
void read_spreadsheet(Reader& r, const Json& doc, SpreadsheetSettings& spreadsheet)
{
  const auto s = doc.find("spreadsheet");
  if (s == doc.end() || !r.object(*s, "spreadsheet", { "cell_size", "spacing", "labels" }))
  {
    return;
  }
  optional_key(*s,
    "cell_size",
    "spreadsheet",
    spreadsheet.cell_size,
    [&](const Json& v, const std::string& p) { return r.integer(v, p, 16, max_picture_size); });
  optional_key(*s,
    "spacing",
    "spreadsheet",
    spreadsheet.spacing,
    [&](const Json& v, const std::string& p) -> std::optional<double>
    {
      auto x = r.number(v, p);
      if (x && (*x < 0 || *x > 10))
      {
        r.error(p, "must be from 0 to 10 (a fraction of the cell)");
        return std::nullopt;
      }
      return x;
    });
  optional_key(*s,
    "labels",
    "spreadsheet",
    spreadsheet.labels,
    [&](const Json& v, const std::string& p) { return r.boolean(v, p); });
}

// "render.view_box": [xmin, ymin, zmin, xmax, ymax, zmax].
void read_view_box(Reader& r, const Json& render, RenderSettings& rs)
{
  const auto vb = render.find("view_box");
  if (vb == render.end())
  {
    return;
  }
  if (const auto box = r.fixed_numbers<6>(*vb, "render.view_box"))
  {
    bool ok = true;
    for (int k = 0; k < 3; ++k)
    {
      ok = ok && (*box)[k] < (*box)[k + 3];
    }
    if (ok)
    {
      rs.view_box = *box;
    }
    else
    {
      r.error("render.view_box", "must be [xmin, ymin, zmin, xmax, ymax, zmax] with min < max");
    }
  }
}

// "render.method": "mesh" | "raycast" for cells and frames, or {"cells": ..., "frames": ...}.
void read_render_method(Reader& r, const Json& render, RenderSettings& rs)
{
  const auto m = render.find("method");
  if (m == render.end())
  {
    return;
  }
  if (m->is_object())
  {
    if (!r.object(*m, "render.method", { "cells", "frames" }))
    {
      return;
    }
    for (const auto& [key, target] :
      { std::pair<const char*, RenderSettings::Method*>{ "cells", &rs.method },
        std::pair<const char*, RenderSettings::Method*>{ "frames", &rs.frames_method } })
    {
      if (const auto v = m->find(key); v != m->end())
      {
        if (const auto method = r.choice(*v, std::string("render.method.") + key, "method", render_methods))
        {
          *target = *method;
        }
      }
    }
    return;
  }
  if (const auto method = r.choice(*m, "render.method", "method", render_methods))
  {
    rs.method = rs.frames_method = *method;
  }
}

// "render": picture size, colours, camera angles, inset, view box, colour source.
void read_render(Reader& r, const Json& doc, RenderSettings& rs)
{
  const auto g = doc.find("render");
  if (g == doc.end() || !r.object(*g,
                          "render",
                          { "width",
                            "height",
                            "background",
                            "colour",
                            "azimuth",
                            "elevation",
                            "inset",
                            "colour_source",
                            "view_box",
                            "method",
                            "scene" }))
  {
    return;
  }
  auto size = [&](const Json& v, const std::string& p)
  { return r.integer(v, p, 16, max_picture_size); };
  auto angle = [&](const Json& v, const std::string& p) { return r.number(v, p); };
  auto colour = [&](const Json& v, const std::string& p) { return r.rgb(v, p); };
  optional_key(*g, "width", "render", rs.width, size);
  optional_key(*g, "height", "render", rs.height, size);
  optional_key(*g, "background", "render", rs.background, colour);
  optional_key(*g, "colour", "render", rs.colour, colour);
  optional_key(*g, "azimuth", "render", rs.azimuth, angle);
  optional_key(*g, "elevation", "render", rs.elevation, angle);
  optional_key(*g,
    "inset",
    "render",
    rs.inset,
    [&](const Json& v, const std::string& p) { return r.boolean(v, p); });
  read_view_box(r, *g, rs);
  optional_key(*g,
    "colour_source",
    "render",
    rs.colour_source,
    [&](const Json& v, const std::string& p)
    { return r.choice(v, p, "colour source", colour_sources); });
  read_render_method(r, *g, rs);
  optional_key(*g,
    "scene",
    "render",
    rs.scene,
    [&](const Json& v, const std::string& p) { return r.choice(v, p, "scene", render_scenes); });
}

// "audio": sample_rate.
void read_audio(Reader& r, const Json& doc, AudioSettings& audio)
{
  const auto au = doc.find("audio");
  if (au == doc.end() || !r.object(*au, "audio", { "sample_rate" }))
  {
    return;
  }
  optional_key(*au,
    "sample_rate",
    "audio",
    audio.sample_rate,
    [&](const Json& v, const std::string& p) { return r.integer(v, p, 8000, 384000); });
}

} // namespace

LoadResult load_mapping(const std::string& json_text)
{
  LoadResult result;
  Reader r;
  const std::optional<Json> doc = parse_document(r, json_text, result);
  if (!doc)
  {
    return result;
  }
  if (r.object(*doc,
        "",
        { "version",
          "object",
          "parameters",
          "world",
          "coordinates",
          "animation",
          "spreadsheet",
          "render",
          "audio",
          "topology" }))
  {
    Spec& spec = result.spec;
    read_header(r, *doc, spec);
    read_world(r, *doc, spec.world); // first: the world channels' axis names depend on it
    read_coordinates(r, *doc, spec);
    read_animation(r, *doc, spec.animation);
    read_spreadsheet(r, *doc, spec.spreadsheet);
    read_render(r, *doc, spec.render);
    read_audio(r, *doc, spec.audio);
    read_topology(r, *doc, spec.topology);
  }
  result.errors = std::move(r.errors);
  return result;
}

} // namespace frep::mapping
