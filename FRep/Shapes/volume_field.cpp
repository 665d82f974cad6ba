#include "Shapes/volume_field.h"

#include <algorithm>
#include <cmath>

namespace frep::shapes
{

VolumeField::BuildResult VolumeField::build(VolumeGrid grid, double iso)
{
  BuildResult r;
  std::size_t n = 1;
  for (int k = 0; k < 3; ++k)
  {
    if (grid.dims[k] < 2)
    {
      r.error = "the volume needs at least 2 samples on each axis (it has " +
                std::to_string(grid.dims[0]) + " x " + std::to_string(grid.dims[1]) + " x " +
                std::to_string(grid.dims[2]) + ")";
      return r;
    }
    if (!(grid.spacing[k] > 0) || !std::isfinite(grid.spacing[k]) || !std::isfinite(grid.origin[k]))
    {
      r.error = "the volume's spacing must be positive and finite, its origin finite";
      return r;
    }
    n *= static_cast<std::size_t>(grid.dims[k]);
  }
  if (grid.values.size() != n)
  {
    r.error = "the volume has " + std::to_string(grid.values.size()) + " values for " +
              std::to_string(n) + " samples";
    return r;
  }
  const std::size_t bad = static_cast<std::size_t>(std::count_if(
    grid.values.begin(), grid.values.end(), [](double v) { return !std::isfinite(v); }));
  if (bad > 0)
  {
    r.error = "the volume has " + std::to_string(bad) + " non-finite values";
    return r;
  }
  if (!std::isfinite(iso))
  {
    r.error = "the iso value must be finite";
    return r;
  }
  auto f = std::shared_ptr<VolumeField>(new VolumeField());
  f->grid_ = std::move(grid);
  f->iso_ = iso;
  const auto& d = f->grid_.dims;
  for (int k = 0; k < 3; ++k)
  {
    f->bricks_[k] = (d[k] - 1 + kBrick - 1) / kBrick; // bricks of cells
  }
  const std::size_t nb = static_cast<std::size_t>(f->bricks_[0]) * f->bricks_[1] * f->bricks_[2];
  f->brick_min_.assign(nb, INFINITY);
  f->brick_max_.assign(nb, -INFINITY);
  // A sample belongs to every brick whose cells it is a corner of.
  for (int k = 0; k < d[2]; ++k)
  {
    for (int j = 0; j < d[1]; ++j)
    {
      for (int i = 0; i < d[0]; ++i)
      {
        const double v = f->sample(i, j, k);
        const int ib[2] = { std::min(i / kBrick, f->bricks_[0] - 1), std::max(i - 1, 0) / kBrick };
        const int jb[2] = { std::min(j / kBrick, f->bricks_[1] - 1), std::max(j - 1, 0) / kBrick };
        const int kb[2] = { std::min(k / kBrick, f->bricks_[2] - 1), std::max(k - 1, 0) / kBrick };
        for (int c = 0; c < 2; ++c)
        {
          for (int b = 0; b < 2; ++b)
          {
            for (int a = 0; a < 2; ++a)
            {
              const std::size_t index =
                (static_cast<std::size_t>(kb[c]) * f->bricks_[1] + jb[b]) * f->bricks_[0] + ib[a];
              f->brick_min_[index] = std::min(f->brick_min_[index], v);
              f->brick_max_[index] = std::max(f->brick_max_[index], v);
            }
          }
        }
      }
    }
  }
  r.field = std::move(f);
  return r;
}

double VolumeField::sample(int i, int j, int k) const
{
  const auto& d = grid_.dims;
  return grid_.values[(static_cast<std::size_t>(k) * d[1] + j) * d[0] + i];
}

double VolumeField::value(const std::array<double, 3>& p) const
{
  std::array<double, 3> g;
  return value_and_gradient(p, g);
}

double VolumeField::value_and_gradient(const std::array<double, 3>& p,
  std::array<double, 3>& g) const
{
  std::array<int, 3> cell{};
  std::array<double, 3> t{};
  std::array<double, 3> outside{};
  double out2 = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double extent = grid_.spacing[k] * (grid_.dims[k] - 1);
    const double u = p[k] - grid_.origin[k];
    const double clamped = std::clamp(u, 0.0, extent);
    outside[k] = u - clamped;
    out2 += outside[k] * outside[k];
    const double s = clamped / grid_.spacing[k];
    cell[k] = std::min(static_cast<int>(s), grid_.dims[k] - 2);
    t[k] = s - cell[k];
  }
  double c[2][2][2];
  for (int a = 0; a < 2; ++a)
  {
    for (int b = 0; b < 2; ++b)
    {
      for (int e = 0; e < 2; ++e)
      {
        c[a][b][e] = sample(cell[0] + a, cell[1] + b, cell[2] + e);
      }
    }
  }
  // Exact at both ends: on the last grid plane (t = 1) x + (y - x) can differ from y by rounding,
  // and F at every grid point is to be the sample minus the iso value.
  const auto lerp = [](double x, double y, double s) { return s == 1 ? y : x + (y - x) * s; };
  const double x00 = lerp(c[0][0][0], c[1][0][0], t[0]);
  const double x10 = lerp(c[0][1][0], c[1][1][0], t[0]);
  const double x01 = lerp(c[0][0][1], c[1][0][1], t[0]);
  const double x11 = lerp(c[0][1][1], c[1][1][1], t[0]);
  const double y0 = lerp(x00, x10, t[1]);
  const double y1 = lerp(x01, x11, t[1]);
  const double v = lerp(y0, y1, t[2]);
  if (out2 > 0)
  {
    const double dist = std::sqrt(out2);
    for (int k = 0; k < 3; ++k)
    {
      g[k] = -outside[k] / dist;
    }
    return v - iso_ - dist;
  }
  const double dx0 = lerp(lerp(c[1][0][0] - c[0][0][0], c[1][1][0] - c[0][1][0], t[1]),
    lerp(c[1][0][1] - c[0][0][1], c[1][1][1] - c[0][1][1], t[1]),
    t[2]);
  const double dy0 = lerp(lerp(c[0][1][0] - c[0][0][0], c[1][1][0] - c[1][0][0], t[0]),
    lerp(c[0][1][1] - c[0][0][1], c[1][1][1] - c[1][0][1], t[0]),
    t[2]);
  g = { dx0 / grid_.spacing[0], dy0 / grid_.spacing[1], (y1 - y0) / grid_.spacing[2] };
  return v - iso_;
}

