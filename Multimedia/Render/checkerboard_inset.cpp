// draw_checkerboard_inset (plot2d.h): the (x4, x5) plane as a checkerboard with the animation's
// path on it. The checker squares make the plane's scale readable at a glance even at 240 px,
// the range labels sit at the board's corners, and the way already travelled is drawn stronger
// than the way ahead so a viewer sees the direction of motion in a single frame.
#include "Render/plot2d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frep::render
{

namespace
{

std::string number(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  std::string s = text;
  // A true minus sign reads better than a hyphen.
  if (!s.empty() && s[0] == '-')
  {
    s.replace(0, 1, "\u2212");
  }
  return s;
}

} // namespace

PixelBox draw_checkerboard_inset(imaging::Image& image, const CheckerboardInset& in, Font* font)
{
  const PixelBox& r = in.rect;
  if (r.empty())
  {
    return {};
  }
  const double size = std::min(r.x1 - r.x0, r.y1 - r.y0);
  // Sizes grow with the inset up to what still reads as a diagram, not a poster.
  const double text = in.text_pixels > 0.0 ? in.text_pixels : std::clamp(0.06 * size, 10.0, 22.0);
  const double line = in.path_width > 0.0 ? in.path_width : std::clamp(0.012 * size, 1.5, 4.0);
  const double marker =
    in.marker_radius > 0.0 ? in.marker_radius : std::clamp(0.028 * size, 4.0, 11.0);
  const double pad = std::max(4.0, 0.6 * text);

  fill_rect(image, r, in.background);
  stroke_rect(image, r, 1.0, in.frame_colour);

  // Room for the labels: a column at the left as wide as the widest v label, a row under the
  // board one line high.
  const std::string u_lo = number(in.u_lo), u_hi = number(in.u_hi);
  const std::string v_lo = number(in.v_lo), v_hi = number(in.v_hi);
  const bool labels = font != nullptr;
  double left = pad, bottom = pad;
  if (labels)
  {
    double widest = text_extent(*font, in.v_label, text).width;
    if (in.range_labels)
    {
      widest = std::max(
        { widest, text_extent(*font, v_lo, text).width, text_extent(*font, v_hi, text).width });
    }
    left = pad + widest + 0.5 * text;
    bottom = pad + 1.4 * text;
  }
  PixelBox board{ r.x0 + left, r.y0 + pad, r.x1 - pad, r.y1 - bottom };
  if (board.empty())
  {
    return {};
  }
  // Whole pixels: the squares' edges stay sharp.
  board = {
    std::round(board.x0), std::round(board.y0), std::round(board.x1), std::round(board.y1)
  };

  const int nu = std::clamp(in.squares_u, 1, 64);
  const int nv = std::clamp(in.squares_v, 1, 64);
  const double bw = board.x1 - board.x0, bh = board.y1 - board.y0;
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      // (u_lo, v_lo) is the bottom-left square, dark like a chessboard's a1.
      const PixelBox square{ board.x0 + bw * i / nu,
        board.y1 - bh * (j + 1) / nv,
        board.x0 + bw * (i + 1) / nu,
        board.y1 - bh * j / nv };
      fill_rect(image, square, (i + j) % 2 == 0 ? in.dark_square : in.light_square);
    }
  }
  stroke_rect(
    image, { board.x0 - 1, board.y0 - 1, board.x1 + 1, board.y1 + 1 }, 1.0, in.frame_colour);

  const double du = in.u_hi - in.u_lo, dv = in.v_hi - in.v_lo;
  const auto to_pixel = [&](Point2 p) -> Point2
  {
    return { board.x0 + (du != 0.0 ? (p.x - in.u_lo) / du : 0.5) * bw,
      board.y1 - (dv != 0.0 ? (p.y - in.v_lo) / dv : 0.5) * bh };
  };
  std::vector<Point2> path;
  path.reserve(in.path.size());
  for (const Point2& p : in.path)
  {
    path.push_back(to_pixel(p));
  }
  const std::size_t past = std::min(in.past_points, path.size());
  if (past > 0)
  {
    // Ahead: from the current point (or the last past point) on, thinner and lighter.
    std::vector<Point2> ahead;
    if (in.current)
    {
      ahead.push_back(to_pixel(*in.current));
    }
    ahead.insert(ahead.end(),
      path.begin() + static_cast<std::ptrdiff_t>(past - (in.current ? 0 : 1)),
      path.end());
    imaging::Rgba faint = in.path_colour;
    faint.a *= 0.55F;
    draw_polyline(image, ahead, line, faint);
    std::vector<Point2> behind(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(past));
    if (in.current)
    {
      behind.push_back(to_pixel(*in.current));
    }
    draw_polyline(image, behind, 1.6 * line, in.past_colour);
  }
  else
  {
    draw_polyline(image, path, line, in.path_colour);
  }
  const imaging::Rgba white{ 1, 1, 1, 1 };
  for (const Point2& p : in.markers)
  {
    draw_marker(
      image, to_pixel(p), 0.45 * marker, in.path_colour, white, std::max(1.0, 0.12 * marker));
  }
  if (in.mark_start && !path.empty())
  {
    const double ring = 0.75 * marker;
    draw_marker(image, path.front(), ring, white, in.path_colour, std::max(1.5, 0.3 * ring));
  }
  if (in.current)
  {
    draw_marker(
      image, to_pixel(*in.current), marker, in.marker_colour, white, std::max(1.5, 0.25 * marker));
  }

  if (labels)
  {
    const double below = board.y1 + 0.35 * text;
    const double beside = board.x0 - 0.4 * text;
    font->draw(image,
      board.x0 + 0.5 * bw,
      below,
      in.u_label,
      text,
      in.text_colour,
      { HAlign::Centre, VAlign::Top });
    font->draw(image,
      beside,
      board.y0 + 0.5 * bh,
      in.v_label,
      text,
      in.text_colour,
      { HAlign::Right, VAlign::Middle });
    if (in.range_labels)
    {
      font->draw(image, board.x0, below, u_lo, text, in.text_colour, { HAlign::Left, VAlign::Top });
      font->draw(
        image, board.x1, below, u_hi, text, in.text_colour, { HAlign::Right, VAlign::Top });
      font->draw(
        image, beside, board.y1, v_lo, text, in.text_colour, { HAlign::Right, VAlign::Bottom });
      font->draw(
        image, beside, board.y0, v_hi, text, in.text_colour, { HAlign::Right, VAlign::Top });
    }
  }
  return board;
}

} // namespace frep::render
