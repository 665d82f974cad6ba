#include "Raycast/raycast.h"

#include "Raycast/detail/piece_tracer.h"
#include "Raycast/detail/shadow_map.h"
#include "Mesh/solid_bounds.h"
#include "Raycast/detail/surface_shading.h"
#include "Raycast/detail/view_rays.h"

#include "Eval/gradient_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Eval/thread_pool.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <thread>

namespace frep::raycast
{
namespace
{

using detail::Vec3;

constexpr int kTile = 16; // samples per tile side: pieces start at this size

double dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

bool normalise(Vec3& v)
{
  const double n = std::sqrt(dot(v, v));
  if (!(n > 0.0) || !std::isfinite(n))
  {
    return false;
  }
  v = { v[0] / n, v[1] / n, v[2] / n };
  return true;
}

std::string check_input(const imaging::Image& target, const Shape& shape, const Floor* floor)
{
  if (target.empty())
  {
    return "the picture is empty";
  }
  if (!shape.tape)
  {
    return "no tape";
  }
  if (shape.tape->input_count != 3)
  {
    return "the tape has " + std::to_string(shape.tape->input_count) +
           " inputs; the ray caster draws 3-D solids (3 inputs)";
  }
  for (int k = 0; k < 3; ++k)
  {
    if (!(shape.box[k].lo < shape.box[k].hi) || !std::isfinite(shape.box[k].lo) ||
        !std::isfinite(shape.box[k].hi))
    {
      return "the model box must be finite with lo < hi on every axis";
    }
  }
  if (!(shape.opacity >= 0.0 && shape.opacity <= 1.0))
  {
    return "the opacity must be in [0, 1]";
  }
  if (floor && (!(floor->square > 0.0) || !std::isfinite(floor->square) || floor->columns <= 0 ||
                 floor->rows <= 0 || !std::isfinite(floor->height)))
  {
    return "the floor needs a finite height, a square size > 0 and at least one square";
  }
  return {};
}

// What one thread needs: the tracer of the camera's rays, the full tape's point and gradient
// evaluators (colours and normals come from the exact tape), scratch.
struct Worker
{
  Worker(const Shape& shape,
    const std::array<Interval, 3>& clip,
    const detail::ViewRays& pixels,
    const detail::ViewRays& samples,
    const detail::TraceOptions& options)
    : tracer(shape.tape, shape.box, clip, pixels, options)
    , fine(shape.tape, shape.box, clip, samples, options)
    , point(shape.tape)
    , gradient(shape.tape)
    , outputs(shape.tape->outputs.size())
  {
  }
  detail::PieceTracer tracer; // one ray per pixel
  detail::PieceTracer fine;   // supersample x supersample rays per pixel, at edges
  PointEvaluator point;
  GradientEvaluator gradient;
  std::vector<double> outputs;
  std::vector<detail::Hit> hits;
  std::vector<unsigned char> active;
};

struct Context
{
  const Shape& shape;
  const Floor* floor;
  const Style& style;
  detail::Affine3 map;
  detail::LightKit kit;
  std::optional<detail::FloorIndex> floor_index;
  std::optional<detail::ShadowMap> shadow;
};

// The outward unit normal (world) of a hit, facing the eye.
Vec3 hit_normal(const Context& c, Worker& w, const detail::Hit& hit, const Vec3& m, const Vec3& v)
{
  Vec3 g{ 0.0, 0.0, 0.0 };
  if (hit.kind == detail::HitKind::Cap)
  {
    g[hit.face / 2] = hit.face % 2 ? -1.0 : 1.0; // F grows into the box: minus the outward face
  }
  else
  {
    w.gradient.evaluate(m, g);
  }
  Vec3 n = c.map.gradient_to_world(g);
  n = { -n[0], -n[1], -n[2] };
  if (!normalise(n))
  {
    return v;
  }
  if (dot(n, v) < 0.0)
  {
    n = { -n[0], -n[1], -n[2] };
  }
  return n;
}

// The sample (sx, sy): its colour and alpha into `rgba`, its depth into `depth`.
// What a pixel shows, for telling edges: nothing, the floor or the shape.
enum class Seen : std::uint8_t
{
  Nothing,
  Floor,
  Shape
};

Seen shade_sample(const Context& c,
  const detail::ViewRays& view,
  Worker& w,
  int sx,
  int sy,
  const detail::Hit& hit,
  float* rgba,
  float& depth)
{
  const Vec3 dir = view.world_direction(sx + 0.5, sy + 0.5);
  Vec3 v{ -dir[0], -dir[1], -dir[2] };
  normalise(v);
  Vec3 o, d;
  view.ray(sx + 0.5, sy + 0.5, o, d);

  // The floor, if the ray meets it in its squares before the shape.
  std::array<float, 3> floor_rgb{};
  bool floor_hit = false;
  double floor_lambda = std::numeric_limits<double>::infinity();
  if (c.floor_index)
  {
    const Vec3 origin = view.world_origin(sx + 0.5, sy + 0.5);
    if (dir[2] != 0.0)
    {
      const double lambda = (c.floor->height - origin[2]) / dir[2];
      const double x = origin[0] + lambda * dir[0], y = origin[1] + lambda * dir[1];
      std::array<float, 3> pattern;
      if (lambda >= view.near && std::isfinite(lambda) &&
          detail::floor_colour(*c.floor_index, x, y, pattern))
      {
        const Vec3 p{ x, y, c.floor->height };
        const float reach = c.shadow && c.floor->shadows ? c.shadow->light(p) : 1.0F;
        const float lit = 1.0F - static_cast<float>(c.style.shadow_factor);
        const Vec3 up{ 0.0, 0.0, origin[2] >= c.floor->height ? 1.0 : -1.0 };
        floor_rgb = detail::shade(c.kit, pattern, up, v, 1.0F - lit * (1.0F - reach), false);
        floor_hit = true;
        floor_lambda = lambda;
      }
    }
  }

  if (hit.kind != detail::HitKind::None && hit.lambda <= floor_lambda)
  {
    Vec3 m;
    for (int k = 0; k < 3; ++k)
    {
      m[k] = std::clamp(o[k] + hit.lambda * d[k], c.shape.box[k].lo, c.shape.box[k].hi);
    }
    const Vec3 n = hit_normal(c, w, hit, m, v);
    std::array<float, 3> colour = c.shape.colour;
    if (c.shape.colour_function)
    {
      w.point.evaluate(m, w.outputs);
      colour = c.shape.colour_function(m, w.outputs);
    }
    float key = 1.0F;
    if (c.shadow && c.style.self_shadows)
    {
      const Vec3 p = c.map.point(m);
      const double bias = 2.0 * c.shadow->texel();
      const float reach = c.shadow->light({ p[0] + bias * n[0], p[1] + bias * n[1], p[2] + bias * n[2] });
      key = 1.0F - static_cast<float>(1.0 - c.style.shadow_factor) * (1.0F - reach);
    }
    const std::array<float, 3> rgb = detail::shade(c.kit, colour, n, v, key);
    const float alpha = static_cast<float>(c.shape.opacity);
    if (floor_hit && alpha < 1.0F)
    {
      for (int k = 0; k < 3; ++k)
      {
        rgba[k] = alpha * rgb[k] + (1.0F - alpha) * floor_rgb[k];
      }
      rgba[3] = 1.0F;
    }
    else
    {
      rgba[0] = rgb[0];
      rgba[1] = rgb[1];
      rgba[2] = rgb[2];
      rgba[3] = alpha;
    }
    depth = static_cast<float>(hit.lambda);
    return Seen::Shape;
  }
  if (floor_hit)
  {
    rgba[0] = floor_rgb[0];
    rgba[1] = floor_rgb[1];
    rgba[2] = floor_rgb[2];
    rgba[3] = 1.0F;
    depth = static_cast<float>(floor_lambda);
    return Seen::Floor;
  }
  return Seen::Nothing;
}

// Pixels whose first ray differs from a neighbour's in what it sees, in depth (more than a
// few pixel widths: a silhouette over the shape itself) or in colour (by more than kColourEdge:
// a crease or the rim of a highlight; smooth shading changes by less between two pixels): only
// these get supersample x supersample rays. Interiors of smooth regions keep their one ray,
// which is what makes anti-aliasing affordable (4-9 times fewer rays). The threshold was 0.12
// until 2026-12-02: on a 300 x 300 cell of Meta5D it marked 3051 pixels against 1876 at 0.3 (and
// 1444 with no colour test at all), for a picture that looks the same (edges 2.84 s -> 1.97 s).
constexpr float kColourEdge = 0.3F; // summed over linear R, G, B
std::vector<std::uint32_t> edge_pixels(const imaging::Image& image,
  const std::vector<Seen>& seen,
  const std::vector<float>& depth,
  const detail::ViewRays& view)
{
  const int w = image.width, h = image.height;
  std::vector<unsigned char> mark(static_cast<std::size_t>(w) * h, 0);
  const auto differ = [&](std::size_t a, std::size_t b)
  {
    if (seen[a] != seen[b])
    {
      return true;
    }
    if (seen[a] == Seen::Nothing)
    {
      return false;
    }
    const double near = std::min(depth[a], depth[b]);
    if (std::abs(depth[a] - depth[b]) > 4.0 * view.footprint(near))
    {
      return true;
    }
    const float* p = image.rgba.data() + 4 * a;
    const float* q = image.rgba.data() + 4 * b;
    return std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) > kColourEdge;
  };
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (x + 1 < w && differ(i, i + 1))
      {
        mark[i] = mark[i + 1] = 1;
      }
      if (y + 1 < h && differ(i, i + w))
      {
        mark[i] = mark[i + w] = 1;
      }
    }
  }
  std::vector<std::uint32_t> edges;
  for (std::size_t i = 0; i < mark.size(); ++i)
  {
    if (mark[i])
    {
      edges.push_back(static_cast<std::uint32_t>(i));
    }
  }
  return edges;
}

