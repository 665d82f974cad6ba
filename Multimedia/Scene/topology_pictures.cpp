#include "Scene/topology_pictures.h"

#include "Render/plot2d.h"
#include "Render/step_chart.h"

#include <algorithm>
#include <utility>

namespace frep::mapping
{
namespace
{

// "3 pieces (2 slivers), genus 1"
std::string shape_text(const mesh::ShapeTopology& s)
{
  std::string t = std::to_string(s.components) + (s.components == 1 ? " piece" : " pieces");
  if (s.slivers > 0)
    t += " (" + std::to_string(s.slivers) + (s.slivers == 1 ? " sliver)" : " slivers)");
  return s.genus != 0 ? t + ", genus " + std::to_string(s.genus) : t;
}

// A bar in the gap between two cell pictures side by side (across the middle of the gap) or one
// above the other (just above the lower picture: the gap holds the upper one's label); nothing
// for cells of different layers, whose pictures are not neighbours.
void mark_gap(imaging::Image& image, const std::array<int, 4>& p, const std::array<int, 4>& q,
  imaging::Rgba colour)
{
  const auto& [l, r] = p[0] <= q[0] ? std::pair(p, q) : std::pair(q, p);
  const auto& [t, b] = p[1] <= q[1] ? std::pair(p, q) : std::pair(q, p);
  if (p[1] == q[1] && l[0] + l[2] <= r[0])
  {
    const double mid = 0.5 * (l[0] + l[2] + r[0]);
    render::fill_rect(image, { mid - 3, double(p[1]), mid + 3, double(p[1] + p[3]) }, colour);
  }
  else if (p[0] == q[0] && t[1] + t[3] <= b[1])
  {
    const double y = std::max(double(t[1] + t[3]), b[1] - 8.0);
    render::fill_rect(image, { double(p[0]), y, double(p[0] + p[2]), y + 5 }, colour);
  }
}

} // namespace

imaging::Image topology_sheet(const imaging::Image& sheet,
  const std::vector<std::array<int, 4>>& rects,
  const TopologyMap& t,
  PictureKit* kit)
{
  imaging::Image image = sheet;
  const imaging::Rgba red = imaging::srgb_hex(0xd1495b);
  for (const TopologyChange& c : t.changes)
  {
    if (c.from >= rects.size() || c.to >= rects.size())
      continue;
    const auto& p = rects[c.from];
    const auto& q = rects[c.to];
    for (const auto& r : { p, q })
      render::stroke_rect(image, { double(r[0]), double(r[1]), double(r[0] + r[2]),
        double(r[1] + r[3]) }, 3.0, red);
    mark_gap(image, p, q, red);
  }
  if (!kit->font)
    return image;
  for (std::size_t i = 0; i < t.shapes.size() && i < rects.size(); ++i)
  {
    const auto& r = rects[i];
    const double px = std::max(10.0, r[2] / 18.0);
    const std::string text = shape_text(t.shapes[i]);
    const render::TextExtent e = render::text_extent(*kit->font, text, px);
    render::fill_rect(image, { r[0] + 4.0, r[1] + 4.0, r[0] + 12.0 + e.width,
      r[1] + 8.0 + e.ascent + e.descent }, imaging::srgb(1.0, 1.0, 1.0, 0.8));
    render::draw_text(image, *kit->font, r[0] + 8.0, r[1] + 6.0, text, px,
      imaging::srgb_hex(0x222222), { render::HAlign::Left, render::VAlign::Top });
  }
  return image;
}

imaging::Image topology_chart(const Plan& plan, const TopologyMap& t, PictureKit* kit)
{
  render::StepChart chart;
  chart.title = "The section's topology along the animation";
  chart.x_label = "time (s)";
  chart.x_lo = plan.frames.front().time;
  chart.x_hi = plan.frames.back().time;
  render::StepSeries pieces{ "pieces", { { chart.x_lo, double(t.shapes.front().components) } },
    imaging::srgb_hex(0x1f5fa8) };
  render::StepSeries genus{ "genus", { { chart.x_lo, double(t.shapes.front().genus) } },
    imaging::srgb_hex(0xe08e0b) };
  for (const TopologyChange& c : t.changes)
  {
    const double u = 0.5 * (c.event.before + c.event.after);
    const double x = plan.frames[c.from].time + u * (plan.frames[c.to].time - plan.frames[c.from].time);
    pieces.steps.push_back({ x, double(c.event.components_after) });
    genus.steps.push_back({ x, double(c.event.genus_after) });
    chart.marks.push_back(x);
  }
  // Slivers are counted per frame (a piece that shrinks is no event): steps at the frames.
  render::StepSeries solids{ "pieces but slivers", {}, imaging::srgb_hex(0x2a9d8f) };
  for (std::size_t k = 0; k < t.shapes.size() && k < plan.frames.size(); ++k)
    solids.steps.push_back(
      { plan.frames[k].time, double(t.shapes[k].components - t.shapes[k].slivers) });
  chart.series = { pieces, genus, solids };
  return render::draw_step_chart(chart, 900, 360, kit->font ? &*kit->font : nullptr);
}

} // namespace frep::mapping
