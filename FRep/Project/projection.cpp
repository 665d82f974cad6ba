#include "Project/projection.h"

#include "Eval/detail/object_pool.h"
#include "Language/names.h"
#include "Shapes/tape_function.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>

namespace frep::project
{

std::string check_projection(const Model& model, const std::vector<CoordinateRange>& axes,
  const ProjectionOptions& options)
{
  if (axes.empty())
    return "no coordinate to project along";
  std::set<int> seen;
  for (const CoordinateRange& e : axes)
  {
    const std::string name = "x" + std::to_string(e.coordinate);
    if (e.coordinate < 1 || e.coordinate > model.x_dim())
      return "cannot project along " + name + ": " + model.name() + " has x[" +
             std::to_string(model.x_dim()) + "]";
    if (!seen.insert(e.coordinate).second)
      return name + " is projected twice";
    if (!std::isfinite(e.lo) || !std::isfinite(e.hi) || e.lo > e.hi)
      return name + "'s range must be finite, lo <= hi (got " + std::to_string(e.lo) + ":" +
             std::to_string(e.hi) + ")";
  }
  if (static_cast<int>(axes.size()) >= model.x_dim())
    return "every coordinate of " + model.name() + " is projected: nothing would be left";
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
    return "the projection's tolerance must be > 0";
  if (options.max_boxes < 1 || options.enclosure_boxes < 1)
    return "the projection needs at least one box per point and per enclosure";
  return {};
}

namespace
{

bool parse_number(std::string_view text, double& value)
{
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

// "x4=0:1" (or "4=0:1").
bool parse_one(std::string_view item, CoordinateRange& e, std::string& error)
{
  const std::size_t equals = item.find('=');
  const std::size_t colon = item.find(':', equals == std::string_view::npos ? 0 : equals);
  std::string_view name = item.substr(0, equals);
  if (!name.empty() && (name.front() == 'x' || name.front() == 'X'))
    name.remove_prefix(1);
  double index = 0.0;
  if (equals == std::string_view::npos || colon == std::string_view::npos ||
      !parse_number(name, index) || index != std::floor(index) ||
      !parse_number(item.substr(equals + 1, colon - equals - 1), e.lo) ||
      !parse_number(item.substr(colon + 1), e.hi))
  {
    error = "'" + std::string(item) + "': give COORDINATE=LO:HI, e.g. x4=0:1";
    return false;
  }
  e.coordinate = static_cast<int>(index);
  return true;
}

} // namespace

std::vector<CoordinateRange> parse_eliminated(std::string_view text, std::string& error)
{
  std::vector<CoordinateRange> axes;
  error.clear();
  while (true)
  {
    const std::size_t comma = text.find(',');
    CoordinateRange e;
    if (!parse_one(text.substr(0, comma), e, error))
      return {};
    axes.push_back(e);
    if (comma == std::string_view::npos)
      return axes;
    text.remove_prefix(comma + 1);
  }
}

std::string eliminated_text(const std::vector<CoordinateRange>& axes)
{
  std::string out;
  for (const CoordinateRange& e : axes)
  {
    char range[96];
    std::snprintf(range, sizeof range, "=%.17g:%.17g", e.lo, e.hi);
    out += (out.empty() ? "x" : ",x") + std::to_string(e.coordinate) + range;
  }
  return out;
}

UserFunction projection_function(const std::string& name, std::shared_ptr<const Tape> tape,
  std::vector<Interval> ranges, const ProjectorOptions& options)
{
  const int k = static_cast<int>(tape->input_count - ranges.size());
  auto pool = std::make_shared<eval::ObjectPool<Projector>>(
    [tape, ranges, options] { return std::make_unique<Projector>(tape, ranges, options); });
  shapes::ArrayForms forms;
  forms.point = [pool](std::span<const double> x)
  { return pool->with([&](Projector& p) { return p.maximise(x).value; }); };
  forms.interval = [pool](std::span<const Interval> box)
  { return pool->with([&](Projector& p) { return p.enclose(box); }); };
  forms.gradient = [pool](std::span<const double> x, std::span<double> g)
  { return pool->with([&](Projector& p) { return p.gradient(x, g); }); };
  return shapes::array_function(name, k, std::move(forms));
}

namespace
{

// The object's name: the source's, if it is a plain identifier, with "_projection".
std::string projected_name(const std::string& source)
{
  return is_identifier(source) ? source + "_projection" : std::string("projection");
}

// The wrapper: `name(x[n or m], a[1]) { name = frep_projection(kept x); }`.
std::string wrapper_text(const std::string& name, int x_dim, const std::vector<int>& kept,
  bool keep_coordinates)
{
  const int m = static_cast<int>(kept.size());
  std::string text = "-- " + name + ": a projection (Project/projection.h)\n" + name + "(x[" +
                     std::to_string(keep_coordinates ? x_dim : m) + "], a[1])\n{\n";
  if (!keep_coordinates)
    return text + "  " + name + " = frep_projection(x);\n}\n";
  text += "  array mk[" + std::to_string(m) + "];\n";
  for (int i = 0; i < m; ++i)
    text += "  mk[" + std::to_string(i + 1) + "] = x[" +
            std::to_string(kept[static_cast<std::size_t>(i)] + 1) + "];\n";
  return text + "  " + name + " = frep_projection(mk);\n}\n";
}

} // namespace

LoadedModel project(std::shared_ptr<const Model> model, const std::vector<CoordinateRange>& axes,
  const ProjectionOptions& options)
{
  LoadedModel failed;
  failed.file = "<projection>";
  if (!model)
  {
    failed.diagnostics.push_back(Diagnostic{ failed.file, {}, "no model to project" });
    return failed;
  }
  if (const std::string why = check_projection(*model, axes, options); !why.empty())
  {
    failed.diagnostics.push_back(Diagnostic{ failed.file, {}, why });
    return failed;
  }
  // The source's tape: the kept coordinates first (in increasing order), the eliminated last.
  std::vector<bool> eliminated(static_cast<std::size_t>(model->x_dim()), false);
  for (const CoordinateRange& e : axes)
    eliminated[static_cast<std::size_t>(e.coordinate - 1)] = true;
  Specialisation source;
  source.parameters = options.parameters;
  std::vector<int> kept;
  for (int i = 0; i < model->x_dim(); ++i)
    if (!eliminated[static_cast<std::size_t>(i)])
      kept.push_back(i);
  source.input_order = kept;
  std::vector<Interval> ranges;
  for (const CoordinateRange& e : axes)
  {
    source.input_order.push_back(e.coordinate - 1);
    ranges.push_back(Interval{ e.lo, e.hi });
  }
  auto functions = std::make_shared<UserFunctionRegistry>();
  functions->add(projection_function(
    "frep_projection", model->specialise(source), std::move(ranges), options));
  const std::string name = projected_name(model->name());
  LoadOptions load;
  load.functions = functions;
  return load_model(ModelSource::from_text(
                      wrapper_text(name, model->x_dim(), kept, options.keep_coordinates),
                      "<projection of " + model->name() + " along " + eliminated_text(axes) + ">"),
    load);
}

} // namespace frep::project