/// One picture's passes over the pool: the workers (one per participant, made on first use),
/// cancellation, progress, and the picture of the first pass (refined at edges by the second).
class Frame
{
public:
  Frame(const Context& c, const imaging::Image& target, const detail::ViewRays& pixels,
    const detail::ViewRays& samples, const std::array<Interval, 3>& clip,
    const detail::TraceOptions& options, ThreadPool& pool, int ss, const RunControl& run)
    : c_(c)
    , target_(target)
    , pixels_(pixels)
    , samples_(samples)
    , clip_(clip)
    , options_(options)
    , pool_(pool)
    , ss_(ss)
    , run_(run)
    , tiles_x_((target.width + kTile - 1) / kTile)
    , tiles_y_((target.height + kTile - 1) / kTile)
    , workers_(static_cast<std::size_t>(pool.size()))
    , first_(target.width, target.height)
    , first_depth_(static_cast<std::size_t>(target.width) * target.height,
        std::numeric_limits<float>::infinity())
    , seen_(static_cast<std::size_t>(target.width) * target.height, Seen::Nothing)
  {
  }

  /// 1. One ray per pixel, tile by tile.
  void trace_pixels()
  {
    const std::size_t tiles = static_cast<std::size_t>(tiles_x_) * tiles_y_;
    pool_.parallel_for(tiles,
      [&](std::size_t t, int slot)
      {
        if (stop())
        {
          return;
        }
        pixel_tile(t, worker(slot));
        report(0.0, ss_ > 1 ? 0.7 : 1.0, tiles);
      });
  }

