#include "Scene/section_mesh.h"

#include "Mapping/colour_maps.h"
#include "Mapping/unit_map.h"
#include "Render/normal_matrix.h"

#include "Compiler/attribute_rgb.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>

namespace frep::mapping
{
namespace
{

int world_axis_count(const Plan& plan)
{
  return plan.world_coordinates[2] >= 0 ? 3 : 2;
}

// Row-major 4x4 applied to a point (w = 1) and to a direction by the inverse transpose of its
// 3x3 part, so normals stay perpendicular under non-uniform scaling.
struct Affine
{
  std::array<double, 16> m;
  std::array<double, 9> normal_matrix{};
  bool orientation_preserving = true;

  explicit Affine(const std::array<double, 16>& matrix)
    : m(matrix)
  {
    // The cofactor matrix, unsigned: a mirror flips the triangles instead (Render/normal_matrix.h).
    const render::Matrix3 linear = render::linear_part(m);
    normal_matrix = render::cofactor_matrix(linear);
    orientation_preserving = render::determinant(linear, normal_matrix) >= 0;
  }

  bool is_identity() const
  {
    static constexpr std::array<double, 16> identity{
      1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1
    };
    return m == identity;
  }

  std::array<double, 3> point(const std::array<double, 3>& p) const
  {
    return { m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3],
      m[4] * p[0] + m[5] * p[1] + m[6] * p[2] + m[7],
      m[8] * p[0] + m[9] * p[1] + m[10] * p[2] + m[11] };
  }

  std::array<double, 3> normal(const std::array<double, 3>& n) const
  {
    return render::apply(normal_matrix, n);
  }
};

std::array<double, 3> normalised(std::array<double, 3> v)
{
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (length > 0 && std::isfinite(length))
  {
    for (double& c : v)
    {
      c /= length;
    }
  }
  return v;
}

} // namespace

std::unique_ptr<WorldMapping> WorldMapping::make(const Plan& plan, std::string& error)
{
  std::unique_ptr<WorldMapping> m(new WorldMapping);
  m->axes_ = world_axis_count(plan);
  m->system_ = plan.system;
  m->box_ = plan.model_box;
  for (int k = 0; k < m->axes_; ++k)
  {
    ChannelMap::Result r =
      ChannelMap::make(plan.model_box[k], plan.world_curves[k], plan.world_targets[k]);
    if (!r.ok())
    {
      error = "world axis " + std::to_string(k) + ": " + r.error;
      return nullptr;
    }
    m->maps_[k] = r.map;
  }
  return m;
}

std::array<double, 3> WorldMapping::to_world(const std::array<double, 3>& p) const
{
  std::array<double, 3> v{ 0, 0, 0 };
  for (int k = 0; k < axes_; ++k)
  {
    v[k] = maps_[k].forward(p[k]);
  }
  switch (system_)
  {
    case WorldSystem::Cartesian:
      return v;
    case WorldSystem::Cylindrical:
      return { v[0] * std::cos(v[1]), v[0] * std::sin(v[1]), v[2] };
    case WorldSystem::Spherical:
      return { v[0] * std::sin(v[1]) * std::cos(v[2]),
        v[0] * std::sin(v[1]) * std::sin(v[2]),
        v[0] * std::cos(v[1]) };
  }
  return v;
}

std::array<double, 9> WorldMapping::jacobian(const std::array<double, 3>& p) const
{
  std::array<double, 9> j{};
  for (int k = 0; k < 3; ++k)
  {
    if (k >= axes_)
    {
      j[k * 3 + k] = 1.0; // the flat axis of a 2-D section
      continue;
    }
    const double width = box_[k].hi - box_[k].lo;
    const double h = std::max(std::abs(width), 1e-300) * 1e-6;
    std::array<double, 3> a = p, b = p;
    a[k] -= h;
    b[k] += h;
    const std::array<double, 3> wa = to_world(a), wb = to_world(b);
    for (int r = 0; r < 3; ++r)
    {
      j[r * 3 + k] = (wb[r] - wa[r]) / (2 * h);
    }
  }
  return j;
}

