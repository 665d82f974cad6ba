#include "Raycast/detail/piece_tracer.h"

#include <algorithm>
#include <cmath>

namespace frep::raycast::detail
{

namespace
{

RegionWalkerOptions walk_options(const TraceOptions& options)
{
  RegionWalkerOptions o;
  o.simplify = options.simplify_area > 0;
  // A freeze at every other depth (the other pieces pass their parent's on): making one costs
  // about half an interval evaluation and one level adds little (meta5d 600x600 ray cast 0.92
  // -> 0.87 s, the four key shapes 1-6 % faster; every third depth: 0.88 s).
  o.freeze = true;
  o.freeze_every = 2;
  // The root's tape runs every march and refinement of the image, in batches of a few rays'
  // steps: compile it at once rather than after a thousand samples.
  o.compile_root_now = true;
  o.block = 64;
  return o;
}

} // namespace

namespace
{
// A piece marched without intervals has at most march_budget steps, so at most that many rays.
constexpr std::size_t kMaxMarchRays = 256;
} // namespace

PieceTracer::PieceTracer(std::shared_ptr<const Tape> tape,
  const std::array<Interval, 3>& box,
  const std::array<Interval, 3>& clip,
  const ViewRays& view,
  const TraceOptions& options)
  : model_box_(box)
  , box_(clip)
  , view_(view)
  , options_(options)
  , walker_(std::move(tape), walk_options(options))
{
}

void PieceTracer::trace_tile(int x0, int y0, int x1, int y1, std::span<Hit> hits,
  const unsigned char* active)
{
  tx0_ = x0;
  ty0_ = y0;
  tw_ = x1 - x0;
  const std::size_t count = static_cast<std::size_t>(tw_) * static_cast<std::size_t>(y1 - y0);
  rays_.assign(count, Ray{});
  hits_ = hits.data();
  open_ = 0;
  double l0 = std::numeric_limits<double>::infinity(), l1 = -l0;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y - y0) * tw_ + (x - x0);
      hits[i] = Hit{};
      if (active && !active[i])
      {
        continue;
      }
      Ray& ray = rays_[i];
      view_.ray(x + 0.5, y + 0.5, ray.o, ray.d);
      const auto [in, out] = clip_to_box(ray.o, ray.d, box_, options_.from);
      ++stats_.rays;
      if (in <= out)
      {
        ray.in = in;
        ray.out = out;
        ray.done = false;
        ++open_;
        ++stats_.rays_in_box;
        l0 = std::min(l0, in);
        l1 = std::max(l1, out);
      }
    }
  }
  if (open_ > 0)
  {
    piece(x0, y0, x1, y1, l0, l1, walker_.root());
  }
}

void PieceTracer::set_hit(Ray& ray, Hit& hit, double lambda, HitKind kind)
{
  hit.lambda = lambda;
  hit.kind = kind;
  if (kind == HitKind::Cap)
  {
    // A cap only on a face of the model box; entering the clip box elsewhere inside the
    // solid (which its construction rules out but rounding might not) is a surface point.
    const int face = entry_face(ray.o, ray.d, lambda, box_);
    const int k = face / 2;
    const bool on_model_face =
      face % 2 ? box_[k].hi == model_box_[k].hi : box_[k].lo == model_box_[k].lo;
    hit.face = static_cast<std::uint8_t>(face);
    hit.kind = on_model_face ? HitKind::Cap : HitKind::Surface;
  }
  ray.done = true;
  --open_;
  ++stats_.hits;
}

void PieceTracer::push_point(const Ray& ray, double lambda)
{
  xs_.push_back(std::clamp(ray.o[0] + lambda * ray.d[0], box_[0].lo, box_[0].hi));
  ys_.push_back(std::clamp(ray.o[1] + lambda * ray.d[1], box_[1].lo, box_[1].hi));
  zs_.push_back(std::clamp(ray.o[2] + lambda * ray.d[2], box_[2].lo, box_[2].hi));
}

void PieceTracer::evaluate_points(const RegionWalker::Region& region)
{
  values_.resize(xs_.size());
  if (xs_.empty())
  {
    return;
  }
  const double* inputs[3] = { xs_.data(), ys_.data(), zs_.data() };
  walker_.evaluate(region, inputs, xs_.size(), values_.data());
  stats_.point_evaluations += xs_.size();
}

void PieceTracer::bracket(std::size_t ray, double outside, double f_out, bool out_known,
  double inside, double f_in, bool in_known)
{
  brackets_.push_back({ .ray = ray,
    .outside = outside,
    .f_out = f_out,
    .inside = inside,
    .f_in = f_in,
    .tolerance = options_.tolerance * view_.footprint(inside),
    .out_known = out_known,
    .in_known = in_known });
}

