#include "Shapes/mesh_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace frep::shapes
{
namespace
{

using V = std::array<double, 3>;

V sub(const V& a, const V& b) { return { a[0] - b[0], a[1] - b[1], a[2] - b[2] }; }
V add(const V& a, const V& b) { return { a[0] + b[0], a[1] + b[1], a[2] + b[2] }; }
V scale(const V& a, double s) { return { a[0] * s, a[1] * s, a[2] * s }; }
double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V cross(const V& a, const V& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double length(const V& a) { return std::sqrt(dot(a, a)); }
V normalised(const V& a)
{
  const double l = length(a);
  return l > 0 ? scale(a, 1 / l) : V{ 0, 0, 0 };
}

constexpr std::uint32_t kLeafSize = 4;

// Squared distance from p to the box [lo, hi].
double box_d2(const V& p, const V& lo, const V& hi)
{
  double d2 = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = std::max({ lo[k] - p[k], 0.0, p[k] - hi[k] });
    d2 += d * d;
  }
  return d2;
}

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5), with the
// feature it lies on: 0..2 a vertex, 3..5 the edge from vertex k-3 to the next, 6 the face.
V closest_on_triangle(const V& p, const V& a, const V& b, const V& c, int& feature)
{
  const V ab = sub(b, a);
  const V ac = sub(c, a);
  const V ap = sub(p, a);
  const double d1 = dot(ab, ap);
  const double d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
  {
    feature = 0;
    return a;
  }
  const V bp = sub(p, b);
  const double d3 = dot(ab, bp);
  const double d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
  {
    feature = 1;
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    feature = 3;
    return add(a, scale(ab, d1 / (d1 - d3)));
  }
  const V cp = sub(p, c);
  const double d5 = dot(ab, cp);
  const double d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
  {
    feature = 2;
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    feature = 5; // edge c -> a
    return add(a, scale(ac, d2 / (d2 - d6)));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    feature = 4;
    return add(b, scale(sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
  }
  const double denom = va + vb + vc;
  if (!(denom > 0))
  {
    feature = 0; // a degenerate triangle: its first vertex stands for it
    return a;
  }
  feature = 6;
  const double v = vb / denom;
  const double w = vc / denom;
  return add(a, add(scale(ab, v), scale(ac, w)));
}

} // namespace

MeshDistance::BuildResult MeshDistance::build(TriangleMesh mesh, bool signed_distance)
{
  BuildResult result;
  if (std::string e = validate(mesh); !e.empty())
  {
    result.error = e;
    return result;
  }
  result.edges = count_edges(mesh);
  if (signed_distance && !result.edges.closed())
  {
    result.error = describe_open(result.edges) +
      "; a signed distance needs a closed, consistently oriented mesh (or ask for the unsigned "
      "distance)";
    return result;
  }
  auto d = std::shared_ptr<MeshDistance>(new MeshDistance());
  d->signed_ = signed_distance;
  d->points_ = std::move(mesh.points);
  d->triangles_ = std::move(mesh.triangles);
  const std::size_t nt = d->triangles_.size() / 3;
  const auto point = [&](std::uint32_t id)
  { return V{ d->points_[3 * id], d->points_[3 * id + 1], d->points_[3 * id + 2] }; };

  if (signed_distance)
  {
    // An inward-oriented closed mesh has a negative volume: flip it so outward is outward.
    double volume = 0;
    for (std::size_t t = 0; t < nt; ++t)
    {
      const V a = point(d->triangles_[3 * t]);
      const V b = point(d->triangles_[3 * t + 1]);
      const V c = point(d->triangles_[3 * t + 2]);
      volume += dot(a, cross(b, c));
    }
    if (volume < 0)
    {
      d->flipped_ = true;
      for (std::size_t t = 0; t < nt; ++t)
      {
        std::swap(d->triangles_[3 * t + 1], d->triangles_[3 * t + 2]);
      }
    }
  }

  // Pseudonormals: faces; vertices by incident angles; edges as the sum of their two faces.
  d->face_normal_.resize(nt);
  d->vertex_normal_.assign(d->points_.size() / 3, V{ 0, 0, 0 });
  d->edge_normal_.assign(3 * nt, V{ 0, 0, 0 });
  std::unordered_map<std::uint64_t, V> edge_sum;
  edge_sum.reserve(3 * nt);
  const auto edge_key = [](std::uint32_t a, std::uint32_t b)
  { return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b); };
  for (std::size_t t = 0; t < nt; ++t)
  {
    const std::uint32_t* v = &d->triangles_[3 * t];
    const V p[3] = { point(v[0]), point(v[1]), point(v[2]) };
    const V n = normalised(cross(sub(p[1], p[0]), sub(p[2], p[0])));
    d->face_normal_[t] = n;
    for (int k = 0; k < 3; ++k)
    {
      const V e1 = normalised(sub(p[(k + 1) % 3], p[k]));
      const V e2 = normalised(sub(p[(k + 2) % 3], p[k]));
      const double angle = std::acos(std::clamp(dot(e1, e2), -1.0, 1.0));
      d->vertex_normal_[v[k]] = add(d->vertex_normal_[v[k]], scale(n, angle));
      V& s = edge_sum[edge_key(v[k], v[(k + 1) % 3])];
      s = add(s, n);
    }
  }
  for (std::size_t t = 0; t < nt; ++t)
  {
    const std::uint32_t* v = &d->triangles_[3 * t];
    for (int k = 0; k < 3; ++k)
    {
      d->edge_normal_[3 * t + k] = edge_sum[edge_key(v[k], v[(k + 1) % 3])];
    }
  }

  // The hierarchy: median splits on the longest axis of the centroids.
  std::vector<V> centroid(nt);
  for (std::size_t t = 0; t < nt; ++t)
  {
    const V a = point(d->triangles_[3 * t]);
    const V b = point(d->triangles_[3 * t + 1]);
    const V c = point(d->triangles_[3 * t + 2]);
    centroid[t] = scale(add(a, add(b, c)), 1.0 / 3.0);
  }
  d->order_.resize(nt);
  std::iota(d->order_.begin(), d->order_.end(), 0u);
  d->nodes_.reserve(2 * (nt / kLeafSize + 1));
  d->build_node(0, static_cast<std::uint32_t>(nt), centroid);
  result.distance = std::move(d);
  return result;
}

std::uint32_t MeshDistance::build_node(std::uint32_t begin, std::uint32_t end,
  std::vector<std::array<double, 3>>& centroid)
{
  const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.lo = { INFINITY, INFINITY, INFINITY };
  node.hi = { -INFINITY, -INFINITY, -INFINITY };
  V clo = node.lo;
  V chi = node.hi;
  for (std::uint32_t i = begin; i < end; ++i)
  {
    const std::uint32_t t = order_[i];
    for (int j = 0; j < 3; ++j)
    {
      const std::uint32_t id = triangles_[3 * t + j];
      for (int k = 0; k < 3; ++k)
      {
        node.lo[k] = std::min(node.lo[k], points_[3 * id + k]);
        node.hi[k] = std::max(node.hi[k], points_[3 * id + k]);
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      clo[k] = std::min(clo[k], centroid[t][k]);
      chi[k] = std::max(chi[k], centroid[t][k]);
    }
  }
  if (end - begin <= kLeafSize)
  {
    node.first = begin;
    node.count = end - begin;
    nodes_[index] = node;
    return index;
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (chi[k] - clo[k] > chi[axis] - clo[axis])
    {
      axis = k;
    }
  }
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
    [&](std::uint32_t a, std::uint32_t b) { return centroid[a][axis] < centroid[b][axis]; });
  node.count = 0;
  nodes_[index] = node;
  const std::uint32_t left = build_node(begin, mid, centroid);
  const std::uint32_t right = build_node(mid, end, centroid);
  nodes_[index].first = left;
  nodes_[index].right = right;
  return index;
}

MeshDistance::Closest MeshDistance::closest(const std::array<double, 3>& p) const
{
  Closest best;
  best.d2 = INFINITY;
  // Depth-first, nearer child first; a subtree farther than the best so far is skipped.
  std::array<std::uint32_t, 128> stack{};
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& n = nodes_[stack[--top]];
    if (box_d2(p, n.lo, n.hi) >= best.d2)
    {
      continue;
    }
    if (n.count > 0)
    {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
      {
        const std::uint32_t t = order_[i];
        const std::uint32_t* v = &triangles_[3 * t];
        const V a{ points_[3 * v[0]], points_[3 * v[0] + 1], points_[3 * v[0] + 2] };
        const V b{ points_[3 * v[1]], points_[3 * v[1] + 1], points_[3 * v[1] + 2] };
        const V c{ points_[3 * v[2]], points_[3 * v[2] + 1], points_[3 * v[2] + 2] };
        int feature = 0;
        const V q = closest_on_triangle(p, a, b, c, feature);
        const V pq = sub(p, q);
        const double d2 = dot(pq, pq);
        if (d2 < best.d2)
        {
          best = Closest{ d2, q, t, feature };
        }
      }
      continue;
    }
    const std::uint32_t l = n.first;
    const std::uint32_t r = n.right;
    const double dl = box_d2(p, nodes_[l].lo, nodes_[l].hi);
    const double dr = box_d2(p, nodes_[r].lo, nodes_[r].hi);
    if (top + 2 > static_cast<int>(stack.size()))
    {
      continue; // cannot happen for median splits (depth ~ log2 n); never overflow
    }
    // Push the farther first so the nearer is searched first.
    if (dl < dr)
    {
      stack[top++] = r;
      stack[top++] = l;
    }
    else
    {
      stack[top++] = l;
      stack[top++] = r;
    }
  }
  return best;
}