  /// 2. Edges: supersample x supersample rays per pixel, averaged like imaging::downsample.
  /// Returns the number of edge pixels.
  std::size_t supersample_edges()
  {
    const std::vector<std::uint32_t> edges = edge_pixels(first_, seen_, first_depth_, pixels_);
    // By tile, so that a tile's edge pixels share its pieces: only their rays are traced.
    std::vector<std::vector<std::uint32_t>> by_tile(static_cast<std::size_t>(tiles_x_) * tiles_y_);
    for (const std::uint32_t e : edges)
    {
      const int x = static_cast<int>(e % target_.width), y = static_cast<int>(e / target_.width);
      by_tile[static_cast<std::size_t>(y / kTile) * tiles_x_ + x / kTile].push_back(e);
    }
    std::size_t edge_tiles = 0;
    for (const auto& tile : by_tile)
    {
      edge_tiles += tile.empty() ? 0 : 1;
    }
    finished_ = 0;
    pool_.parallel_for(by_tile.size(),
      [&](std::size_t t, int slot)
      {
        if (by_tile[t].empty() || stop())
        {
          return;
        }
        edge_tile(t, by_tile[t], worker(slot));
        report(0.7, 0.3, edge_tiles);
      });
    return edges.size();
  }

  /// The tracers' counters of every worker, added to `s`.
  void add_statistics(Statistics& s) const
  {
    for (const auto& w : workers_)
    {
      if (w)
      {
        for (const detail::PieceTracer* t : { &w->tracer, &w->fine })
        {
          const Statistics& ts = t->statistics();
          s.rays += ts.rays;
          s.rays_in_box += ts.rays_in_box;
          s.hits += ts.hits;
          s.interval_evaluations += ts.interval_evaluations;
          s.point_evaluations += ts.point_evaluations;
        }
      }
    }
  }