bool VolumeField::enclose(const std::array<double, 3>& lo,
  const std::array<double, 3>& hi,
  double& f_lo,
  double& f_hi) const
{
  std::array<int, 2> range[3];
  std::array<int, 2> cells[3]; // the cells the box covers (clamped to the grid)
  double dmin2 = 0;
  double dmax2 = 0;
  for (int k = 0; k < 3; ++k)
  {
    if (!std::isfinite(lo[k]) || !std::isfinite(hi[k]) || lo[k] > hi[k])
    {
      return false;
    }
    const double extent = grid_.spacing[k] * (grid_.dims[k] - 1);
    const double a = lo[k] - grid_.origin[k];
    const double b = hi[k] - grid_.origin[k];
    // Distance of the box to the grid box along this axis: nearest and farthest.
    const double near = std::max({ 0.0, -b, a - extent });
    const double far = std::max(std::max(0.0, -a), std::max(0.0, b - extent));
    dmin2 += near * near;
    dmax2 += far * far;
    const double ca = std::clamp(a, 0.0, extent) / grid_.spacing[k];
    const double cb = std::clamp(b, 0.0, extent) / grid_.spacing[k];
    const int c0 = std::min(static_cast<int>(ca), grid_.dims[k] - 2);
    const int c1 = std::min(static_cast<int>(cb), grid_.dims[k] - 2);
    range[k] = { c0 / kBrick, c1 / kBrick };
    cells[k] = { c0, c1 };
  }
  double vmin = INFINITY;
  double vmax = -INFINITY;
  // A small box (the ray caster's and the mesher's are): the covered cells' own corner samples,
  // far tighter than whole bricks; the bricks for large boxes.
  const auto corners = [&](int k) { return cells[k][1] - cells[k][0] + 2; };
  if (corners(0) * corners(1) * corners(2) <= 4 * kBrick * kBrick)
  {
    for (int k = cells[2][0]; k <= cells[2][1] + 1; ++k)
      for (int j = cells[1][0]; j <= cells[1][1] + 1; ++j)
        for (int i = cells[0][0]; i <= cells[0][1] + 1; ++i)
        {
          const double v = sample(i, j, k);
          vmin = std::min(vmin, v);
          vmax = std::max(vmax, v);
        }
  }
  else
  {
    for (int bk = range[2][0]; bk <= range[2][1]; ++bk)
    {
      for (int bj = range[1][0]; bj <= range[1][1]; ++bj)
      {
        for (int bi = range[0][0]; bi <= range[0][1]; ++bi)
        {
          const std::size_t index =
            (static_cast<std::size_t>(bk) * bricks_[1] + bj) * bricks_[0] + bi;
          vmin = std::min(vmin, brick_min_[index]);
          vmax = std::max(vmax, brick_max_[index]);
        }
      }
    }
  }
  // Trilinear values lie between their cell's corner values; margins cover the rounding.
  const double scale = std::max(std::fabs(vmin), std::fabs(vmax)) + std::fabs(iso_) + 1;
  const double margin = 1e-12 * scale;
  f_lo = vmin - iso_ - std::sqrt(dmax2) * (1 + 1e-12) - margin;
  f_hi = vmax - iso_ - std::sqrt(dmin2) * (1 - 1e-12) + margin;
  return true;
}

std::array<double, 6> VolumeField::bounds() const
{
  std::array<double, 6> b{};
  for (int k = 0; k < 3; ++k)
  {
    b[k] = grid_.origin[k];
    b[k + 3] = grid_.origin[k] + grid_.spacing[k] * (grid_.dims[k] - 1);
  }
  return b;
}

} // namespace frep::shapes