double MeshDistance::sign_at(const std::array<double, 3>& p, const Closest& c) const
{
  V normal;
  if (c.feature < 3)
  {
    normal = vertex_normal_[triangles_[3 * c.triangle + c.feature]];
  }
  else if (c.feature < 6)
  {
    normal = edge_normal_[3 * c.triangle + (c.feature - 3)];
  }
  else
  {
    normal = face_normal_[c.triangle];
  }
  return dot(sub(p, c.point), normal) >= 0 ? -1.0 : 1.0; // outside: F < 0
}

double MeshDistance::distance(const std::array<double, 3>& p) const
{
  return std::sqrt(closest(p).d2);
}

double MeshDistance::value(const std::array<double, 3>& p) const
{
  const Closest c = closest(p);
  const double d = std::sqrt(c.d2);
  return signed_ ? sign_at(p, c) * d : -d;
}

double MeshDistance::value_and_gradient(const std::array<double, 3>& p, std::array<double, 3>& g) const
{
  const Closest c = closest(p);
  const double d = std::sqrt(c.d2);
  const double s = signed_ ? sign_at(p, c) : -1.0;
  if (d > 0)
  {
    // F = s d: grad = s (p - c) / d (inside, d grows away from the surface).
    g = scale(sub(p, c.point), s / d);
  }
  else
  {
    g = scale(face_normal_[c.triangle], -1.0); // on the surface: inward
  }
  return s * d;
}