  bool cancelled() const { return cancelled_; }
  double reported() const { return reported_; }
  imaging::Image& picture() { return first_; }
  std::vector<float>& depth() { return first_depth_; }

private:
  Worker& worker(int slot)
  {
    auto& w = workers_[static_cast<std::size_t>(slot)];
    if (!w)
    {
      w = std::make_unique<Worker>(c_.shape, clip_, pixels_, samples_, options_);
    }
    return *w;
  }

  bool stop()
  {
    if (cancelled_.load(std::memory_order_relaxed) || run_.cancel_requested())
    {
      cancelled_ = true;
    }
    return cancelled_.load(std::memory_order_relaxed);
  }

  // Progress: tiles finished per pass, reported only on the calling thread (a participant of
  // the pool), so the callback needs no locking; the pixel pass is the first 70 %.
  void report(double from, double span, std::size_t total)
  {
    const std::size_t done = finished_.fetch_add(1, std::memory_order_relaxed) + 1;
    if (run_.progress && std::this_thread::get_id() == caller_ && total > 0)
    {
      const double fraction = from + span * static_cast<double>(done) / static_cast<double>(total);
      if (fraction >= reported_ + 0.01) // at most about 100 calls
      {
        reported_ = fraction;
        if (!run_.progress(fraction))
        {
          cancelled_ = true;
        }
      }
    }
  }

  void pixel_tile(std::size_t t, Worker& w)
  {
    const int x0 = static_cast<int>(t % tiles_x_) * kTile, y0 = static_cast<int>(t / tiles_x_) * kTile;
    const int x1 = std::min(target_.width, x0 + kTile), y1 = std::min(target_.height, y0 + kTile);
    w.hits.resize(static_cast<std::size_t>(x1 - x0) * (y1 - y0));
    w.tracer.trace_tile(x0, y0, x1, y1, w.hits);
    for (int y = y0; y < y1; ++y)
    {
      for (int x = x0; x < x1; ++x)
      {
        const std::size_t i = static_cast<std::size_t>(y) * target_.width + x;
        const detail::Hit& hit = w.hits[static_cast<std::size_t>(y - y0) * (x1 - x0) + (x - x0)];
        seen_[i] = shade_sample(c_, pixels_, w, x, y, hit, first_.rgba.data() + 4 * i, first_depth_[i]);
      }
    }
  }

