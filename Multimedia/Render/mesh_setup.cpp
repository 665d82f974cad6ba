#include "Render/detail/mesh_setup.h"

#include "Render/normal_matrix.h"
#include "Render/detail/render_parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

namespace frep::render::detail
{

namespace
{

// Screen coordinates farther than this from the view centre (in samples) are clipped away, so
// the snapped 32-bit positions and 64-bit edge functions cannot overflow.
constexpr double kGuardBand = 1 << 20;

constexpr int kPlaneCount = 5; // near, then x <= G, x >= -G, y <= G, y >= -G (screen offsets)
constexpr std::size_t kPointChunk = 8192;
constexpr std::size_t kTriangleChunk = 16384;
// Vertex ids made while clipping are chunk-local until the chunks are joined.
constexpr std::uint32_t kLocalBit = 0x80000000U;

using Vec = std::array<double, 3>;

inline Vec sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline Vec cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// A point of a polygon being clipped: camera position and the attributes that interpolate
// linearly along its edges in camera space.
struct ClipVertex
{
  Vec p;
  Vec n;
  Vec c;
};

// The camera-space points, normals, colours and clip outcodes of the mesh's points.
struct PointData
{
  std::vector<Vec> camera;
  std::vector<SetupVertex> vertex;
  std::vector<double> sx, sy;
  std::vector<std::uint8_t> outcode; ///< bit k: outside plane k; 0xFF: not a finite point
};

double plane_distance(const Projection& pr, int plane, const Vec& p)
{
  switch (plane)
  {
    case 0:
      return p[2] - pr.near;
    case 1:
      return (pr.orthographic ? kGuardBand : kGuardBand * p[2]) - pr.focal * p[0];
    case 2:
      return (pr.orthographic ? kGuardBand : kGuardBand * p[2]) + pr.focal * p[0];
    case 3:
      return (pr.orthographic ? kGuardBand : kGuardBand * p[2]) - pr.focal * p[1];
    default:
      return (pr.orthographic ? kGuardBand : kGuardBand * p[2]) + pr.focal * p[1];
  }
}

std::uint8_t outcode_of(const Projection& pr, const Vec& p)
{
  std::uint8_t code = 0;
  for (int k = 0; k < kPlaneCount; ++k)
  {
    if (!(plane_distance(pr, k, p) >= 0.0))
    {
      code |= static_cast<std::uint8_t>(1U << k);
    }
  }
  return code;
}

void project(const Projection& pr, const Vec& p, double& sx, double& sy)
{
  const double k = pr.orthographic ? pr.focal : pr.focal / p[2];
  sx = pr.cx + k * p[0];
  sy = pr.cy - k * p[1];
}

SetupVertex make_vertex(const Projection& pr, const Vec& p, const Vec& n, const Vec& c)
{
  SetupVertex v{};
  v.weight = pr.orthographic ? 1.0F : static_cast<float>(1.0 / p[2]);
  v.key = pr.orthographic ? static_cast<float>(-p[2]) : v.weight;
  for (int i = 0; i < 3; ++i)
  {
    v.n[i] = static_cast<float>(n[i]);
    // A NaN colour would spread through the pixel's average: black instead.
    v.c[i] = std::isfinite(c[i]) ? static_cast<float>(std::clamp(c[i], 0.0, 1.0)) : 0.0F;
  }
  return v;
}

// Row-major 4 x 4 applied to a point (its normal matrix: Render/normal_matrix.h).
Vec transform_point(const std::array<double, 16>& m, const Vec& p)
{
  return { m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3],
    m[4] * p[0] + m[5] * p[1] + m[6] * p[2] + m[7],
    m[8] * p[0] + m[9] * p[1] + m[10] * p[2] + m[11] };
}

struct Chunk
{
  std::vector<SetupTriangle> triangles;
  std::vector<SetupVertex> extra;
  std::size_t skipped = 0;
  std::size_t clipped = 0;
};

// Emits one triangle of vertex ids a, b, c at screen positions (sx, sy) if it covers any sample
// centre's bounding box in the picture.
void emit(const Projection& pr,
  Chunk& chunk,
  std::uint32_t ids[3],
  const double sx[3],
  const double sy[3],
  const float facing[3],
  bool back)
{
  SetupTriangle t{};
  for (int i = 0; i < 3; ++i)
  {
    t.v[i] = ids[i];
    // Round to nearest (inline, not a libm call: this runs for every triangle corner).
    t.x[i] = static_cast<std::int32_t>(std::floor(sx[i] * kSubpixel + 0.5));
    t.y[i] = static_cast<std::int32_t>(std::floor(sy[i] * kSubpixel + 0.5));
  }
  const std::int64_t area = (std::int64_t{ t.x[1] } - t.x[0]) * (std::int64_t{ t.y[2] } - t.y[0]) -
                            (std::int64_t{ t.x[2] } - t.x[0]) * (std::int64_t{ t.y[1] } - t.y[0]);
  if (area == 0)
  {
    return; // edge-on or smaller than the snapping: covers no sample
  }
  if (area < 0)
  {
    std::swap(t.v[1], t.v[2]);
    std::swap(t.x[1], t.x[2]);
    std::swap(t.y[1], t.y[2]);
  }
  // Sample (i, j) is at ((i + 1/2), (j + 1/2)) samples: the rows/columns whose centre can be in.
  const std::int64_t half = kSubpixel / 2;
  const auto first = [&](std::int64_t lo) { return (lo - half + kSubpixel - 1) >> kSubpixelBits; };
  const auto last = [&](std::int64_t hi) { return (hi - half) >> kSubpixelBits; };
  const std::int64_t x0 = std::max<std::int64_t>(0, first(std::min({ t.x[0], t.x[1], t.x[2] })));
  const std::int64_t x1 =
    std::min<std::int64_t>(pr.width - 1, last(std::max({ t.x[0], t.x[1], t.x[2] })));
  const std::int64_t y0 = std::max<std::int64_t>(0, first(std::min({ t.y[0], t.y[1], t.y[2] })));
  const std::int64_t y1 =
    std::min<std::int64_t>(pr.height - 1, last(std::max({ t.y[0], t.y[1], t.y[2] })));
  if (x0 > x1 || y0 > y1)
  {
    return;
  }
  t.y_min = static_cast<std::int32_t>(y0);
  t.y_max = static_cast<std::int32_t>(y1);
  std::copy(facing, facing + 3, t.facing);
  t.back = back;
  chunk.triangles.push_back(t);
}

// Sutherland-Hodgman against the planes in `planes` (bits), in camera space.
std::vector<ClipVertex> clip_polygon(const Projection& pr,
  std::vector<ClipVertex> polygon,
  std::uint8_t planes)
{
  std::vector<ClipVertex> next;
  for (int k = 0; k < kPlaneCount && polygon.size() >= 3; ++k)
  {
    if (!(planes & (1U << k)))
    {
      continue;
    }
    next.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
      const ClipVertex& a = polygon[i];
      const ClipVertex& b = polygon[(i + 1) % polygon.size()];
      const double da = plane_distance(pr, k, a.p);
      const double db = plane_distance(pr, k, b.p);
      if (da >= 0.0)
      {
        next.push_back(a);
      }
      if ((da >= 0.0) != (db >= 0.0))
      {
        const double t = da / (da - db);
        ClipVertex m;
        for (int j = 0; j < 3; ++j)
        {
          m.p[j] = a.p[j] + t * (b.p[j] - a.p[j]);
          m.n[j] = a.n[j] + t * (b.n[j] - a.n[j]);
          m.c[j] = a.c[j] + t * (b.c[j] - a.c[j]);
        }
        next.push_back(m);
      }
    }
    std::swap(polygon, next);
  }
  return polygon;
}

