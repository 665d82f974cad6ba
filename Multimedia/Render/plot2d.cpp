#include "Render/plot2d.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace frep::render
{

namespace
{

struct PixelRange
{
  int x0, y0, x1, y1; // inclusive-exclusive, clamped to the image
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

PixelRange clamp_range(const imaging::Image& image, double x0, double y0, double x1, double y1)
{
  const auto lo = [](double v, int n)
  { return static_cast<int>(std::clamp(std::floor(v), 0.0, double(n))); };
  const auto hi = [](double v, int n)
  { return static_cast<int>(std::clamp(std::ceil(v), 0.0, double(n))); };
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1))
  {
    return { 0, 0, 0, 0 };
  }
  return { lo(x0, image.width), lo(y0, image.height), hi(x1, image.width), hi(y1, image.height) };
}

// Distance from p to the segment a-b.
double segment_distance(Point2 p, Point2 a, Point2 b)
{
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = 0.0;
  if (length2 > 0.0)
  {
    t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0);
  }
  const double ex = a.x + t * dx - p.x, ey = a.y + t * dy - p.y;
  return std::sqrt(ex * ex + ey * ey);
}

// Below one pixel, a shape is drawn one pixel wide with its alpha scaled: thin lines fade
// instead of breaking up.
void thin(double& size, imaging::Rgba& colour, double minimum)
{
  if (size < minimum)
  {
    colour.a *= static_cast<float>(std::max(size, 0.0) / minimum);
    size = minimum;
  }
}

} // namespace

void draw_polyline(imaging::Image& image,
  std::span<const Point2> points,
  double width,
  imaging::Rgba colour)
{
  if (points.empty() || !(width > 0.0) || image.empty())
  {
    return;
  }
  thin(width, colour, 1.0);
  const double r = 0.5 * width;
  double x0 = points[0].x, x1 = x0, y0 = points[0].y, y1 = y0;
  for (const Point2& p : points)
  {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const PixelRange box = clamp_range(image, x0 - r - 1, y0 - r - 1, x1 + r + 1, y1 + r + 1);
  if (box.empty())
  {
    return;
  }
  const int bw = box.x1 - box.x0;
  std::vector<float> coverage(static_cast<std::size_t>(bw) * (box.y1 - box.y0), 0.0F);
  const auto segment = [&](Point2 a, Point2 b)
  {
    const PixelRange s = clamp_range(image,
      std::min(a.x, b.x) - r - 1,
      std::min(a.y, b.y) - r - 1,
      std::max(a.x, b.x) + r + 1,
      std::max(a.y, b.y) + r + 1);
    for (int y = s.y0; y < s.y1; ++y)
    {
      for (int x = s.x0; x < s.x1; ++x)
      {
        const double d = segment_distance({ x + 0.5, y + 0.5 }, a, b);
        const auto c = static_cast<float>(std::clamp(r + 0.5 - d, 0.0, 1.0));
        float& cell = coverage[static_cast<std::size_t>(y - box.y0) * bw + (x - box.x0)];
        cell = std::max(cell, c);
      }
    }
  };
  if (points.size() == 1)
  {
    segment(points[0], points[0]);
  }
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
  {
    segment(points[i], points[i + 1]);
  }
  for (int y = box.y0; y < box.y1; ++y)
  {
    for (int x = box.x0; x < box.x1; ++x)
    {
      const float c = coverage[static_cast<std::size_t>(y - box.y0) * bw + (x - box.x0)];
      if (c > 0.0F)
      {
        imaging::blend_pixel(image, x, y, colour, c);
      }
    }
  }
}

void fill_circle(imaging::Image& image, Point2 centre, double radius, imaging::Rgba colour)
{
  if (!(radius > 0.0))
  {
    return;
  }
  thin(radius, colour, 0.5);
  const PixelRange box = clamp_range(image,
    centre.x - radius - 1,
    centre.y - radius - 1,
    centre.x + radius + 1,
    centre.y + radius + 1);
  for (int y = box.y0; y < box.y1; ++y)
  {
    for (int x = box.x0; x < box.x1; ++x)
    {
      const double d = std::hypot(x + 0.5 - centre.x, y + 0.5 - centre.y);
      const double c = std::clamp(radius + 0.5 - d, 0.0, 1.0);
      if (c > 0.0)
      {
        imaging::blend_pixel(image, x, y, colour, static_cast<float>(c));
      }
    }
  }
}

void draw_marker(imaging::Image& image,
  Point2 centre,
  double radius,
  imaging::Rgba fill,
  imaging::Rgba outline,
  double outline_width)
{
  fill_circle(image, centre, radius, outline);
  fill_circle(image, centre, radius - std::max(outline_width, 0.0), fill);
}

void fill_rect(imaging::Image& image, const PixelBox& b, imaging::Rgba colour)
{
  if (b.empty())
  {
    return;
  }
  const PixelRange box = clamp_range(image, b.x0, b.y0, b.x1, b.y1);
  for (int y = box.y0; y < box.y1; ++y)
  {
    const double cy = std::min(b.y1, y + 1.0) - std::max(b.y0, double(y));
    for (int x = box.x0; x < box.x1; ++x)
    {
      const double cx = std::min(b.x1, x + 1.0) - std::max(b.x0, double(x));
      imaging::blend_pixel(image, x, y, colour, static_cast<float>(std::clamp(cx * cy, 0.0, 1.0)));
    }
  }
}

void stroke_rect(imaging::Image& image, const PixelBox& b, double width, imaging::Rgba colour)
{
  if (b.empty() || !(width > 0.0))
  {
    return;
  }
  const double w = std::min({ width, 0.5 * (b.x1 - b.x0), 0.5 * (b.y1 - b.y0) });
  fill_rect(image, { b.x0, b.y0, b.x1, b.y0 + w }, colour);
  fill_rect(image, { b.x0, b.y1 - w, b.x1, b.y1 }, colour);
  fill_rect(image, { b.x0, b.y0 + w, b.x0 + w, b.y1 - w }, colour);
  fill_rect(image, { b.x1 - w, b.y0 + w, b.x1, b.y1 - w }, colour);
}

} // namespace frep::render