void PieceTracer::refine_brackets(const RegionWalker::Region& region)
{
  if (brackets_.empty())
  {
    return;
  }
  // The unknown ends first, in one batch.
  xs_.clear();
  ys_.clear();
  zs_.clear();
  for (const Bracket& b : brackets_)
  {
    if (!b.out_known)
    {
      push_point(rays_[b.ray], b.outside);
    }
    if (!b.in_known)
    {
      push_point(rays_[b.ray], b.inside);
    }
  }
  evaluate_points(region);
  std::size_t v = 0;
  for (Bracket& b : brackets_)
  {
    b.f_out = b.out_known ? b.f_out : values_[v++];
    b.f_in = b.in_known ? b.f_in : values_[v++];
  }
  // Regula falsi with the Illinois rule (the bracket's stale end has its value halved), which
  // converges superlinearly on smooth F; a bisection step whenever F is not finite or the
  // interpolated point is not strictly inside the bracket. Each ray's steps are those of a ray
  // refined alone; the rays only share the batches.
  for (std::size_t open = brackets_.size(); open > 0;)
  {
    xs_.clear();
    ys_.clear();
    zs_.clear();
    for (Bracket& b : brackets_)
    {
      if (!b.open)
      {
        continue;
      }
      if (b.steps >= 60 || !(std::abs(b.inside - b.outside) > b.tolerance))
      {
        b.open = false;
        --open;
        continue;
      }
      double next = 0.5 * (b.outside + b.inside);
      if (std::isfinite(b.f_out) && std::isfinite(b.f_in) && b.f_in - b.f_out > 0.0)
      {
        const double t = b.outside + (b.inside - b.outside) * (-b.f_out / (b.f_in - b.f_out));
        if ((t - b.outside) * (b.inside - t) > 0.0)
        {
          next = t;
        }
      }
      if (next == b.outside || next == b.inside)
      {
        b.open = false;
        --open;
        continue;
      }
      b.next = next;
      push_point(rays_[b.ray], next);
    }
    if (xs_.empty())
    {
      break;
    }
    evaluate_points(region);
    v = 0;
    for (Bracket& b : brackets_)
    {
      if (!b.open)
      {
        continue;
      }
      const double f = values_[v++];
      ++b.steps;
      if (f >= 0.0)
      {
        b.inside = b.next;
        b.f_in = f;
        b.f_out *= b.stale > 0 ? 0.5 : 1.0;
        b.stale = b.stale > 0 ? b.stale + 1 : 1;
      }
      else
      {
        b.outside = b.next;
        b.f_out = f;
        b.f_in *= b.stale < 0 ? 0.5 : 1.0;
        b.stale = b.stale < 0 ? b.stale - 1 : -1;
      }
    }
  }
  for (const Bracket& b : brackets_)
  {
    set_hit(rays_[b.ray], hits_[b.ray], b.inside, HitKind::Surface);
  }
  brackets_.clear();
}

void PieceTracer::march(
  std::span<const std::size_t> which, double l0, double l1, const RegionWalker::Region& region)
{
  // Every step of every ray in one batch (the SIMD kernel), then each ray's first sign change.
  xs_.clear();
  ys_.clear();
  zs_.clear();
  marches_.clear();
  for (const std::size_t i : which)
  {
    const Ray& ray = rays_[i];
    const double start = std::max(l0, ray.in), end = std::min(l1, ray.out);
    if (ray.done || start > end)
    {
      continue;
    }
    const double step = options_.step * view_.footprint(end);
    const int steps = std::max(1, static_cast<int>(std::ceil((end - start) / step)));
    marches_.push_back({ i, start, end, steps, xs_.size() });
    for (int s = 0; s <= steps; ++s)
    {
      push_point(ray, s == steps ? end : start + (end - start) * s / steps);
    }
  }
  if (xs_.empty())
  {
    return;
  }
  evaluate_points(region);
  // (the brackets' refinement reuses the point buffers: the march's values are read first)
  for (const March& m : marches_)
  {
    Ray& ray = rays_[m.ray];
    Hit& hit = hits_[m.ray];
    const double* f = values_.data() + m.first;
    const auto depth = [&](int s) { return s == m.steps ? m.end : m.start + (m.end - m.start) * s / m.steps; };
    if (f[0] >= 0.0)
    {
      if (m.start == ray.in)
      {
        set_hit(ray, hit, m.start, HitKind::Cap);
      }
      else if (std::isfinite(ray.outside) && ray.outside < m.start)
      {
        bracket(m.ray, ray.outside, 0.0, false, m.start, f[0], true);
      }
      else
      {
        set_hit(ray, hit, m.start, HitKind::Surface);
      }
      continue;
    }
    int s = 1;
    while (s <= m.steps && !(f[s] >= 0.0))
    {
      ++s;
    }
    if (s <= m.steps)
    {
      bracket(m.ray, depth(s - 1), f[s - 1], true, depth(s), f[s], true);
    }
    else
    {
      ray.outside = m.end;
    }
  }
  refine_brackets(region);
}

