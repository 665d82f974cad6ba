// What is computed per point once the mesh is joined: roots refined along their grid edge,
// outward normals from the model's gradient (differences of F, or forward-mode gradients where
// the tape calls functions with exact derivatives), and s[] attributes.
#include "Mesh/detail/extraction_common.h"

#include "Eval/batch_evaluator.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Eval/region_walker.h"
#include "Eval/thread_pool.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <span>

namespace frep::mesh::detail
{
namespace
{

constexpr std::size_t chunk_points = 4096;

struct EdgeOfKey
{
  std::array<std::int64_t, 3> vertex{};
  int kind = 3; ///< axis of the edge, 3 for a grid vertex
};

EdgeOfKey decode(std::uint64_t key, const GridFrame& frame)
{
  EdgeOfKey e;
  e.kind = static_cast<int>(key % 4u);
  std::uint64_t v = key / 4u;
  for (int a = 0; a < frame.dimension; ++a)
  {
    e.vertex[a] = static_cast<std::int64_t>(v % static_cast<std::uint64_t>(frame.samples[a]));
    v /= static_cast<std::uint64_t>(frame.samples[a]);
  }
  return e;
}

// Regula falsi (Illinois) on the grid edge of a crossing, keeping the bracket: the point stays on
// its edge, so the mesh keeps its topology.
void refine(PointEvaluator& evaluator, const GridFrame& frame, const EdgeOfKey& e, double iso,
  int steps, double* point)
{
  std::array<double, 3> p{};
  for (int a = 0; a < frame.dimension; ++a)
  {
    p[a] = frame.coord(a, e.vertex[a]);
  }
  const std::span<const double> in(p.data(), static_cast<std::size_t>(frame.dimension));
  const int axis = e.kind;
  double t0 = frame.coord(axis, e.vertex[axis]);
  double t1 = frame.coord(axis, e.vertex[axis] + 1);
  p[axis] = t0;
  double g0 = evaluator.value(in) - iso;
  p[axis] = t1;
  double g1 = evaluator.value(in) - iso;
  if (!std::isfinite(g0) || !std::isfinite(g1) || (g0 >= 0) == (g1 >= 0))
  {
    return;
  }
  double t = point[axis];
  int same_side = 0;
  for (int s = 0; s < steps; ++s)
  {
    t = (t0 * g1 - t1 * g0) / (g1 - g0);
    p[axis] = t;
    const double g = evaluator.value(in) - iso;
    if (!std::isfinite(g) || g == 0.0)
    {
      break;
    }
    if ((g >= 0) == (g0 >= 0))
    {
      t0 = t;
      g0 = g;
      if (same_side == -1)
      {
        g1 *= 0.5;
      }
      same_side = -1;
    }
    else
    {
      t1 = t;
      g1 = g;
      if (same_side == 1)
      {
        g0 *= 0.5;
      }
      same_side = 1;
    }
  }
  if (std::isfinite(t))
  {
    point[axis] = t;
  }
}

// Normals where the gradient gives none (a failed or flat point): the area-weighted normals of
// the triangles around the point.
void fill_missing_normals(Surface& surface, const std::vector<unsigned char>& missing)
{
  std::vector<double> sum(surface.points.size(), 0.0);
  const auto& x = surface.points;
  for (std::size_t t = 0; t + 2 < surface.cells.size(); t += 3)
  {
    const std::uint32_t a = surface.cells[t], b = surface.cells[t + 1], c = surface.cells[t + 2];
    if (!missing[a] && !missing[b] && !missing[c])
    {
      continue;
    }
    const double u[3] = { x[3 * b] - x[3 * a], x[3 * b + 1] - x[3 * a + 1], x[3 * b + 2] - x[3 * a + 2] };
    const double v[3] = { x[3 * c] - x[3 * a], x[3 * c + 1] - x[3 * a + 1], x[3 * c + 2] - x[3 * a + 2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    for (std::uint32_t id : { a, b, c })
    {
      for (int k = 0; k < 3; ++k)
      {
        sum[3 * id + static_cast<std::size_t>(k)] += n[k];
      }
    }
  }
  for (std::size_t p = 0; p < missing.size(); ++p)
  {
    if (missing[p])
    {
      const double length = std::sqrt(sum[3 * p] * sum[3 * p] + sum[3 * p + 1] * sum[3 * p + 1] +
        sum[3 * p + 2] * sum[3 * p + 2]);
      for (int k = 0; k < 3; ++k)
      {
        surface.normals[3 * p + static_cast<std::size_t>(k)] =
          length > 0 ? static_cast<float>(sum[3 * p + static_cast<std::size_t>(k)] / length) : 0.0f;
      }
    }
  }
}

// Outward normals by forward differences of F, evaluated in batches (vectorised, on the pool):
// four evaluations per point (F at the point and one step along each axis) cost far less than a
// forward-mode gradient of a long tape; the step (1e-3 of a cell) is far below the grid's
// resolution (its truncation error is invisible in a normal) and far above rounding.
constexpr int probes = 4; // the point, then +h along x, y, z

/// Appends the probes of point p to the input columns.
void add_probes(const Surface& surface, std::size_t p, const std::array<double, 3>& h,
  std::array<std::vector<double>, 3>& in)
{
  for (int d = 0; d < probes; ++d)
  {
    for (int a = 0; a < 3; ++a)
    {
      in[a].push_back(surface.points[3 * p + static_cast<std::size_t>(a)] + (d == a + 1 ? h[a] : 0.0));
    }
  }
}

/// The normals of points ids from F at their probes (values, probes per point).
void store_normals(const std::vector<double>& values, std::span<const std::size_t> ids,
  const std::array<double, 3>& h, Surface& surface, std::vector<unsigned char>& missing)
{
  for (std::size_t q = 0; q < ids.size(); ++q)
  {
    const double* v = &values[probes * q];
    // F grows inwards: the outward normal is -grad F.
    const double g[3] = { (v[0] - v[1]) / h[0], (v[0] - v[2]) / h[1], (v[0] - v[3]) / h[2] };
    const double length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    float* n = &surface.normals[3 * ids[q]];
    if (!(length > 0) || !std::isfinite(length))
    {
      missing[ids[q]] = 1;
      continue;
    }
    for (int a = 0; a < 3; ++a)
    {
      n[a] = static_cast<float>(g[a] / length);
    }
  }
}

/// Evaluates F at the probes of `ids` with `evaluate(inputs, count, values)` (a batch evaluator
/// or a runner) and stores their normals.
template<class Evaluate>
void probe_normals(Evaluate&& evaluate, std::span<const std::size_t> ids,
  const std::array<double, 3>& h, Surface& surface, std::vector<unsigned char>& missing,
  std::array<std::vector<double>, 3>& in, std::vector<double>& values)
{
  for (auto& column : in)
  {
    column.clear();
  }
  for (std::size_t p : ids)
  {
    add_probes(surface, p, h, in);
  }
  values.resize(in[0].size());
  const std::array<const double*, 3> inputs{ in[0].data(), in[1].data(), in[2].data() };
  evaluate(inputs, values.size(), values.data());
  store_normals(values, ids, h, surface, missing);
}

/// Points whose normals come from differences (not the grid vertices of caps, done by
/// cap_normals).
bool needs_difference_normal(std::uint64_t key)
{
  return key == unshared_key || key % 4u != 3u;
}

/// Every point with the full tape, in chunks spread over the pool by the batch evaluator.
void full_tape_normals(const std::shared_ptr<const Tape>& tape, const std::vector<std::uint64_t>& keys,
  const ExtractOptions& options, const std::shared_ptr<ThreadPool>& pool,
  const std::array<double, 3>& h, Surface& surface, std::vector<unsigned char>& missing)
{
  const std::size_t count = surface.point_count();
  BatchOptions batch_options;
  batch_options.pool = pool;
  batch_options.jit = options.jit;
  BatchEvaluator batch(tape, batch_options);
  constexpr std::size_t chunk = 1 << 15;
  std::array<std::vector<double>, 3> in;
  std::vector<double> values;
  std::vector<std::size_t> ids;
  for (std::size_t begin = 0; begin < count; begin += chunk)
  {
    const std::size_t end = std::min(count, begin + chunk);
    ids.clear();
    for (std::size_t p = begin; p < end; ++p)
    {
      if (needs_difference_normal(keys[p]))
      {
        ids.push_back(p);
      }
    }
    probe_normals(
      [&](const std::array<const double*, 3>& inputs, std::size_t n, double* out)
      { batch.evaluate(inputs, n, out); },
      ids, h, surface, missing, in, values);
  }
}

/// The box that holds the probes of the points on the grid edges starting at the vertices
/// v0..v0+size-1 per axis: those edges end at most one vertex further; a point on an edge may be
/// an ulp or so past its ends (interpolation rounds), and a probe adds h. The pad covers both,
/// with room to spare (a wider box is only less tight).
std::array<Interval, 3> probe_box(const GridFrame& frame, const std::array<std::int64_t, 3>& v0,
  std::int64_t size, const std::array<double, 3>& h)
{
  std::array<Interval, 3> box{};
  for (int a = 0; a < 3; ++a)
  {
    const double x0 = frame.coord(a, v0[a]);
    const double x1 = frame.coord(a, v0[a] + size);
    const double pad = h[a] + 16 * DBL_EPSILON * std::max(std::fabs(x0), std::fabs(x1));
    box[a] = { x0 - pad, x1 + 2 * pad };
  }
  return box;
}

/// What one pool participant of brick_normals keeps from brick to brick: the full tape's
/// evaluators, the simplifier, and the runner, interval evaluator and kernel of the bricks' tapes.
struct BrickParticipant
{
  // The full tape at the root, a super-brick's simplified tape below it and a brick's below
  // that: rebound from brick to brick (no evaluator or kernel is made per brick).
  RegionWalker walker;
  std::array<std::vector<double>, 3> in;
  std::vector<double> values;

  BrickParticipant(const std::shared_ptr<const Tape>& tape, bool jit)
    : walker(tape, walk_options(jit))
  {
  }
  static RegionWalkerOptions walk_options(bool jit)
  {
    RegionWalkerOptions o;
    o.jit = jit;
    return o;
  }
  /// F of the region's tape at `n` points, on this thread.
  auto evaluator(const RegionWalker::Region& region)
  {
    return [this, region](const std::array<const double*, 3>& inputs, std::size_t n, double* out)
    { walker.evaluate(region, inputs, n, out); };
  }
};

/// A point needing a difference normal, by (super-brick, brick, point).
struct BrickEntry
{
  std::uint64_t super, brick;
  std::size_t point;
  bool operator<(const BrickEntry& o) const
  {
    return super != o.super ? super < o.super : brick != o.brick ? brick < o.brick : point < o.point;
  }
};

/// No super-brick or brick: a cell-centre point (no edge), evaluated on the full tape, last.
constexpr std::uint64_t kNoBrick = std::numeric_limits<std::uint64_t>::max();

/// The points of brick_normals in brick order: `order` sorted, `ids` its points, and the start
/// of each super-brick's run in it (with order.size() at the end).
struct BrickOrder
{
  std::vector<BrickEntry> order;
  std::vector<std::size_t> ids;
  std::vector<std::size_t> super_begin;
};

BrickOrder order_by_brick(const GridFrame& frame, const std::vector<std::uint64_t>& keys,
  std::int64_t brick, std::int64_t super)
{
  BrickOrder out;
  const auto linear = [&](const std::array<std::int64_t, 3>& v, std::int64_t size)
  {
    std::array<std::uint64_t, 3> n{};
    for (int a = 0; a < 3; ++a)
    {
      n[a] = static_cast<std::uint64_t>((frame.samples[a] + size - 1) / size);
    }
    const auto c = [&](int a) { return static_cast<std::uint64_t>(v[a] / size); };
    return (c(2) * n[1] + c(1)) * n[0] + c(0);
  };
  // (super-brick, brick, point) sorted; the cell-centre points (no edge) go last, full tape.
  std::vector<BrickEntry>& order = out.order;
  order.reserve(keys.size());
  for (std::size_t p = 0; p < keys.size(); ++p)
  {
    if (!needs_difference_normal(keys[p]))
    {
      continue;
    }
    if (keys[p] == unshared_key)
    {
      order.push_back({ kNoBrick, kNoBrick, p });
      continue;
    }
    const EdgeOfKey e = decode(keys[p], frame);
    order.push_back({ linear(e.vertex, super), linear(e.vertex, brick), p });
  }
  std::sort(order.begin(), order.end());
  std::vector<std::size_t>& ids = out.ids;
  std::vector<std::size_t>& super_begin = out.super_begin;
  ids.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    ids[i] = order[i].point;
    if (i == 0 || order[i].super != order[i - 1].super)
    {
      super_begin.push_back(i);
    }
  }
  super_begin.push_back(order.size());
  return out;
}

/// The same values brick by brick: the points on the grid edges that start in a brick of
/// leaf_cells^3 vertices, with the tape simplified for the box that holds their probes, in two
/// steps (a super-brick of 4^3 bricks from the full tape, then each brick from the super-brick's
/// tape: simplifying the full tape for every brick would cost more than it saves on long tapes).
/// tape_simplifier.h: the values are the full tape's bit for bit, so are the normals.
void brick_normals(const std::shared_ptr<const Tape>& tape, const GridFrame& frame,
  const std::vector<std::uint64_t>& keys, const ExtractOptions& options,
  const std::shared_ptr<ThreadPool>& pool, const std::array<double, 3>& h, Surface& surface,
  std::vector<unsigned char>& missing)
{
  const std::int64_t brick = std::max(1, options.leaf_cells);
  const std::int64_t super = 4 * brick;
  const BrickOrder sorted = order_by_brick(frame, keys, brick, super);
  const std::vector<BrickEntry>& order = sorted.order;
  const std::vector<std::size_t>& ids = sorted.ids;
  const std::vector<std::size_t>& super_begin = sorted.super_begin;

  const auto corner = [&](std::size_t point, std::int64_t size)
  {
    std::array<std::int64_t, 3> v = decode(keys[point], frame).vertex;
    for (auto& c : v)
    {
      c = c / size * size;
    }
    return v;
  };
  std::vector<std::unique_ptr<BrickParticipant>> participants(static_cast<std::size_t>(pool->size()));
  pool->parallel_for(super_begin.size() - 1,
    [&](std::size_t g, int slot)
    {
      auto& mine = participants[static_cast<std::size_t>(slot)];
      if (!mine)
      {
        mine = std::make_unique<BrickParticipant>(tape, options.jit);
      }
      BrickParticipant& pt = *mine;
      const std::size_t begin = super_begin[g], end = super_begin[g + 1];
      const RegionWalker::Region root = pt.walker.root();
      const std::span<const std::size_t> all(ids.data() + begin, end - begin);
      // A cell-centre point (no brick), or the full tape's super-bricks stopped simplifying.
      if (order[begin].super == kNoBrick || !pt.walker.would_simplify(root))
      {
        probe_normals(pt.evaluator(root), all, h, surface, missing, pt.in, pt.values);
        return;
      }
      pt.walker.enclose(root, probe_box(frame, corner(ids[begin], super), super, h));
      const RegionWalker::Region in_super = pt.walker.descend(root);
      if (pt.walker.tape(in_super) == tape)
      {
        probe_normals(pt.evaluator(in_super), all, h, surface, missing, pt.in, pt.values);
        return;
      }
      for (std::size_t b = begin; b < end;)
      {
        std::size_t e = b;
        while (e < end && order[e].brick == order[b].brick)
        {
          ++e;
        }
        const std::span<const std::size_t> group(ids.data() + b, e - b);
        pt.walker.enclose(in_super, probe_box(frame, corner(ids[b], brick), brick, h));
        probe_normals(pt.evaluator(pt.walker.descend(in_super)), group, h, surface, missing, pt.in,
          pt.values);
        b = e;
      }
    });
}

/// Whether the tape calls a function with exact derivatives (a projection, a mesh's or a volume's
/// distance, a tape function): each call is the costly part of a point, and a forward-mode
/// gradient makes it once per point (its own derivatives exact) where differences make it four
/// times. A projection's values are only within its tolerance of the maximum, too far apart for
/// differences of 1e-3 of a cell; its gradient (F's at the maximiser) is right.
bool calls_with_gradients(const Tape& tape)
{
  return std::any_of(tape.calls.begin(), tape.calls.end(),
    [](const CallSite& c) { return c.function && c.function->has_jacobian(); });
}

/// The normals of the points that need one from forward-mode gradients, chunks on the pool.
void gradient_normals(const std::shared_ptr<const Tape>& tape,
  const std::vector<std::uint64_t>& keys, const std::shared_ptr<ThreadPool>& pool,
  Surface& surface, std::vector<unsigned char>& missing)
{
  const std::size_t count = surface.point_count();
  const std::size_t chunks = (count + chunk_points - 1) / chunk_points;
  std::vector<std::unique_ptr<GradientEvaluator>> evaluators(static_cast<std::size_t>(pool->size()));
  pool->parallel_for(chunks,
    [&](std::size_t chunk, int slot)
    {
      auto& evaluator = evaluators[static_cast<std::size_t>(slot)];
      if (!evaluator)
        evaluator = std::make_unique<GradientEvaluator>(tape);
      std::array<double, 3> g{};
      const std::size_t end = std::min(count, (chunk + 1) * chunk_points);
      for (std::size_t p = chunk * chunk_points; p < end; ++p)
      {
        if (!needs_difference_normal(keys[p]))
          continue;
        evaluator->evaluate(std::span<const double>(&surface.points[3 * p], 3), g);
        const double length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (!(length > 0) || !std::isfinite(length))
        {
          missing[p] = 1;
          continue;
        }
        for (int a = 0; a < 3; ++a) // F grows inwards: the outward normal is -grad F
          surface.normals[3 * p + static_cast<std::size_t>(a)] = static_cast<float>(-g[a] / length);
      }
    });
}

void point_normals(const std::shared_ptr<const Tape>& tape, const GridFrame& frame,
  const std::vector<std::uint64_t>& keys, const ExtractOptions& options,
  const std::shared_ptr<ThreadPool>& pool, Surface& surface, std::vector<unsigned char>& missing)
{
  std::array<double, 3> h{};
  for (int a = 0; a < 3; ++a)
  {
    h[a] = 1e-3 * frame.step[a];
  }
  if (calls_with_gradients(*tape))
  {
    gradient_normals(tape, keys, pool, surface, missing);
  }
  else if (options.cull && options.simplify && may_simplify(*tape))
  {
    brick_normals(tape, frame, keys, options, pool, h, surface, missing);
  }
  else
  {
    full_tape_normals(tape, keys, options, pool, h, surface, missing);
  }
}

// A grid vertex is a point of a cap: the box's outward normal there.
void cap_normals(const GridFrame& frame, const std::vector<std::uint64_t>& keys, Surface& surface)
{
  for (std::size_t p = 0; p < keys.size(); ++p)
  {
    if (keys[p] == unshared_key || keys[p] % 4u != 3u)
    {
      continue;
    }
    const EdgeOfKey e = decode(keys[p], frame);
    double sum[3] = { 0, 0, 0 };
    for (int a = 0; a < 3; ++a)
    {
      sum[a] = e.vertex[a] == 0 ? -1.0 : e.vertex[a] == frame.samples[a] - 1 ? 1.0 : 0.0;
    }
    const double length = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    for (int a = 0; a < 3; ++a)
    {
      surface.normals[3 * p + static_cast<std::size_t>(a)] = static_cast<float>(sum[a] / length);
    }
  }
}

} // namespace

void finish_points(const std::shared_ptr<const Tape>& tape, const GridFrame& frame,
  const std::vector<std::uint64_t>& keys, const ExtractOptions& options,
  const std::shared_ptr<ThreadPool>& pool,
  Surface& surface, ExtractStatistics& /*statistics*/)
{
  const std::size_t count = surface.point_count();
  const int dim = frame.dimension;
  if (options.refine_steps > 0)
  {
    const std::size_t chunks = (count + chunk_points - 1) / chunk_points;
    std::vector<std::unique_ptr<PointEvaluator>> evaluators(static_cast<std::size_t>(pool->size()));
    pool->parallel_for(chunks,
      [&](std::size_t chunk, int slot)
      {
        auto& evaluator = evaluators[static_cast<std::size_t>(slot)];
        if (!evaluator)
        {
          evaluator = std::make_unique<PointEvaluator>(tape);
        }
        const std::size_t end = std::min(count, (chunk + 1) * chunk_points);
        for (std::size_t p = chunk * chunk_points; p < end; ++p)
        {
          if (keys[p] != unshared_key && keys[p] % 4u != 3u)
          {
            refine(*evaluator, frame, decode(keys[p], frame), options.iso, options.refine_steps,
              &surface.points[3 * p]);
          }
        }
      });
  }
  if (options.normals && dim == 3)
  {
    surface.normals.assign(3 * count, 0.0f);
    std::vector<unsigned char> missing(count, 0);
    cap_normals(frame, keys, surface);
    point_normals(tape, frame, keys, options, pool, surface, missing);
    fill_missing_normals(surface, missing);
  }
  const int attribute_count = static_cast<int>(tape->outputs.size()) - 1;
  surface.attribute_count = attribute_count;
  if (options.attributes && attribute_count > 0 && count > 0)
  {
    BatchOptions batch_options;
      batch_options.pool = pool;
    batch_options.jit = options.jit;
    BatchEvaluator batch(tape, batch_options);
    std::vector<double> xyz[3];
    for (int a = 0; a < dim; ++a)
    {
      xyz[a].resize(count);
      for (std::size_t p = 0; p < count; ++p)
      {
        xyz[a][p] = surface.points[3 * p + static_cast<std::size_t>(a)];
      }
    }
    const std::array<const double*, 3> inputs{ xyz[0].data(), xyz[1].data(),
      dim == 3 ? xyz[2].data() : nullptr };
    std::vector<double> values(count);
    std::vector<std::vector<double>> s(static_cast<std::size_t>(attribute_count),
      std::vector<double>(count));
    std::vector<double*> outputs;
    for (auto& column : s)
    {
      outputs.push_back(column.data());
    }
    batch.evaluate(std::span<const double* const>(inputs.data(), static_cast<std::size_t>(dim)),
      count, values.data(), nullptr, outputs);
    surface.attributes.resize(count * static_cast<std::size_t>(attribute_count));
    for (std::size_t p = 0; p < count; ++p)
    {
      for (int k = 0; k < attribute_count; ++k)
      {
        surface.attributes[p * static_cast<std::size_t>(attribute_count) + static_cast<std::size_t>(k)] =
          static_cast<float>(s[static_cast<std::size_t>(k)][p]);
      }
    }
  }
  else
  {
    surface.attributes.clear();
  }
}

} // namespace frep::mesh::detail