  void edge_tile(std::size_t t, const std::vector<std::uint32_t>& edges, Worker& w)
  {
    const int ss = ss_;
    const int px0 = static_cast<int>(t % tiles_x_) * kTile, py0 = static_cast<int>(t / tiles_x_) * kTile;
    const int px1 = std::min(target_.width, px0 + kTile), py1 = std::min(target_.height, py0 + kTile);
    const int sw = (px1 - px0) * ss, sh = (py1 - py0) * ss;
    w.active.assign(static_cast<std::size_t>(sw) * sh, 0);
    for (const std::uint32_t e : edges)
    {
      const int x = static_cast<int>(e % target_.width) - px0, y = static_cast<int>(e / target_.width) - py0;
      for (int j = 0; j < ss; ++j)
      {
        for (int i = 0; i < ss; ++i)
        {
          w.active[static_cast<std::size_t>(y * ss + j) * sw + (x * ss + i)] = 1;
        }
      }
    }
    w.hits.resize(w.active.size());
    w.fine.trace_tile(px0 * ss, py0 * ss, px1 * ss, py1 * ss, w.hits, w.active.data());
    for (const std::uint32_t e : edges)
    {
      const int x = static_cast<int>(e % target_.width), y = static_cast<int>(e / target_.width);
      double r = 0.0, g = 0.0, b = 0.0, a = 0.0;
      float nearest = std::numeric_limits<float>::infinity();
      for (int j = 0; j < ss; ++j)
      {
        for (int i = 0; i < ss; ++i)
        {
          float rgba[4] = { 0.0F, 0.0F, 0.0F, 0.0F };
          float sample_depth = std::numeric_limits<float>::infinity();
          const std::size_t k =
            static_cast<std::size_t>((y - py0) * ss + j) * sw + ((x - px0) * ss + i);
          shade_sample(c_, samples_, w, x * ss + i, y * ss + j, w.hits[k], rgba, sample_depth);
          r += rgba[0] * rgba[3];
          g += rgba[1] * rgba[3];
          b += rgba[2] * rgba[3];
          a += rgba[3];
          nearest = std::min(nearest, sample_depth);
        }
      }
      float* out = first_.rgba.data() + 4 * static_cast<std::size_t>(e);
      const double n = static_cast<double>(ss) * ss;
      out[0] = a > 0.0 ? static_cast<float>(r / a) : 0.0F;
      out[1] = a > 0.0 ? static_cast<float>(g / a) : 0.0F;
      out[2] = a > 0.0 ? static_cast<float>(b / a) : 0.0F;
      out[3] = static_cast<float>(a / n);
      first_depth_[e] = nearest;
    }
  }

  const Context& c_;
  const imaging::Image& target_;
  const detail::ViewRays& pixels_;
  const detail::ViewRays& samples_;
  const std::array<Interval, 3>& clip_;
  const detail::TraceOptions& options_;
  ThreadPool& pool_;
  const int ss_;
  const RunControl& run_;
  const int tiles_x_, tiles_y_;
  std::vector<std::unique_ptr<Worker>> workers_;
  std::atomic<bool> cancelled_{ false };
  const std::thread::id caller_ = std::this_thread::get_id();
  std::atomic<std::size_t> finished_{ 0 };
  double reported_ = 0.0;
  imaging::Image first_;
  std::vector<float> first_depth_;
  std::vector<Seen> seen_;
};

} // namespace

mesh::SolidBounds solid_bounds(const std::shared_ptr<const Tape>& tape,
  std::span<const Interval> box)
{
  // Two passes of 1/16: the second looks only where the first found the solid, so it costs
  // about as much as the first, where one pass of 1/256 would split every cell near the surface.
  mesh::SolidBounds coarse = mesh::solid_bounds_in(tape, box, 4);
  if (!coarse.bounded())
  {
    return coarse;
  }
  mesh::SolidBounds fine = mesh::solid_bounds_in(tape, coarse.box, 4);
  fine.interval_evaluations += coarse.interval_evaluations;
  fine.seconds += coarse.seconds;
  // A sound enclosure finds the solid again inside its own bounds; keep the coarse box if not.
  return fine.bounded() ? fine : coarse;
}

