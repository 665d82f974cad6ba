// A chart of whole-number quantities that change in steps along one axis (how many pieces a
// shape has, its genus, along an animation), drawn headless: each series holds its value from
// one step to the next; vertical marks show where the steps are. The map of the topology's
// topology.png (Multimedia/Production/topology.cpp).
#pragma once

#include "Imaging/image.h"
#include "Render/plot2d.h"
#include "Render/text.h"

#include <string>
#include <vector>

namespace frep::render
{

struct StepSeries
{
  std::string name;
  /// (x, value): the value holds from x to the next step's x (the last to the chart's x_hi).
  /// Sorted by x; the first step's x is the chart's x_lo.
  std::vector<Point2> steps;
  imaging::Rgba colour = imaging::srgb_hex(0x1f5fa8);
};

struct StepChart
{
  std::string title;
  std::string x_label;
  double x_lo = 0.0; ///< the horizontal axis's range (x_hi > x_lo)
  double x_hi = 1.0;
  std::vector<StepSeries> series;
  std::vector<double> marks; ///< x of vertical marks (thin lines over the plot)
  imaging::Rgba background = imaging::srgb(1.0, 1.0, 1.0);
  imaging::Rgba text_colour = imaging::srgb_hex(0x222222);
  imaging::Rgba grid_colour = imaging::srgb_hex(0xd8dbe0);
  imaging::Rgba mark_colour = imaging::srgb_hex(0xd1495b, 0.45);
};

/// The chart, width x height pixels: whole-number ticks from 0 to the largest value (at most
/// ten of them), five ticks along x, the series' names as a legend. `font` may be null (no
/// text).
imaging::Image draw_step_chart(const StepChart& chart, int width, int height, Font* font);

} // namespace frep::render