std::array<Interval, 3> WorldMapping::world_box(const std::array<Interval, 3>& model_box) const
{
  std::array<Interval, 3> axes{ Interval{ 0.0, 0.0 }, Interval{ 0.0, 0.0 }, Interval{ 0.0, 0.0 } };
  for (int k = 0; k < axes_; ++k)
  {
    const ChannelMap& map = maps_[k];
    const Interval range = model_box[k];
    const int steps = map.is_monotone() ? 1 : 1024;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int i = 0; i <= steps; ++i)
    {
      const double v = map.forward(range.lo + (range.hi - range.lo) * i / steps);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    axes[k] = Interval{ lo, hi };
  }
  return system_ == WorldSystem::Cartesian ? axes : curvilinear_box(system_, axes);
}

Specialisation section_specialisation(const Plan& plan,
  const Sample& sample,
  const std::vector<double>& parameters)
{
  Specialisation s;
  s.parameters = parameters;
  s.fixed.resize(sample.values.size());
  for (std::size_t i = 0; i < sample.values.size(); ++i)
  {
    if (!std::isnan(sample.values[i]))
    {
      s.fixed[i] = sample.values[i];
    }
  }
  for (int k = 0; k < world_axis_count(plan); ++k)
  {
    s.input_order.push_back(plan.world_coordinates[k]);
  }
  return s;
}

namespace
{

/// Per-vertex colours of the section's surface, from the model-space positions (before they move
/// to world space): a world coordinate through the colour map, or s[1..3]. The error, or "".
std::string colour_vertices(const Plan& plan, const Sample& sample, int axes, Section& section)
{
  const mesh::Surface& surface = section.surface;
  const std::size_t n = surface.point_count();
  const VertexColouring& vc = plan.vertex_colouring;
  if (vc.source == VertexColouring::Source::WorldCoordinate)
  {
    int axis = -1;
    for (int k = 0; k < axes; ++k)
    {
      axis = plan.world_coordinates[k] == vc.coordinate ? k : axis;
    }
    ChannelMap::Result map = ChannelMap::make(vc.range, vc.curve, Interval{ 0.0, 1.0 });
    if (!map.ok() || axis < 0)
    {
      return "vertex colours: " + (map.ok() ? "the coordinate is not a world one" : map.error);
    }
    const std::optional<int> component = colour_component(vc.colormap);
    section.colours.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const double v = std::clamp(map.map.forward(surface.points[3 * i + axis]), 0.0, 1.0);
      Rgb rgb = sample.colour;
      if (component)
      {
        rgb[*component] = v;
      }
      else if (const std::optional<Rgb> c = colour_map(vc.colormap, v))
      {
        rgb = *c;
      }
      for (int c = 0; c < 3; ++c)
      {
        section.colours[3 * i + c] = static_cast<float>(rgb[c]);
      }
    }
  }
  else if (vc.source == VertexColouring::Source::Attributes && surface.attribute_count > 0)
  {
    // s[1..3] as RGB, the rule of every output (Compiler/attribute_rgb.h).
    const auto m = static_cast<std::size_t>(surface.attribute_count);
    section.colours.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
      const AttributeRgb rgb = attribute_rgb(surface.attributes.data() + i * m, m);
      std::copy(
        rgb.begin(), rgb.end(), section.colours.begin() + static_cast<std::ptrdiff_t>(3 * i));
    }
  }
  return {};
}

