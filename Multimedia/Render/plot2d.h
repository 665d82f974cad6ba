// 2-D drawing over rendered pictures: anti-aliased polylines, discs, rectangles, and the
// checkerboard picture of the (x4, x5) plane that shows where an animation is on its path (as a
// small inset of each frame, or large on its own as path.png).
//
// Anti-aliasing is analytic: a pixel's coverage is how far its centre lies inside the shape's
// edge, clamped to one pixel of ramp; a polyline's coverage is that of its nearest segment, so
// joins are round and no pixel is blended twice.
#pragma once

#include "Imaging/image.h"
#include "Render/text.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace frep::render
{

struct Point2
{
  double x = 0.0;
  double y = 0.0;
};

/// A polyline of `width` pixels (round joins and caps) through pixel positions (x right, y
/// down). One point draws a dot; none, nothing.
void draw_polyline(imaging::Image& image,
  std::span<const Point2> points,
  double width,
  imaging::Rgba colour);

/// A filled disc.
void fill_circle(imaging::Image& image, Point2 centre, double radius, imaging::Rgba colour);

/// A disc with a ring: `fill` inside radius - outline_width, `outline` in the ring.
void draw_marker(imaging::Image& image,
  Point2 centre,
  double radius,
  imaging::Rgba fill,
  imaging::Rgba outline,
  double outline_width);

/// A filled axis-aligned rectangle; fractional edges get fractional coverage.
void fill_rect(imaging::Image& image, const PixelBox& box, imaging::Rgba colour);

/// The outline of a rectangle, `width` pixels inside the box.
void stroke_rect(imaging::Image& image, const PixelBox& box, double width, imaging::Rgba colour);

/// The picture of a path through a plane (u across, v up) over a checkerboard of that plane.
struct CheckerboardInset
{
  PixelBox rect;     ///< where the whole inset goes (labels included), pixels
  double u_lo = 0.0; ///< the plane's range shown
  double u_hi = 1.0;
  double v_lo = 0.0;
  double v_hi = 1.0;
  int squares_u = 4; ///< checker squares per axis
  int squares_v = 4;
  std::vector<Point2> path;      ///< in plane units (u, v), drawn in order
  std::optional<Point2> current; ///< the marker (plane units)
  /// The first `past_points` points of the path (then `current`) drawn as the way already
  /// travelled (stronger); the rest fainter. 0: the whole path alike.
  std::size_t past_points = 0;
  std::vector<Point2> markers; ///< small dots, e.g. every frame's point (plane units)
  /// A ring at the path's first point, so the direction of travel can be read.
  bool mark_start = true;
  std::string u_label = "x\u2084"; ///< x with subscript 4
  std::string v_label = "x\u2085";
  bool range_labels = true; ///< the range's ends at the board's corners
  /// Text height in pixels; 0: from the inset's size.
  double text_pixels = 0.0;
  /// Line widths and marker radius in pixels; 0: from the inset's size.
  double path_width = 0.0;
  double marker_radius = 0.0;
  imaging::Rgba background =
    imaging::srgb(1.0, 1.0, 1.0, 0.88); ///< panel behind the board (translucent over a frame)
  imaging::Rgba light_square = imaging::srgb_hex(0xf2f2f2);
  imaging::Rgba dark_square = imaging::srgb_hex(0xc9cdd4);
  imaging::Rgba path_colour = imaging::srgb_hex(0x1f5fa8);
  imaging::Rgba past_colour = imaging::srgb_hex(0xd1495b);
  imaging::Rgba marker_colour = imaging::srgb_hex(0xd1495b);
  imaging::Rgba text_colour = imaging::srgb_hex(0x222222);
  imaging::Rgba frame_colour = imaging::srgb_hex(0x444444);
};

/// Draw it. `font` may be null: no labels, the board takes the whole rect. Returns the board's
/// pixel box (where (u_lo, v_lo) .. (u_hi, v_hi) went).
PixelBox draw_checkerboard_inset(imaging::Image& image, const CheckerboardInset& inset, Font* font);

} // namespace frep::render
