#include "Scene/section_mesh.h"

#include "Plan/colour_maps.h"
#include "Plan/unit_map.h"

#include <algorithm>
#include <cmath>
#include <exception>
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
    const double a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9],
                 i = m[10];
    const double det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    orientation_preserving = det >= 0;
    // cofactor matrix = det * inverse transpose (the scale does not matter: normals are
    // renormalised)
    normal_matrix = { e * i - f * h,
      -(d * i - f * g),
      d * h - e * g,
      -(b * i - c * h),
      a * i - c * g,
      -(a * h - b * g),
      b * f - c * e,
      -(a * f - c * d),
      a * e - b * d };
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
    const auto& q = normal_matrix;
    return { q[0] * n[0] + q[1] * n[1] + q[2] * n[2],
      q[3] * n[0] + q[4] * n[1] + q[5] * n[2],
      q[6] * n[0] + q[7] * n[1] + q[8] * n[2] };
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

  mesh::Grid grid;
  for (int k = 0; k < 3; ++k)
  {
    grid.lo[k] = plan.model_box[k].lo;
    grid.hi[k] = plan.model_box[k].hi;
    grid.samples[k] = options.samples[k] > 0 ? options.samples[k] : plan.samples[k];
  }
  mesh::ExtractOptions extract;
  extract.iso = 0.0;
  extract.normals = options.normals;
  extract.attributes = plan.vertex_colouring.source == VertexColouring::Source::Attributes;
  extract.pool = options.pool;
  extract.progress = options.progress;
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
  const std::size_t n = surface.point_count();

  // Per-vertex colours, from the model-space positions (before they move to world space).
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
      section.error =
        "vertex colours: " + (map.ok() ? "the coordinate is not a world one" : map.error);
      return section;
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
    const int m = surface.attribute_count;
    section.colours.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        const float a = c < m ? surface.attributes[i * m + c] : 0.0f;
        section.colours[3 * i + c] = std::isfinite(a) ? std::clamp(a, 0.0f, 1.0f) : 0.0f;
      }
    }
  }

  // Model box -> world space. Linear maps keep the mesh exactly; curves and the cylindrical /
  // spherical systems bend it (the grid is fine, so the triangles follow).
  std::string world_error;
  const std::unique_ptr<WorldMapping> world = WorldMapping::make(plan, world_error);
  if (!world)
  {
    section.error = world_error;
    return section;
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
      // inverse transpose up to scale = cofactor matrix
      const std::array<double, 9> cof{ j[4] * j[8] - j[5] * j[7],
        -(j[3] * j[8] - j[5] * j[6]),
        j[3] * j[7] - j[4] * j[6],
        -(j[1] * j[8] - j[2] * j[7]),
        j[0] * j[8] - j[2] * j[6],
        -(j[0] * j[7] - j[1] * j[6]),
        j[1] * j[5] - j[2] * j[4],
        -(j[0] * j[5] - j[2] * j[3]),
        j[0] * j[4] - j[1] * j[3] };
      const double det = j[0] * cof[0] + j[1] * cof[1] + j[2] * cof[2];
      if (i == 0 && det < 0)
      {
        flip = !flip; // a reversed target mirrors the shape: keep the triangles outward
      }
      const double sign = det < 0 ? -1.0 : 1.0;
      std::array<double, 3> nm{ 0, 0, 0 };
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          nm[r] += sign * cof[r * 3 + c] * surface.normals[3 * i + c];
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
  return section;
}

} // namespace frep::mapping
