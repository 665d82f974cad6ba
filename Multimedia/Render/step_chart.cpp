#include "Render/step_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frep::render
{
namespace
{

// Where values go: the plot's pixel box and the value ranges it shows.
struct Axes
{
  PixelBox plot;
  double x_lo = 0.0, x_hi = 1.0;
  double y_hi = 1.0; // the vertical axis runs from 0
  double px(double x) const { return plot.x0 + (x - x_lo) / (x_hi - x_lo) * (plot.x1 - plot.x0); }
  double py(double y) const { return plot.y1 - y / y_hi * (plot.y1 - plot.y0); }
};

double largest_value(const StepChart& chart)
{
  double top = 1.0;
  for (const StepSeries& s : chart.series)
    for (const Point2& p : s.steps)
      top = std::max(top, p.y);
  return top;
}

std::string number_text(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// Horizontal grid lines at whole numbers (every k-th, at most ten) with their labels.
void draw_value_ticks(imaging::Image& image, const Axes& a, const StepChart& chart, Font* font,
  double text_px)
{
  const int top = static_cast<int>(std::ceil(a.y_hi));
  const int every = std::max(1, (top + 9) / 10);
  for (int v = 0; v <= top; v += every)
  {
    const double y = a.py(v);
    const Point2 line[2] = { { a.plot.x0, y }, { a.plot.x1, y } };
    draw_polyline(image, line, 1.0, chart.grid_colour);
    if (font)
      draw_text(image, *font, a.plot.x0 - 8, y, std::to_string(v), text_px, chart.text_colour,
        { HAlign::Right, VAlign::Middle });
  }
}

// A round step for about five ticks over `span`: 1, 2 or 5 times a power of ten.
double tick_step(double span)
{
  const double raw = span / 5.0;
  const double ten = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : { 1.0, 2.0, 5.0 })
    if (m * ten >= raw)
      return m * ten;
  return 10.0 * ten;
}

void draw_x_ticks(imaging::Image& image, const Axes& a, const StepChart& chart, Font* font,
  double text_px)
{
  const double step = tick_step(a.x_hi - a.x_lo);
  for (double x = std::ceil(a.x_lo / step - 1e-9) * step; x <= a.x_hi + 1e-9 * step; x += step)
  {
    const Point2 tick[2] = { { a.px(x), a.plot.y1 }, { a.px(x), a.plot.y1 + 5 } };
    draw_polyline(image, tick, 1.0, chart.text_colour);
    if (font)
      draw_text(image, *font, a.px(x), a.plot.y1 + 8, number_text(std::abs(x) < 1e-12 ? 0.0 : x),
        text_px, chart.text_colour, { HAlign::Centre, VAlign::Top });
  }
}

// The series as steps: across at its value, then up or down at the next step's x.
void draw_series(imaging::Image& image, const Axes& a, const StepSeries& s, double width)
{
  std::vector<Point2> line;
  for (std::size_t i = 0; i < s.steps.size(); ++i)
  {
    const double x0 = std::clamp(s.steps[i].x, a.x_lo, a.x_hi);
    const double x1 = i + 1 < s.steps.size() ? std::clamp(s.steps[i + 1].x, a.x_lo, a.x_hi) : a.x_hi;
    line.push_back({ a.px(x0), a.py(s.steps[i].y) });
    line.push_back({ a.px(x1), a.py(s.steps[i].y) });
  }
  draw_polyline(image, line, width, s.colour);
}

void draw_legend(imaging::Image& image, const Axes& a, const StepChart& chart, Font& font,
  double text_px)
{
  double x = a.plot.x1;
  for (auto s = chart.series.rbegin(); s != chart.series.rend(); ++s)
  {
    const TextLayout t = draw_text(image, font, x, a.plot.y0 - 10, s->name, text_px,
      chart.text_colour, { HAlign::Right, VAlign::Baseline });
    const double y = t.baseline_y - 0.35 * text_px;
    const Point2 swatch[2] = { { t.box.x0 - 30, y }, { t.box.x0 - 8, y } };
    draw_polyline(image, swatch, 3.0, s->colour);
    x = t.box.x0 - 46;
  }
}

} // namespace

imaging::Image draw_step_chart(const StepChart& chart, int width, int height, Font* font)
{
  imaging::Image image(width, height, chart.background);
  const double text_px = std::clamp(height / 26.0, 10.0, 22.0);
  Axes a;
  a.plot = { 4.0 * text_px, 3.2 * text_px, width - 1.5 * text_px, height - 3.6 * text_px };
  a.x_lo = chart.x_lo;
  a.x_hi = chart.x_hi > chart.x_lo ? chart.x_hi : chart.x_lo + 1.0;
  a.y_hi = std::ceil(largest_value(chart)) + 0.5;
  if (a.plot.empty())
    return image;
  draw_value_ticks(image, a, chart, font, text_px);
  for (const double m : chart.marks)
  {
    const Point2 line[2] = { { a.px(m), a.plot.y0 }, { a.px(m), a.plot.y1 } };
    draw_polyline(image, line, 1.5, chart.mark_colour);
  }
  // Wider first: a series under another of the same value still shows along its edges.
  for (std::size_t i = 0; i < chart.series.size(); ++i)
    draw_series(image, a, chart.series[i], std::max(1.5, 4.0 - 1.5 * static_cast<double>(i)));
  stroke_rect(image, { a.plot.x0 - 1, a.plot.y0 - 1, a.plot.x1 + 1, a.plot.y1 + 1 }, 1.0,
    chart.text_colour);
  draw_x_ticks(image, a, chart, font, text_px);
  if (font)
  {
    draw_text(image, *font, a.plot.x0, a.plot.y0 - 10, chart.title, text_px * 1.1,
      chart.text_colour, { HAlign::Left, VAlign::Baseline });
    draw_text(image, *font, 0.5 * (a.plot.x0 + a.plot.x1), height - 0.5 * text_px, chart.x_label,
      text_px, chart.text_colour, { HAlign::Centre, VAlign::Bottom });
    draw_legend(image, a, chart, *font, text_px);
  }
  return image;
}

} // namespace frep::render