void PieceTracer::solid(
  int x0, int y0, int x1, int y1, double l0, double l1, const RegionWalker::Region& region)
{
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y - ty0_) * tw_ + (x - tx0_);
      Ray& ray = rays_[i];
      if (ray.done || ray.out < l0 || ray.in > l1)
      {
        continue;
      }
      const double start = std::max(l0, ray.in);
      if (start == ray.in)
      {
        set_hit(ray, hits_[i], start, HitKind::Cap);
      }
      else if (std::isfinite(ray.outside) && ray.outside < start)
      {
        bracket(i, ray.outside, 0.0, false, start, 0.0, false);
      }
      else
      {
        set_hit(ray, hits_[i], start, HitKind::Surface);
      }
    }
  }
  refine_brackets(region);
}

double PieceTracer::march_steps(int x0, int y0, int x1, int y1, double l0, double l1) const
{
  double steps = 0.0;
  const double step = options_.step * view_.footprint(l1);
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      const Ray& ray = rays_[static_cast<std::size_t>(y - ty0_) * tw_ + (x - tx0_)];
      if (!ray.done)
      {
        steps += 1.0 + std::max(0.0, std::min(l1, ray.out) - std::max(l0, ray.in)) / step;
      }
    }
  }
  return steps;
}

void PieceTracer::piece(
  int x0, int y0, int x1, int y1, double l0, double l1, const RegionWalker::Region& region)
{
  // The depths the open rays of the piece still search.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int y = y0; y < y1; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      const Ray& ray = rays_[static_cast<std::size_t>(y - ty0_) * tw_ + (x - tx0_)];
      if (!ray.done && ray.out >= l0 && ray.in <= l1)
      {
        lo = std::min(lo, std::max(l0, ray.in));
        hi = std::max(hi, std::min(l1, ray.out));
      }
    }
  }
  if (!(lo <= hi))
  {
    return;
  }
  l0 = lo;
  l1 = hi;

  // Marching every open ray of a small piece costs fewer point evaluations than an interval
  // evaluation costs (about 20 of them, measured on the key shapes): march it.
  const double steps = march_steps(x0, y0, x1, y1, l0, l1);
  if (steps <= options_.march_budget)
  {
    std::size_t which[kMaxMarchRays];
    std::size_t n = 0;
    for (int y = y0; y < y1; ++y)
    {
      for (int x = x0; x < x1; ++x)
      {
        const std::size_t i = static_cast<std::size_t>(y - ty0_) * tw_ + (x - tx0_);
        if (!rays_[i].done && n < kMaxMarchRays)
        {
          which[n++] = i;
        }
      }
    }
    march(std::span<const std::size_t>(which, n), l0, l1, region);
    return;
  }

  std::array<Interval, 3> region_box;
  if (!piece_box(view_, x0, x1, y0, y1, l0, l1, box_, region_box))
  {
    return;
  }
  const int area = (x1 - x0) * (y1 - y0);
  ++stats_.interval_evaluations;
  const IntervalResult r = walker_.enclose(region, region_box, area >= options_.simplify_area);
  if (r.value.hi < 0.0)
  {
    // Empty for every ray: each knows a depth outside, for the bisection of a solid piece behind.
    for (int y = y0; y < y1; ++y)
    {
      for (int x = x0; x < x1; ++x)
      {
        Ray& ray = rays_[static_cast<std::size_t>(y - ty0_) * tw_ + (x - tx0_)];
        if (!ray.done && ray.in <= l1 && ray.out >= l0)
        {
          ray.outside = std::min(l1, ray.out);
        }
      }
    }
    return;
  }
  if (r.value.lo >= 0.0 && !r.may_fail)
  {
    solid(x0, y0, x1, y1, l0, l1, region);
    return;
  }

  // Ambiguous: maybe a shorter tape for everything below (or what this piece dominates need
  // not be evaluated again inside it), then split.
  const RegionWalker::Region use = walker_.descend(region);
  const int w = x1 - x0, h = y1 - y0;
  const double width = std::max(w, h) * view_.footprint(l1);
  const double depth = l1 - l0;
  if (w == 1 && h == 1)
  {
    const std::size_t i = static_cast<std::size_t>(y0 - ty0_) * tw_ + (x0 - tx0_);
    if (depth > options_.leaf_depth * view_.footprint(l1) && depth > 0.0)
    {
      const double mid = 0.5 * (l0 + l1);
      piece(x0, y0, x1, y1, l0, mid, use);
      if (!rays_[i].done)
      {
        piece(x0, y0, x1, y1, mid, l1, use);
      }
      return;
    }
    march(std::span<const std::size_t>(&i, 1), l0, l1, use);
    return;
  }
  if (depth > 2.0 * width)
  {
    const double mid = 0.5 * (l0 + l1);
    piece(x0, y0, x1, y1, l0, mid, use);
    piece(x0, y0, x1, y1, mid, l1, use);
    return;
  }
  const int xm = w > 1 ? x0 + w / 2 : x1, ym = h > 1 ? y0 + h / 2 : y1;
  piece(x0, y0, xm, ym, l0, l1, use);
  if (xm < x1)
  {
    piece(xm, y0, x1, ym, l0, l1, use);
  }
  if (ym < y1)
  {
    piece(x0, ym, xm, y1, l0, l1, use);
    if (xm < x1)
    {
      piece(xm, ym, x1, y1, l0, l1, use);
    }
  }
}

} // namespace frep::raycast::detail
