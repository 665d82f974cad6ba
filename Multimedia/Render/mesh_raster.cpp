#include "Render/detail/mesh_raster.h"

#include "Render/detail/render_parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frep::render::detail
{

namespace
{

// Sample rows per band: small enough that 2 threads stay busy, large enough that a typical
// triangle falls in one band.
constexpr int kBandRows = 16;

// Edge a -> b as an integer edge function E(p) = (bx - ax)(py - ay) - (by - ay)(px - ax), positive
// inside (the triangle's area is positive). Samples exactly on an edge belong to one of the two
// triangles sharing it: the edge and its reverse never both include zero.
struct Edge
{
  std::int64_t step_x; ///< change of E per sample to the right
  std::int64_t step_y; ///< per sample down
  std::int64_t bias;   ///< 0 (edge includes its points) or -1 (excludes them)

  Edge(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by)
    : step_x(-(by - ay) * kSubpixel)
    , step_y((bx - ax) * kSubpixel)
    , bias((by - ay) > 0 || ((by - ay) == 0 && (bx - ax) < 0) ? 0 : -1)
  {
  }
};

inline std::int64_t edge_at(std::int64_t ax,
  std::int64_t ay,
  std::int64_t bx,
  std::int64_t by,
  std::int64_t px,
  std::int64_t py)
{
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

void rasterise_in_band(Visibility& vis,
  const MeshSetup& setup,
  std::uint32_t index,
  int row0,
  int row1)
{
  const SetupTriangle& t = setup.triangles[index];
  const int y0 = std::max(t.y_min, row0);
  const int y1 = std::min(t.y_max, row1);
  if (y0 > y1)
  {
    return;
  }
  const std::int64_t x[3] = { t.x[0], t.x[1], t.x[2] };
  const std::int64_t y[3] = { t.y[0], t.y[1], t.y[2] };
  const std::int64_t half = kSubpixel / 2;
  const std::int64_t lo = std::min({ x[0], x[1], x[2] });
  const std::int64_t hi = std::max({ x[0], x[1], x[2] });
  const int x0 =
    static_cast<int>(std::max<std::int64_t>(0, (lo - half + kSubpixel - 1) >> kSubpixelBits));
  const int x1 =
    static_cast<int>(std::min<std::int64_t>(vis.width - 1, (hi - half) >> kSubpixelBits));
  if (x0 > x1)
  {
    return;
  }
  // Weight of vertex i: the edge opposite it.
  const Edge e0(x[1], y[1], x[2], y[2]);
  const Edge e1(x[2], y[2], x[0], y[0]);
  const Edge e2(x[0], y[0], x[1], y[1]);
  const std::int64_t px = x0 * kSubpixel + half;
  const std::int64_t py = y0 * kSubpixel + half;
  std::int64_t w0 = edge_at(x[1], y[1], x[2], y[2], px, py);
  std::int64_t w1 = edge_at(x[2], y[2], x[0], y[0], px, py);
  std::int64_t w2 = edge_at(x[0], y[0], x[1], y[1], px, py);
  // The depth key is linear in the picture: key = sum k_i w_i / area.
  const double area = static_cast<double>(w0) + static_cast<double>(w1) + static_cast<double>(w2);
  const double k[3] = {
    setup.vertices[t.v[0]].key, setup.vertices[t.v[1]].key, setup.vertices[t.v[2]].key
  };
  const double key_dx = (k[0] * e0.step_x + k[1] * e1.step_x + k[2] * e2.step_x) / area;
  const double key_dy = (k[0] * e0.step_y + k[1] * e1.step_y + k[2] * e2.step_y) / area;
  double key_row = (k[0] * w0 + k[1] * w1 + k[2] * w2) / area;
  w0 += e0.bias;
  w1 += e1.bias;
  w2 += e2.bias;
  for (int sy = y0; sy <= y1; ++sy)
  {
    std::int64_t a = w0, b = w1, c = w2;
    double key = key_row; // double: no drift along long rows
    const std::size_t row = static_cast<std::size_t>(sy) * vis.width;
    float* keys = vis.key.data() + row;
    std::uint32_t* ids = vis.triangle.data() + row;
    for (int sx = x0; sx <= x1; ++sx)
    {
      if ((a | b | c) >= 0 && static_cast<float>(key) > keys[sx])
      {
        keys[sx] = static_cast<float>(key);
        ids[sx] = index;
      }
      a += e0.step_x;
      b += e1.step_x;
      c += e2.step_x;
      key += key_dx;
    }
    w0 += e0.step_y;
    w1 += e1.step_y;
    w2 += e2.step_y;
    key_row += key_dy;
  }
}

// b^e for e a small non-negative integer, by squaring (a few multiplies instead of a pow).
inline float integer_power(float base, unsigned e)
{
  float result = 1.0F;
  while (e)
  {
    if (e & 1U)
    {
      result *= base;
    }
    base *= base;
    e >>= 1U;
  }
  return result;
}

} // namespace

Visibility::Visibility(int w, int h)
  : width(std::max(w, 0))
  , height(std::max(h, 0))
  , key(static_cast<std::size_t>(width) * height, -std::numeric_limits<float>::infinity())
  , triangle(static_cast<std::size_t>(width) * height, kNoTriangle)
{
}

void rasterise(Visibility& vis, const MeshSetup& setup, std::size_t first, int threads)
{
  const std::size_t end = setup.triangles.size();
  if (first >= end || vis.width == 0 || vis.height == 0)
  {
    return;
  }
  // Bin the triangles by band (counting sort, submission order kept within a band).
  const int bands = (vis.height + kBandRows - 1) / kBandRows;
  std::vector<std::size_t> start(static_cast<std::size_t>(bands) + 1, 0);
  for (std::size_t i = first; i < end; ++i)
  {
    const SetupTriangle& t = setup.triangles[i];
    for (int b = t.y_min / kBandRows; b <= t.y_max / kBandRows; ++b)
    {
      ++start[b + 1];
    }
  }
  for (int b = 0; b < bands; ++b)
  {
    start[b + 1] += start[b];
  }
  std::vector<std::uint32_t> binned(start[bands]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = first; i < end; ++i)
  {
    const SetupTriangle& t = setup.triangles[i];
    for (int b = t.y_min / kBandRows; b <= t.y_max / kBandRows; ++b)
    {
      binned[fill[b]++] = static_cast<std::uint32_t>(i);
    }
  }
  parallel_items(static_cast<std::size_t>(bands),
    threads,
    [&](std::size_t b)
    {
      const int row0 = static_cast<int>(b) * kBandRows;
      const int row1 = std::min(vis.height, row0 + kBandRows) - 1;
      for (std::size_t i = start[b]; i < start[b + 1]; ++i)
      {
        rasterise_in_band(vis, setup, binned[i], row0, row1);
      }
    });
}

Shading::Shading(const imaging::RenderStyle& style)
  : ambient(static_cast<float>(std::max(0.0, style.ambient)))
  , shininess(static_cast<float>(std::clamp(style.shininess, 0.0, 4096.0)))
  , back_face_factor(static_cast<float>(std::clamp(style.back_face_factor, 0.0, 1.0)))
{
  integer_shininess = shininess == std::floor(shininess) && shininess <= 1024.0F;
  for (const imaging::Light& light : style.lights)
  {
    // The API's z points towards the viewer; ours points away.
    const double x = light.direction[0], y = light.direction[1], z = -light.direction[2];
    const double n = std::sqrt(x * x + y * y + z * z);
    if (!(n > 0.0) || !std::isfinite(n))
    {
      continue;
    }
    lights.push_back(
      { { static_cast<float>(x / n), static_cast<float>(y / n), static_cast<float>(z / n) },
        static_cast<float>(std::max(0.0, light.intensity)),
        static_cast<float>(std::max(0.0, light.intensity * light.specular * style.specular)) });
  }
}

void shade_sample(const MeshSetup& setup,
  std::uint32_t index,
  int sx,
  int sy,
  const Projection& pr,
  const Shading& shading,
  float rgb[3])
{
  const SetupTriangle& t = setup.triangles[index];
  const std::int64_t px = sx * kSubpixel + kSubpixel / 2;
  const std::int64_t py = sy * kSubpixel + kSubpixel / 2;
  // Screen-space barycentrics (exact integers), then perspective-correct weights.
  const double b0 = static_cast<double>(edge_at(t.x[1], t.y[1], t.x[2], t.y[2], px, py));
  const double b1 = static_cast<double>(edge_at(t.x[2], t.y[2], t.x[0], t.y[0], px, py));
  const double b2 = static_cast<double>(edge_at(t.x[0], t.y[0], t.x[1], t.y[1], px, py));
  const SetupVertex& v0 = setup.vertices[t.v[0]];
  const SetupVertex& v1 = setup.vertices[t.v[1]];
  const SetupVertex& v2 = setup.vertices[t.v[2]];
  double w0 = b0 * v0.weight, w1 = b1 * v1.weight, w2 = b2 * v2.weight;
  const double sum = w0 + w1 + w2;
  if (sum != 0.0)
  {
    w0 /= sum;
    w1 /= sum;
    w2 /= sum;
  }
  else
  {
    w0 = w1 = w2 = 1.0 / 3.0;
  }
  const auto mix = [&](const float* a, const float* b, const float* c, int j)
  { return static_cast<float>(w0 * a[j] + w1 * b[j] + w2 * c[j]); };
  float n[3] = { mix(v0.n, v1.n, v2.n, 0), mix(v0.n, v1.n, v2.n, 1), mix(v0.n, v1.n, v2.n, 2) };
  float length2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (!(length2 > 1e-12F))
  {
    n[0] = t.facing[0];
    n[1] = t.facing[1];
    n[2] = t.facing[2];
    length2 = 1.0F;
  }
  const float flip = (t.back ? -1.0F : 1.0F) / std::sqrt(length2);
  n[0] *= flip;
  n[1] *= flip;
  n[2] *= flip;
  // Towards the eye.
  float v[3] = { 0.0F, 0.0F, -1.0F };
  if (!pr.orthographic)
  {
    v[0] = static_cast<float>(-((sx + 0.5) - pr.cx) / pr.focal);
    v[1] = static_cast<float>(((sy + 0.5) - pr.cy) / pr.focal);
    const float inv = 1.0F / std::sqrt(v[0] * v[0] + v[1] * v[1] + 1.0F);
    v[0] *= inv;
    v[1] *= inv;
    v[2] = -inv;
  }
  float diffuse = shading.ambient;
  float specular = 0.0F;
  for (const ShadingLight& light : shading.lights)
  {
    const float ndl = n[0] * light.l[0] + n[1] * light.l[1] + n[2] * light.l[2];
    if (ndl <= 0.0F)
    {
      continue;
    }
    diffuse += light.diffuse * ndl;
    if (light.specular > 0.0F)
    {
      float h[3] = { light.l[0] + v[0], light.l[1] + v[1], light.l[2] + v[2] };
      const float hl = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
      if (hl > 0.0F)
      {
        const float ndh = (n[0] * h[0] + n[1] * h[1] + n[2] * h[2]) / hl;
        if (ndh > 0.0F)
        {
          specular +=
            light.specular * (shading.integer_shininess
                                 ? integer_power(ndh, static_cast<unsigned>(shading.shininess))
                                 : std::pow(ndh, shading.shininess));
        }
      }
    }
  }
  if (t.back)
  {
    diffuse *= shading.back_face_factor;
    specular *= shading.back_face_factor;
  }
  for (int j = 0; j < 3; ++j)
  {
    rgb[j] = std::clamp(mix(v0.c, v1.c, v2.c, j) * diffuse + specular, 0.0F, 1.0F);
  }
}

} // namespace frep::render::detail
