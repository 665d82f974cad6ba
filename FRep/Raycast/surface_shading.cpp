#include "Raycast/detail/surface_shading.h"

#include <algorithm>
#include <cmath>

namespace frep::raycast::detail
{
namespace
{

double dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Squared distance from p to the segment a-b (2-D).
double segment_distance2(double px, double py, double ax, double ay, double bx, double by)
{
  const double dx = bx - ax, dy = by - ay;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0.0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = ax + t * dx - px, ey = ay + t * dy - py;
  return ex * ex + ey * ey;
}

} // namespace

LightKit world_lights(const imaging::RenderStyle& style, const ViewRays& view)
{
  LightKit kit;
  kit.ambient = static_cast<float>(std::max(0.0, style.ambient));
  kit.shininess = static_cast<float>(std::clamp(style.shininess, 0.0, 4096.0));
  for (const imaging::Light& light : style.lights)
  {
    // Camera coordinates: x right, y up, z from the scene towards the camera.
    const double x = light.direction[0], y = light.direction[1], z = light.direction[2];
    Vec3 l;
    for (int k = 0; k < 3; ++k)
    {
      l[k] = x * view.right[k] + y * view.up[k] - z * view.forward[k];
    }
    const double n = std::sqrt(dot(l, l));
    if (!(n > 0.0) || !std::isfinite(n))
    {
      continue;
    }
    kit.lights.push_back({ { l[0] / n, l[1] / n, l[2] / n },
      static_cast<float>(std::max(0.0, light.intensity)),
      static_cast<float>(std::max(0.0, light.intensity * light.specular * style.specular)) });
  }
  return kit;
}

std::array<float, 3> shade(const LightKit& kit,
  const std::array<float, 3>& colour,
  const Vec3& n,
  const Vec3& v,
  float key_light,
  bool specular)
{
  float diffuse = kit.ambient;
  float highlight = 0.0F;
  for (std::size_t i = 0; i < kit.lights.size(); ++i)
  {
    const WorldLight& light = kit.lights[i];
    const float reach = i == 0 ? key_light : 1.0F;
    const double ndl = dot(n, light.l);
    if (ndl <= 0.0 || reach <= 0.0F)
    {
      continue;
    }
    diffuse += reach * light.diffuse * static_cast<float>(ndl);
    if (specular && light.specular > 0.0F)
    {
      const Vec3 h{ light.l[0] + v[0], light.l[1] + v[1], light.l[2] + v[2] };
      const double hl = std::sqrt(dot(h, h));
      if (hl > 0.0)
      {
        const double ndh = dot(n, h) / hl;
        if (ndh > 0.0)
        {
          highlight += reach * light.specular * static_cast<float>(std::pow(ndh, kit.shininess));
        }
      }
    }
  }
  return { std::clamp(colour[0] * diffuse + highlight, 0.0F, 1.0F),
    std::clamp(colour[1] * diffuse + highlight, 0.0F, 1.0F),
    std::clamp(colour[2] * diffuse + highlight, 0.0F, 1.0F) };
}

FloorIndex::FloorIndex(const Floor& f)
  : floor(f)
{
  if (!(f.square > 0.0) || f.columns <= 0 || f.rows <= 0)
  {
    return;
  }
  segments.resize(static_cast<std::size_t>(f.columns) * static_cast<std::size_t>(f.rows));
  const double r = 0.5 * f.path_width;
  for (std::size_t p = 0; p + 3 < f.path.size(); p += 2)
  {
    const double x0 = std::min(f.path[p], f.path[p + 2]) - r, x1 = std::max(f.path[p], f.path[p + 2]) + r;
    const double y0 = std::min(f.path[p + 1], f.path[p + 3]) - r,
                 y1 = std::max(f.path[p + 1], f.path[p + 3]) + r;
    const auto cell = [&](double v, double o, int n)
    { return std::clamp(static_cast<int>(std::floor((v - o) / f.square)), 0, n - 1); };
    for (int j = cell(y0, f.origin[1], f.rows); j <= cell(y1, f.origin[1], f.rows); ++j)
    {
      for (int i = cell(x0, f.origin[0], f.columns); i <= cell(x1, f.origin[0], f.columns); ++i)
      {
        segments[static_cast<std::size_t>(j) * f.columns + i].push_back(p);
      }
    }
  }
}

bool floor_colour(const FloorIndex& index, double x, double y, std::array<float, 3>& colour)
{
  const Floor& floor = index.floor;
  if (!(floor.square > 0.0))
  {
    return false;
  }
  const double u = (x - floor.origin[0]) / floor.square, w = (y - floor.origin[1]) / floor.square;
  if (!(u >= 0.0 && w >= 0.0 && u < floor.columns && w < floor.rows))
  {
    return false;
  }
  const long i = static_cast<long>(u), j = static_cast<long>(w);
  colour = (i + j) % 2 == 0 ? floor.dark : floor.light;
  const double r2 = 0.25 * floor.path_width * floor.path_width;
  for (const std::size_t p : index.segments[static_cast<std::size_t>(j) * floor.columns + i])
  {
    if (segment_distance2(
          x, y, floor.path[p], floor.path[p + 1], floor.path[p + 2], floor.path[p + 3]) <= r2)
    {
      colour = floor.path_colour;
      break;
    }
  }
  return true;
}

} // namespace frep::raycast::detail