/// Model box -> world space. Linear maps keep the mesh exactly; curves and the cylindrical /
/// spherical systems bend it (the grid is fine, so the triangles follow). The error, or "".
std::string place_in_world(const Plan& plan, const Sample& sample, int axes, mesh::Surface& surface)
{
  const std::size_t n = surface.point_count();
  std::string world_error;
  const std::unique_ptr<WorldMapping> world = WorldMapping::make(plan, world_error);
  if (!world)
  {
    return world_error;
  }
  const Affine transform(sample.transform);
  const bool identity = transform.is_identity();
  bool flip = !transform.orientation_preserving;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::array<double, 3> p{
      surface.points[3 * i], surface.points[3 * i + 1], axes == 3 ? surface.points[3 * i + 2] : 0.0
    };
    std::array<double, 3> w = world->to_world(p);
    if (!surface.normals.empty())
    {
      const std::array<double, 9> j = world->jacobian(p);
      // The Jacobian's normal matrix (Render/normal_matrix.h): signed, so normals stay outward.
      const render::Matrix3 q = render::normal_matrix(j);
      if (i == 0 && render::determinant(j) < 0)
      {
        flip = !flip; // a reversed target mirrors the shape: keep the triangles outward
      }
      std::array<double, 3> nm{ 0, 0, 0 };
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          nm[r] += q[r * 3 + c] * surface.normals[3 * i + c];
        }
      }
      nm = normalised(identity ? nm : transform.normal(nm));
      for (int c = 0; c < 3; ++c)
      {
        surface.normals[3 * i + c] = static_cast<float>(nm[c]);
      }
    }
    if (!identity)
    {
      w = transform.point(w);
    }
    for (int c = 0; c < 3; ++c)
    {
      surface.points[3 * i + c] = w[c];
    }
  }
  if (flip && surface.dimension == 3)
  {
    for (std::size_t t = 0; t + 2 < surface.cells.size(); t += 3)
    {
      std::swap(surface.cells[t + 1], surface.cells[t + 2]);
    }
  }
  return {};
}

} // namespace

Section make_section(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& sample,
  const SectionOptions& options)
{
  Section section;
  const int axes = world_axis_count(plan);
  if (plan.world_coordinates[0] < 0 || plan.world_coordinates[1] < 0)
  {
    section.error = "the mapping has fewer than two world coordinates";
    return section;
  }
  if (static_cast<int>(sample.values.size()) != model.x_dim())
  {
    section.error = "the sample has " + std::to_string(sample.values.size()) +
                    " coordinate values, the model " + std::to_string(model.x_dim()) +
                    " coordinates";
    return section;
  }

  std::shared_ptr<const Tape> tape;
  try
  {
    tape = model.specialise(section_specialisation(plan, sample, parameters));
  }
  catch (const std::exception& e)
  {
    section.error = std::string("specialisation failed: ") + e.what();
    return section;
  }

  GridSpec grid;
  for (int k = 0; k < axes; ++k)
  {
    grid.axes.push_back({ plan.model_box[k].lo,
      plan.model_box[k].hi,
      options.samples[k] > 0 ? options.samples[k] : plan.samples[k] });
  }
  mesh::ExtractOptions extract;
  static_cast<RunControl&>(extract) = options; // threads, pool, progress, cancel
  extract.iso = 0.0;
  extract.normals = options.normals;
  extract.attributes = plan.vertex_colouring.source == VertexColouring::Source::Attributes;
  mesh::ExtractResult r = axes == 3 ? mesh::extract_surface(tape, grid, extract)
                                    : mesh::extract_contour(tape, grid, extract);
  section.statistics = r.statistics;
  section.cancelled = r.cancelled;
  section.error = r.error;
  if (!r.ok())
  {
    return section;
  }
  section.surface = std::move(r.surface);
  mesh::Surface& surface = section.surface;

  if (std::string error = colour_vertices(plan, sample, axes, section); !error.empty())
  {
    section.error = std::move(error);
    return section;
  }
  if (std::string error = place_in_world(plan, sample, axes, surface); !error.empty())
  {
    section.error = std::move(error);
    return section;
  }
  return section;
}

} // namespace frep::mapping
