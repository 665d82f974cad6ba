// 2-D drawing: analytic anti-aliasing gives the right areas, and the inset puts its squares,
// path and marker where the plane coordinates say.
#include "Render/plot2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace frep::render
{
namespace
{

double alpha_sum(const imaging::Image& image)
{
  double sum = 0.0;
  for (std::size_t i = 3; i < image.rgba.size(); i += 4)
  {
    sum += image.rgba[i];
  }
  return sum;
}

TEST(Plot2d, AreasOfShapes)
{
  imaging::Image line(200, 100);
  const std::vector<Point2> points = { { 20.3, 50.2 }, { 120.3, 50.2 } };
  draw_polyline(line, points, 4.0, { 0, 0, 0, 1 });
  EXPECT_NEAR(alpha_sum(line), 100.0 * 4.0 + std::numbers::pi * 4.0, 6.0);

  // A polyline with a sharp turn: the joint is not blended twice (coverage never exceeds 1).
  imaging::Image turn(100, 100);
  const std::vector<Point2> zigzag = { { 10, 10 }, { 80, 50 }, { 10, 90 } };
  draw_polyline(turn, zigzag, 6.0, { 0, 0, 0, 0.5F });
  float most = 0;
  for (std::size_t i = 3; i < turn.rgba.size(); i += 4)
  {
    most = std::max(most, turn.rgba[i]);
  }
  EXPECT_FLOAT_EQ(most, 0.5F);

  imaging::Image disc(100, 100);
  fill_circle(disc, { 50.4, 49.7 }, 20.0, { 0, 0, 0, 1 });
  EXPECT_NEAR(alpha_sum(disc) / (std::numbers::pi * 400.0), 1.0, 0.01);

  imaging::Image rect(10, 10);
  fill_rect(rect, { 1.5, 1.5, 3.5, 2.5 }, { 0, 0, 0, 1 });
  EXPECT_NEAR(alpha_sum(rect), 2.0, 1e-6);
  EXPECT_FLOAT_EQ(rect.at(1, 1).a, 0.25F);

  imaging::Image frame(20, 20);
  stroke_rect(frame, { 0, 0, 20, 20 }, 1.0, { 0, 0, 0, 1 });
  EXPECT_NEAR(alpha_sum(frame), 76.0, 1e-6);
  EXPECT_EQ(frame.at(10, 10).a, 0.0F);
}

TEST(Plot2d, InsetPlacesBoardPathAndMarker)
{
  imaging::Image image(300, 300, { 0, 0, 0, 1 });
  CheckerboardInset inset;
  inset.rect = { 20, 20, 260, 260 };
  inset.u_lo = -1, inset.u_hi = 1, inset.v_lo = 0, inset.v_hi = 2;
  inset.squares_u = inset.squares_v = 4;
  inset.path = { { -0.75, 1.75 }, { 0.75, 1.75 } }; // along the top row of squares
  inset.current = Point2{ 0.75, 0.25 };             // in the bottom-right square
  inset.background = { 1, 1, 1, 1 };
  const PixelBox board = draw_checkerboard_inset(image, inset, nullptr);
  ASSERT_FALSE(board.empty());
  EXPECT_GE(board.x0, 20.0);
  EXPECT_LE(board.x1, 260.0);
  const double sw = (board.x1 - board.x0) / 4, sh = (board.y1 - board.y0) / 4;
  const auto square_centre = [&](int i, int j) // i across from u_lo, j up from v_lo
  {
    return image.at(
      static_cast<int>(board.x0 + (i + 0.5) * sw), static_cast<int>(board.y1 - (j + 0.5) * sh));
  };
  // The bottom-left square is dark, its neighbours light, the pattern alternates.
  EXPECT_EQ(square_centre(0, 0).r, inset.dark_square.r);
  EXPECT_EQ(square_centre(1, 0).r, inset.light_square.r);
  EXPECT_EQ(square_centre(0, 1).r, inset.light_square.r);
  EXPECT_EQ(square_centre(1, 1).r, inset.dark_square.r);
  // The marker (bottom-right square) and the path (top row) are drawn there.
  const imaging::Rgba m = square_centre(3, 0);
  EXPECT_NEAR(m.r, inset.marker_colour.r, 1e-6);
  EXPECT_NEAR(m.b, inset.marker_colour.b, 1e-6);
  const imaging::Rgba p = square_centre(1, 3);
  EXPECT_GT(p.b, p.r + 0.1F); // the path's blue over a light square
  // Outside the rect: untouched.
  EXPECT_EQ(image.at(10, 10).r, 0.0F);
  EXPECT_EQ(image.at(280, 280).r, 0.0F);

  // With labels the board shrinks to make room, to the left and below.
  Font::LoadResult font = Font::load_default();
  ASSERT_TRUE(font.ok()) << font.error;
  imaging::Image labelled(300, 300);
  const PixelBox with = draw_checkerboard_inset(labelled, inset, &*font.font);
  EXPECT_GT(with.x0, board.x0 + 5);
  EXPECT_LT(with.y1, board.y1 - 5);
}

} // namespace
} // namespace frep::render