void setup_triangles(const MeshInput& mesh,
  const Projection& pr,
  const PointData& pts,
  std::size_t begin,
  std::size_t end,
  Chunk& chunk)
{
  const std::size_t point_count = pts.camera.size();
  chunk.triangles.reserve(end - begin);
  for (std::size_t t = begin; t < end; ++t)
  {
    std::uint32_t ids[3] = {
      mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]
    };
    if (ids[0] >= point_count || ids[1] >= point_count || ids[2] >= point_count ||
        pts.outcode[ids[0]] == 0xFF || pts.outcode[ids[1]] == 0xFF || pts.outcode[ids[2]] == 0xFF)
    {
      ++chunk.skipped;
      continue;
    }
    const std::uint8_t all = pts.outcode[ids[0]] | pts.outcode[ids[1]] | pts.outcode[ids[2]];
    const std::uint8_t common = pts.outcode[ids[0]] & pts.outcode[ids[1]] & pts.outcode[ids[2]];
    if (common != 0)
    {
      continue; // wholly behind the near plane or beyond the guard band
    }
    const Vec& p0 = pts.camera[ids[0]];
    const Vec& p1 = pts.camera[ids[1]];
    const Vec& p2 = pts.camera[ids[2]];
    Vec g = cross(sub(p1, p0), sub(p2, p0));
    const double g_length = std::sqrt(dot(g, g));
    if (!(g_length > 0.0) || !std::isfinite(g_length))
    {
      ++chunk.skipped; // degenerate (zero area) or overflowing
      continue;
    }
    // The outside is where the point normals point (given or computed); the winding only
    // breaks a tie. A triangle whose outside faces away from the eye is a back face.
    Vec reference{ 0.0, 0.0, 0.0 };
    for (const std::uint32_t id : ids)
    {
      for (int j = 0; j < 3; ++j)
      {
        reference[j] += pts.vertex[id].n[j];
      }
    }
    if (dot(g, reference) < 0.0)
    {
      g = { -g[0], -g[1], -g[2] };
    }
    const Vec to_eye = pr.orthographic ? Vec{ 0.0, 0.0, -1.0 } : Vec{ -p0[0], -p0[1], -p0[2] };
    const bool back = dot(g, to_eye) < 0.0;
    const double s = (back ? -1.0 : 1.0) / g_length;
    const float facing[3] = {
      static_cast<float>(g[0] * s), static_cast<float>(g[1] * s), static_cast<float>(g[2] * s)
    };

    if (all == 0)
    {
      const double sx[3] = { pts.sx[ids[0]], pts.sx[ids[1]], pts.sx[ids[2]] };
      const double sy[3] = { pts.sy[ids[0]], pts.sy[ids[1]], pts.sy[ids[2]] };
      emit(pr, chunk, ids, sx, sy, facing, back);
      continue;
    }
    ++chunk.clipped;
    std::vector<ClipVertex> polygon(3);
    for (int i = 0; i < 3; ++i)
    {
      const SetupVertex& v = pts.vertex[ids[i]];
      polygon[i].p = pts.camera[ids[i]];
      polygon[i].n = { v.n[0], v.n[1], v.n[2] };
      polygon[i].c = { v.c[0], v.c[1], v.c[2] };
    }
    polygon = clip_polygon(pr, std::move(polygon), all);
    if (polygon.size() < 3)
    {
      continue;
    }
    std::vector<std::uint32_t> local(polygon.size());
    std::vector<double> sx(polygon.size()), sy(polygon.size());
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
      local[i] = kLocalBit | static_cast<std::uint32_t>(chunk.extra.size());
      chunk.extra.push_back(make_vertex(pr, polygon[i].p, polygon[i].n, polygon[i].c));
      project(pr, polygon[i].p, sx[i], sy[i]);
    }
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
    {
      std::uint32_t fan[3] = { local[0], local[i], local[i + 1] };
      const double fx[3] = { sx[0], sx[i], sx[i + 1] };
      const double fy[3] = { sy[0], sy[i], sy[i + 1] };
      emit(pr, chunk, fan, fx, fy, facing, back);
    }
  }
}

} // namespace