Floor floor_under(std::array<double, 3>& lo, std::array<double, 3>& hi)
{
  const double span = 1.6 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
  Floor floor;
  floor.height = lo[2];
  floor.square = span / 8.0;
  floor.columns = floor.rows = 8;
  floor.origin = { 0.5 * (lo[0] + hi[0]) - 0.5 * span, 0.5 * (lo[1] + hi[1]) - 0.5 * span };
  lo[0] = floor.origin[0];
  lo[1] = floor.origin[1];
  hi[0] = floor.origin[0] + span;
  hi[1] = floor.origin[1] + span;
  return floor;
}

Result render(imaging::Image& target,
  const imaging::Camera& camera,
  const Shape& shape,
  const Floor* floor,
  const Style& style,
  std::vector<float>* depth,
  const RunControl& run)
{
  const auto start = std::chrono::steady_clock::now();
  Result result;
  result.error = check_input(target, shape, floor);
  if (!result.ok())
  {
    return result;
  }
  Context c{ shape, floor, style, {}, {}, {}, {} };
  if (!detail::Affine3::make(shape.to_world, c.map))
  {
    result.error = "the model-to-world map is singular or not finite";
    return result;
  }
  const int ss = std::clamp(style.render.supersample, 1, 4);
  const int width = target.width * ss, height = target.height * ss;
  if (width > 32768 || height > 32768)
  {
    result.error = "the picture is larger than 32768 samples on a side";
    return result;
  }
  const detail::ViewRays pixels = detail::make_view_rays(camera, target.width, target.height, c.map);
  const detail::ViewRays samples = detail::make_view_rays(camera, width, height, c.map);
  c.kit = detail::world_lights(style.render, pixels);
  if (floor)
  {
    c.floor_index.emplace(*floor);
  }
  const std::shared_ptr<ThreadPool> shared_pool = run.thread_pool();
  ThreadPool& pool = *shared_pool;
  // Rays clip to the solid's bounds in the box (solid_bounds: to 1/256 of the box).
  const mesh::SolidBounds bounds =
    shape.bounds ? *shape.bounds : solid_bounds(shape.tape, shape.box);
  result.statistics.interval_evaluations += bounds.interval_evaluations;
  // With nothing inside the box, rays search an empty box outside it (none enters).
  const std::array<Interval, 3> clip = bounds.bounded()
    ? std::array<Interval, 3>{ bounds.box[0], bounds.box[1], bounds.box[2] }
    : std::array<Interval, 3>{ Interval{ 1.0, 0.0 }, Interval{ 1.0, 0.0 }, Interval{ 1.0, 0.0 } };
  if (bounds.bounded() && !c.kit.lights.empty() && ((floor && floor->shadows) || style.self_shadows))
  {
    // Half a picture's side over the shape's bounding sphere (the look-up is bilinear): the map
    // is a picture of its own, traced like the camera's, and costs as much per sample.
    const int size = std::clamp(std::max(target.width, target.height) / 4, 192, 512);
    const auto t0 = std::chrono::steady_clock::now();
    c.shadow.emplace(shape, clip, c.map, c.kit.lights[0].l, size, pool, result.statistics);
    result.statistics.shadow_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  detail::TraceOptions options;
  options.from = pixels.near;
  Frame frame(c, target, pixels, samples, clip, options, pool, ss, run);
  frame.trace_pixels();
  const auto edge_start = std::chrono::steady_clock::now();
  if (ss > 1 && !frame.cancelled())
  {
    result.statistics.edge_pixels = frame.supersample_edges();
  }
  result.statistics.edge_seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - edge_start).count();
  frame.add_statistics(result.statistics);
  if (frame.cancelled())
  {
    result.error = "cancelled";
    return result;
  }
  imaging::composite_over(target, frame.picture(), 0, 0);
  if (depth)
  {
    *depth = std::move(frame.depth());
  }
  if (run.progress && frame.reported() < 1.0)
  {
    run.progress(1.0);
  }
  result.statistics.seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace frep::raycast