bool MeshDistance::enclose(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
  double& f_lo, double& f_hi) const
{
  V centre;
  double r2 = 0;
  for (int k = 0; k < 3; ++k)
  {
    if (!std::isfinite(lo[k]) || !std::isfinite(hi[k]) || lo[k] > hi[k])
    {
      return false;
    }
    centre[k] = 0.5 * (lo[k] + hi[k]);
    const double h = 0.5 * (hi[k] - lo[k]);
    r2 += h * h;
  }
  // Every point of the box is within r of the centre, so |d(p) - d(c)| <= r (d is 1-Lipschitz).
  // The margins cover the rounding of these few operations many times over.
  const double r = std::sqrt(r2) * (1 + 1e-12) + 1e-300;
  const Closest c = closest(centre);
  const double d = std::sqrt(c.d2);
  const double margin = 1e-12 * (d + r);
  const double far = d + r + margin;
  const double near = std::max(0.0, d - r - margin);
  if (!signed_)
  {
    f_lo = -far;
    f_hi = -near;
    return true;
  }
  if (near > 0)
  {
    // The surface does not reach into the box: the sign is the centre's everywhere in it.
    if (sign_at(centre, c) > 0)
    {
      f_lo = near;
      f_hi = far;
    }
    else
    {
      f_lo = -far;
      f_hi = -near;
    }
    return true;
  }
  f_lo = -far;
  f_hi = far;
  return true;
}

std::array<double, 6> MeshDistance::bounds() const
{
  const Node& root = nodes_.front();
  return { root.lo[0], root.lo[1], root.lo[2], root.hi[0], root.hi[1], root.hi[2] };
}

} // namespace frep::shapes