Projection::Projection(const imaging::Camera& camera, int sample_width, int sample_height)
  : frame(imaging::camera_frame(camera))
  , eye(camera.position)
  , orthographic(camera.orthographic)
  , cx(0.5 * sample_width)
  , cy(0.5 * sample_height)
  , width(sample_width)
  , height(sample_height)
{
  if (orthographic)
  {
    const double scale = camera.parallel_scale > 0.0 && std::isfinite(camera.parallel_scale)
                           ? camera.parallel_scale
                           : 1.0;
    focal = 0.5 * sample_height / scale;
  }
  else
  {
    const double angle =
      camera.view_angle_deg > 0.0 ? std::clamp(camera.view_angle_deg, 0.01, 179.0) : 30.0;
    focal = 0.5 * sample_height / std::tan(0.5 * angle * std::numbers::pi / 180.0);
  }
  near = camera.near_distance > 0.0 ? camera.near_distance : 1e-6;
}

namespace
{

/// Why the mesh cannot be drawn (array lengths, the number of points), or "".
std::string check_mesh(const MeshInput& mesh)
{
  std::string error;
  if (mesh.points.size() % 3 != 0)
  {
    error = "render: the point array's length is not a multiple of 3";
  }
  else if (mesh.triangles.size() % 3 != 0)
  {
    error = "render: the triangle array's length is not a multiple of 3";
  }
  else if (!mesh.normals.empty() && mesh.normals.size() != mesh.points.size())
  {
    error = "render: there must be 3 normal components per point (or none)";
  }
  else if (!mesh.colours.empty() && mesh.colours.size() != mesh.points.size())
  {
    error = "render: there must be 3 colour components per point (or none)";
  }
  else if (mesh.points.size() / 3 >= kLocalBit)
  {
    error = "render: too many points (at most 2^31)";
  }
  return error;
}

/// The points in world space (through the mesh's transform, if any).
std::vector<Vec> world_points(const MeshInput& mesh)
{
  const std::size_t n = mesh.points.size() / 3;
  std::vector<Vec> world(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec p{ mesh.points[3 * i], mesh.points[3 * i + 1], mesh.points[3 * i + 2] };
    world[i] = mesh.transform ? transform_point(*mesh.transform, p) : p;
  }
  return world;
}

/// World normals: given (through the normal matrix) or area-weighted from the triangles (the
/// unnormalised cross product is twice the area times the unit normal).
std::vector<Vec> world_normals(const MeshInput& mesh, const std::vector<Vec>& world)
{
  const std::size_t n = world.size();
  const std::size_t triangle_count = mesh.triangles.size() / 3;
  std::vector<Vec> normal(n, Vec{ 0.0, 0.0, 0.0 });
  if (!mesh.normals.empty())
  {
    const std::array<double, 9> nm = mesh.transform
                                       ? normal_matrix(*mesh.transform)
                                       : std::array<double, 9>{ 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    for (std::size_t i = 0; i < n; ++i)
    {
      const Vec m{ mesh.normals[3 * i], mesh.normals[3 * i + 1], mesh.normals[3 * i + 2] };
      normal[i] = { nm[0] * m[0] + nm[1] * m[1] + nm[2] * m[2],
        nm[3] * m[0] + nm[4] * m[1] + nm[5] * m[2],
        nm[6] * m[0] + nm[7] * m[1] + nm[8] * m[2] };
    }
  }
  else
  {
    for (std::size_t t = 0; t < triangle_count; ++t)
    {
      const std::uint32_t a = mesh.triangles[3 * t], b = mesh.triangles[3 * t + 1],
                          c = mesh.triangles[3 * t + 2];
      if (a >= n || b >= n || c >= n)
      {
        continue;
      }
      const Vec g = cross(sub(world[b], world[a]), sub(world[c], world[a]));
      if (!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(g[2]))
      {
        continue;
      }
      for (const std::uint32_t id : { a, b, c })
      {
        for (int j = 0; j < 3; ++j)
        {
          normal[id][j] += g[j];
        }
      }
    }
  }
  return normal;
}

/// Camera space, projection and outcodes of the points, in chunks of points on `threads`.
PointData camera_points(const MeshInput& mesh, const Projection& pr, const std::vector<Vec>& world,
  const std::vector<Vec>& normal, int threads)
{
  const std::size_t n = world.size();
  PointData pts;
  pts.camera.resize(n);
  pts.vertex.resize(n);
  pts.sx.resize(n);
  pts.sy.resize(n);
  pts.outcode.resize(n);
  const imaging::CameraFrame& f = pr.frame;
  const Vec colour{ mesh.colour[0], mesh.colour[1], mesh.colour[2] };
  parallel_items((n + kPointChunk - 1) / kPointChunk,
    threads,
    [&](std::size_t chunk)
    {
      const std::size_t end = std::min(n, (chunk + 1) * kPointChunk);
      for (std::size_t i = chunk * kPointChunk; i < end; ++i)
      {
        const Vec d = sub(world[i], pr.eye);
        const Vec p{ dot(d, f.right), dot(d, f.up), dot(d, f.forward) };
        pts.camera[i] = p;
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        {
          pts.outcode[i] = 0xFF;
          continue;
        }
        Vec m{ dot(normal[i], f.right), dot(normal[i], f.up), dot(normal[i], f.forward) };
        const double length = std::sqrt(dot(m, m));
        if (length > 0.0 && std::isfinite(length))
        {
          m = { m[0] / length, m[1] / length, m[2] / length };
        }
        else
        {
          m = { 0.0, 0.0, 0.0 }; // the shader falls back to the facet normal
        }
        const Vec c =
          mesh.colours.empty()
            ? colour
            : Vec{ mesh.colours[3 * i], mesh.colours[3 * i + 1], mesh.colours[3 * i + 2] };
        pts.vertex[i] = make_vertex(pr, p, m, c);
        pts.outcode[i] = outcode_of(pr, p);
        if (pts.outcode[i] == 0)
        {
          project(pr, p, pts.sx[i], pts.sy[i]);
        }
      }
    });
  return pts;
}

/// The depth of the centre of the bounding box of the drawable points, for ordering transparent
/// layers; none when no point is drawable.
std::optional<double> centre_depth(const std::vector<Vec>& world, const PointData& pts,
  const Projection& pr)
{
  const std::size_t n = world.size();
  const imaging::CameraFrame& f = pr.frame;
  Vec lo{ std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  Vec hi{ -lo[0], -lo[1], -lo[2] };
  for (std::size_t i = 0; i < n; ++i)
  {
    if (pts.outcode[i] != 0xFF)
    {
      for (int j = 0; j < 3; ++j)
      {
        lo[j] = std::min(lo[j], world[i][j]);
        hi[j] = std::max(hi[j], world[i][j]);
      }
    }
  }
  if (lo[0] <= hi[0])
  {
    const Vec centre{ 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]) };
    return dot(sub(centre, pr.eye), f.forward);
  }
  return std::nullopt;
}

} // namespace

