#include "Render/mesh_renderer.h"

#include "Render/detail/mesh_raster.h"
#include "Render/detail/mesh_setup.h"
#include "Render/detail/render_parallel.h"

#include <algorithm>
#include <cmath>

namespace frep::render
{

namespace
{

constexpr int kMaxSamplesPerSide = 32768; // the guard band and 32-bit sizes stay safe

int clamp_supersample(int s)
{
  return std::clamp(s, 1, 4);
}

} // namespace

struct Renderer::State
{
  int width;
  int height;
  int factor;
  int threads;
  detail::Projection projection;
  detail::Shading shading;
  detail::MeshSetup opaque;   ///< every opaque mesh's triangles, in submission order
  detail::Visibility visible; ///< of the opaque triangles
  struct Layer
  {
    detail::MeshSetup setup;
    float opacity;
  };
  std::vector<Layer> layers;

  State(int w, int h, const imaging::Camera& camera, const imaging::RenderStyle& style)
    : width(std::clamp(w, 0, kMaxSamplesPerSide / clamp_supersample(style.supersample)))
    , height(std::clamp(h, 0, kMaxSamplesPerSide / clamp_supersample(style.supersample)))
    , factor(clamp_supersample(style.supersample))
    , threads(detail::resolve_thread_count(style.threads))
    , projection(camera, width * factor, height * factor)
    , shading(style)
    , visible(width * factor, height * factor)
  {
  }
};

Renderer::Renderer(int width,
  int height,
  const imaging::Camera& camera,
  const imaging::RenderStyle& style)
  : state_(std::make_unique<State>(width, height, camera, style))
{
}

Renderer::~Renderer() = default;

RenderReport Renderer::add(const MeshInput& mesh)
{
  RenderReport report;
  State& s = *state_;
  detail::MeshSetup setup = detail::setup_mesh(mesh, s.projection, s.threads, report);
  const double opacity = std::isnan(mesh.opacity) ? 1.0 : std::clamp(mesh.opacity, 0.0, 1.0);
  if (!report.ok() || setup.triangles.empty() || opacity == 0.0)
  {
    return report;
  }
  if (opacity < 1.0)
  {
    s.layers.push_back({ std::move(setup), static_cast<float>(opacity) });
    return report;
  }
  // Append to the opaque pool (vertex ids shift by the vertices already there) and rasterise
  // just the new triangles into the shared depth buffer.
  const auto base = static_cast<std::uint32_t>(s.opaque.vertices.size());
  const std::size_t first = s.opaque.triangles.size();
  if (first == 0)
  {
    s.opaque = std::move(setup);
  }
  else
  {
    s.opaque.vertices.insert(s.opaque.vertices.end(), setup.vertices.begin(), setup.vertices.end());
    for (detail::SetupTriangle t : setup.triangles)
    {
      for (std::uint32_t& v : t.v)
      {
        v += base;
      }
      s.opaque.triangles.push_back(t);
    }
  }
  detail::rasterise(s.visible, s.opaque, first, s.threads);
  return report;
}

std::string Renderer::resolve(imaging::Image& target) const
{
  const State& s = *state_;
  if (target.width != s.width || target.height != s.height)
  {
    return "render: the target picture is " + std::to_string(target.width) + " x " +
           std::to_string(target.height) + ", the renderer's " + std::to_string(s.width) + " x " +
           std::to_string(s.height);
  }
  // Transparent layers: each its nearest surface in front of the opaque geometry, far to near.
  std::vector<const State::Layer*> order;
  for (const State::Layer& layer : s.layers)
  {
    order.push_back(&layer);
  }
  std::stable_sort(order.begin(),
    order.end(),
    [](const State::Layer* a, const State::Layer* b)
    { return a->setup.centre_depth > b->setup.centre_depth; });
  std::vector<detail::Visibility> layer_visible;
  layer_visible.reserve(order.size());
  for (const State::Layer* layer : order)
  {
    detail::Visibility v = s.visible;
    std::fill(v.triangle.begin(), v.triangle.end(), detail::kNoTriangle);
    detail::rasterise(v, layer->setup, 0, s.threads);
    layer_visible.push_back(std::move(v));
  }

  // Shade every sample once and box-average each pixel's samples (premultiplied), then
  // composite over the target. Rows are independent: any thread count gives the same picture.
  const int f = s.factor;
  const float inv_samples = 1.0F / static_cast<float>(f * f);
  constexpr int kRows = 4;
  detail::parallel_items(static_cast<std::size_t>((s.height + kRows - 1) / kRows),
    s.threads,
    [&](std::size_t chunk)
    {
      const int y_end = std::min(s.height, static_cast<int>(chunk + 1) * kRows);
      for (int y = static_cast<int>(chunk) * kRows; y < y_end; ++y)
      {
        for (int x = 0; x < s.width; ++x)
        {
          float sum[4] = { 0, 0, 0, 0 }; // premultiplied
          for (int j = 0; j < f; ++j)
          {
            const int sy = y * f + j;
            for (int i = 0; i < f; ++i)
            {
              const int sx = x * f + i;
              const std::size_t at = static_cast<std::size_t>(sy) * s.visible.width + sx;
              float c[4] = { 0, 0, 0, 0 };
              if (s.visible.triangle[at] != detail::kNoTriangle)
              {
                detail::shade_sample(
                  s.opaque, s.visible.triangle[at], sx, sy, s.projection, s.shading, c);
                c[3] = 1.0F;
              }
              for (std::size_t l = 0; l < order.size(); ++l)
              {
                const std::uint32_t t = layer_visible[l].triangle[at];
                if (t == detail::kNoTriangle)
                {
                  continue;
                }
                float rgb[3];
                detail::shade_sample(order[l]->setup, t, sx, sy, s.projection, s.shading, rgb);
                const float a = order[l]->opacity;
                const float keep = c[3] * (1.0F - a);
                const float out = a + keep;
                for (int k = 0; k < 3; ++k)
                {
                  c[k] = (rgb[k] * a + c[k] * keep) / out;
                }
                c[3] = out;
              }
              sum[0] += c[0] * c[3];
              sum[1] += c[1] * c[3];
              sum[2] += c[2] * c[3];
              sum[3] += c[3];
            }
          }
          if (sum[3] > 0.0F)
          {
            const float a = sum[3] * inv_samples;
            imaging::blend_pixel(target,
              x,
              y,
              { sum[0] / sum[3], sum[1] / sum[3], sum[2] / sum[3], std::min(a, 1.0F) });
          }
        }
      }
    });
  return {};
}

RenderReport render_mesh(imaging::Image& target,
  const imaging::Camera& camera,
  const MeshInput& mesh,
  const imaging::RenderStyle& style)
{
  Renderer renderer(target.width, target.height, camera, style);
  RenderReport report = renderer.add(mesh);
  if (report.ok())
  {
    report.error = renderer.resolve(target);
  }
  return report;
}

} // namespace frep::render