MeshSetup setup_mesh(const MeshInput& mesh, const Projection& pr, int threads, RenderReport& report)
{
  MeshSetup out;
  report.triangles = mesh.triangles.size() / 3;
  if (std::string error = check_mesh(mesh); !error.empty())
  {
    report.error = std::move(error);
  }
  if (!report.error.empty() || mesh.points.empty() || mesh.triangles.empty())
  {
    return out;
  }
  const std::size_t n = mesh.points.size() / 3;
  const std::size_t triangle_count = mesh.triangles.size() / 3;

  const std::vector<Vec> world = world_points(mesh);
  const std::vector<Vec> normal = world_normals(mesh, world);
  PointData pts = camera_points(mesh, pr, world, normal, threads);

  // Triangles, in fixed chunks (the output does not depend on the thread count).
  std::vector<Chunk> chunks((triangle_count + kTriangleChunk - 1) / kTriangleChunk);
  parallel_items(chunks.size(),
    threads,
    [&](std::size_t c)
    {
      setup_triangles(mesh,
        pr,
        pts,
        c * kTriangleChunk,
        std::min(triangle_count, (c + 1) * kTriangleChunk),
        chunks[c]);
    });

  // Join: the points' vertices, then each chunk's clipped vertices.
  std::size_t total_triangles = 0, total_extra = 0;
  for (const Chunk& c : chunks)
  {
    total_triangles += c.triangles.size();
    total_extra += c.extra.size();
  }
  if (n + total_extra >= kLocalBit)
  {
    report.error = "render: too many vertices after clipping";
    return out;
  }
  out.vertices = std::move(pts.vertex);
  out.vertices.reserve(n + total_extra);
  out.triangles.reserve(total_triangles);
  for (Chunk& c : chunks)
  {
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), c.extra.begin(), c.extra.end());
    for (SetupTriangle& t : c.triangles)
    {
      for (std::uint32_t& v : t.v)
      {
        if (v & kLocalBit)
        {
          v = base + (v & ~kLocalBit);
        }
      }
    }
    out.triangles.insert(out.triangles.end(), c.triangles.begin(), c.triangles.end());
    report.triangles_skipped += c.skipped;
    report.triangles_clipped += c.clipped;
  }

  if (const std::optional<double> d = centre_depth(world, pts, pr))
  {
    out.centre_depth = *d;
  }
  return out;
}

} // namespace frep::render::detail
