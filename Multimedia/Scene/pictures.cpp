#include "Scene/pictures.h"

#include "Scene/floor_mesh.h"

#include "Render/mesh_renderer.h"
#include "Render/plot2d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frep::mapping
{
namespace
{

imaging::Rgba to_rgba(const std::array<double, 3>& srgb_colour, double alpha = 1.0)
{
  return imaging::srgb(srgb_colour[0], srgb_colour[1], srgb_colour[2], alpha);
}

// Dark text on a light background, light text on a dark one.
imaging::Rgba text_colour_on(const std::array<double, 3>& background)
{
  const double luminance = 0.2126 * background[0] + 0.7152 * background[1] + 0.0722 * background[2];
  return luminance > 0.5 ? imaging::srgb_hex(0x222222) : imaging::srgb_hex(0xeeeeee);
}

render::Font* font_of(PictureKit* kit)
{
  return kit && kit->font ? &*kit->font : nullptr;
}

// A 2-D section (segments in z = 0): the shown box's x/y fitted into the picture.
void draw_contour(imaging::Image& image,
  const std::array<Interval, 3>& box,
  const Section& section,
  const Sample& sample)
{
  const double w = std::max(box[0].hi - box[0].lo, 1e-300),
               h = std::max(box[1].hi - box[1].lo, 1e-300);
  const double scale = 0.9 * std::min(image.width / w, image.height / h);
  const double ox = 0.5 * image.width - scale * 0.5 * (box[0].lo + box[0].hi);
  const double oy = 0.5 * image.height + scale * 0.5 * (box[1].lo + box[1].hi);
  const auto& s = section.surface;
  const imaging::Rgba colour = to_rgba(sample.colour, sample.opacity);
  const double width = std::max(1.5, image.height / 200.0);
  for (std::size_t c = 0; c + 1 < s.cells.size(); c += 2)
  {
    const std::uint32_t a = s.cells[c], b = s.cells[c + 1];
    const render::Point2 line[2] = { { ox + scale * s.points[3 * a],
                                       oy - scale * s.points[3 * a + 1] },
      { ox + scale * s.points[3 * b], oy - scale * s.points[3 * b + 1] } };
    render::draw_polyline(image, line, width, colour);
  }
}

// decorate_frame's caption: its text size and its baseline's height above the bottom, pixels.
double caption_px(int height)
{
  return std::max(12.0, height / 34.0);
}
double caption_lift(int height)
{
  return 0.03 * height;
}

// The camera of plan_camera and frame_camera, `band` of the height kept free at the bottom.
imaging::Camera fitted(const Plan& plan,
  const RenderSettings& settings,
  double aspect,
  const Framing& framing,
  double band)
{
  imaging::FitOptions fit;
  fit.fill = 0.92;
  fit.free_bottom = band;
  if (!settings.view_box && !framing.outline.empty())
  {
    return imaging::fit_points(framing.outline, aspect, settings.azimuth, settings.elevation, fit);
  }
  // The box's eight corners, not its bounding sphere (up to sqrt(3) wider), fill the picture.
  const std::array<Interval, 3> box = shown_box(plan, settings);
  std::array<imaging::Vec3, 8> corners;
  for (int c = 0; c < 8; ++c)
  {
    corners[c] = {
      c & 1 ? box[0].hi : box[0].lo, c & 2 ? box[1].hi : box[1].lo, c & 4 ? box[2].hi : box[2].lo
    };
  }
  return imaging::fit_points(corners, aspect, settings.azimuth, settings.elevation, fit);
}

std::string format_time(double t)
{
  char text[32];
  std::snprintf(text, sizeof text, "t = %.2f s", t);
  return text;
}

} // namespace

PictureKit::PictureKit()
{
  render::Font::LoadResult loaded = render::Font::load_default();
  if (loaded.ok())
  {
    font = std::move(loaded.font);
  }
  else
  {
    font_error = loaded.error;
  }
}

imaging::Camera plan_camera(const Plan& plan,
  const RenderSettings& settings,
  double aspect,
  const Framing& framing)
{
  return fitted(plan, settings, aspect, framing, 0.0);
}

double caption_band(int height)
{
  // The caption's text, its descent and a gap, over its baseline.
  return height > 0 ? std::min((caption_lift(height) + 1.3 * caption_px(height)) / height, 0.5)
                    : 0.0;
}

imaging::Camera frame_camera(const Plan& plan,
  const RenderSettings& settings,
  int width,
  int height,
  const Framing& framing)
{
  const double aspect = static_cast<double>(width) / std::max(height, 1);
  return fitted(plan, settings, aspect, framing, caption_band(height));
}

imaging::Camera box_camera(const std::array<double, 3>& lo,
  const std::array<double, 3>& hi,
  double aspect,
  double azimuth,
  double elevation)
{
  // The eight corners, not the box's bounding sphere (up to sqrt(3) wider), fill the picture.
  std::array<imaging::Vec3, 8> corners;
  for (int c = 0; c < 8; ++c)
  {
    corners[c] = { c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2] };
  }
  imaging::FitOptions fit;
  fit.fill = 0.92;
  return imaging::fit_points(corners, aspect, azimuth, elevation, fit);
}

imaging::Image render_sample(const Plan& plan,
  const Section& section,
  const Sample& sample,
  const imaging::Camera& camera,
  int width,
  int height,
  const RenderSettings& settings,
  int threads,
  const raycast::Floor* floor,
  const Framing& framing)
{
  imaging::Image image(width, height, to_rgba(sample.background));
  const mesh::Surface& s = section.surface;
  if (s.cells.empty() && !floor)
  {
    return image;
  }
  if (s.dimension == 2)
  {
    // No camera for a flat section: it is drawn as seen from +z, fitted to the view box.
    draw_contour(image, shown_box(plan, settings, framing), section, sample);
    return image;
  }
  std::vector<float> linear;
  if (!section.colours.empty())
  {
    linear.resize(section.colours.size());
    std::transform(section.colours.begin(),
      section.colours.end(),
      linear.begin(),
      [](float c) { return imaging::srgb_to_linear(c); });
  }
  imaging::RenderStyle style;
  style.threads = threads;
  style.supersample = std::max(width, height) <= 400 ? 3 : 2;
  for (auto& light : style.lights)
  {
    light.intensity *= sample.light_intensity;
  }
  style.ambient *= sample.light_intensity;
  render::MeshInput mesh;
  mesh.points = s.points;
  mesh.triangles = s.cells;
  mesh.normals = s.normals;
  mesh.colours = linear;
  const imaging::Rgba c = to_rgba(sample.colour);
  mesh.colour = { c.r, c.g, c.b };
  mesh.opacity = sample.opacity;
  if (!floor)
  {
    render::render_mesh(image, camera, mesh, style);
    return image;
  }
  // The floor scene: board and path, the shape, its shadow over the board (a transparent
  // layer of its own: overlapping shadow triangles do not darken twice).
  render::Renderer renderer(width, height, camera, style);
  const OwnedMesh board = floor_board(*floor);
  renderer.add(board.input({ 1.0F, 1.0F, 1.0F }));
  if (!s.cells.empty())
  {
    renderer.add(mesh);
    const OwnedMesh shadow = floor_shadow(*floor, s, camera, style);
    if (!shadow.triangles.empty())
    {
      render::MeshInput dark = shadow.input({ 0.0F, 0.0F, 0.0F }, 0.45);
      renderer.add(dark);
    }
  }
  renderer.resolve(image);
  return image;
}

imaging::Image compose_spreadsheet(const Plan& plan,
  const std::vector<imaging::Image>& cells,
  const Spec& spec,
  PictureKit* kit,
  std::vector<std::array<int, 4>>* rects)
{
  if (rects)
  {
    rects->clear();
  }
  const int columns = std::max(1, plan.grid_shape[0]);
  const int rows = std::max(1, plan.grid_shape[1]);
  const int layers = std::max(1, plan.grid_shape[2]);
  const int cell = spec.spreadsheet.cell_size;
  const int gap = static_cast<int>(std::lround(spec.spreadsheet.spacing * cell));
  render::Font* font = font_of(kit);
  const bool labels = spec.spreadsheet.labels && font;
  const double label_px = std::max(11.0, 0.065 * cell);
  const int label_h = labels ? static_cast<int>(std::ceil(1.7 * label_px)) : 0;
  const double title_px = std::max(14.0, 0.09 * cell);
  const int title_h = labels ? static_cast<int>(std::ceil(2.2 * title_px)) : 0;
  const int margin = std::max(gap, 8);
  const int block_w = columns * cell + (columns - 1) * gap;
  const int width = 2 * margin + layers * block_w + (layers - 1) * 3 * gap;
  const int height = 2 * margin + title_h + rows * (cell + label_h) + (rows - 1) * gap;
  const std::array<double, 3>& bg = spec.render.background;
  imaging::Image sheet(width, height, to_rgba(bg));
  const imaging::Rgba ink = text_colour_on(bg);
  const imaging::Rgba border =
    imaging::srgb(0.5 * bg[0] + 0.25, 0.5 * bg[1] + 0.25, 0.5 * bg[2] + 0.25);

  if (labels)
  {
    std::string title;
    const char* arrows[3] = { "\u2192 columns", "\u2193 rows", "layers" };
    for (std::size_t k = 0; k < plan.grid_coordinates.size() && k < 3; ++k)
    {
      if (!plan.grid_coordinates[k].empty())
      {
        title += (title.empty() ? "" : ",   ") + plan.grid_coordinates[k] + " " + arrows[k];
      }
    }
    font->draw(sheet,
      width / 2.0,
      margin + 0.5 * title_h,
      title,
      title_px,
      ink,
      { render::HAlign::Centre, render::VAlign::Middle });
  }
  for (std::size_t i = 0; i < cells.size() && i < plan.cells.size(); ++i)
  {
    const Sample& s = plan.cells[i];
    const int c = std::max(0, s.cell[0]), r = std::max(0, s.cell[1]), l = std::max(0, s.cell[2]);
    const int x = margin + l * (block_w + 3 * gap) + c * (cell + gap);
    const int y = margin + title_h + r * (cell + label_h + gap);
    imaging::composite_over(sheet, cells[i], x, y);
    if (rects)
    {
      rects->push_back({ x, y, cells[i].width, cells[i].height });
    }
    render::stroke_rect(sheet, { x - 0.5, y - 0.5, x + cell + 0.5, y + cell + 0.5 }, 1.0, border);
    if (labels)
    {
      font->draw(sheet,
        x + cell / 2.0,
        y + cell + 0.55 * label_h,
        s.label,
        label_px,
        ink,
        { render::HAlign::Centre, render::VAlign::Middle });
    }
  }
  return sheet;
}

void decorate_frame(imaging::Image& frame,
  const Plan& plan,
  const Sample& sample,
  const RenderSettings& settings,
  PictureKit* kit)
{
  render::Font* font = font_of(kit);
  const double px = caption_px(frame.height);
  if (font)
  {
    const std::string caption = format_time(sample.time) + "     " + sample.label;
    font->draw(frame,
      0.025 * frame.height,
      frame.height - caption_lift(frame.height),
      caption,
      px,
      text_colour_on(sample.background),
      { render::HAlign::Left, render::VAlign::Bottom });
  }
  // The floor scene shows the plane itself: no inset then.
  if (!settings.inset || settings.scene == RenderSettings::Scene::Floor ||
      plan.dynamic_coordinates.size() != 2 || plan.path_polyline.empty())
  {
    return;
  }
  const double size = 0.32 * frame.height;
  const double margin = 0.03 * frame.height;
  render::CheckerboardInset inset;
  inset.rect = { frame.width - margin - size, margin, frame.width - margin, margin + size };
  inset.u_lo = plan.path_plane[0].lo;
  inset.u_hi = plan.path_plane[0].hi;
  inset.v_lo = plan.path_plane[1].lo;
  inset.v_hi = plan.path_plane[1].hi;
  for (const auto& p : plan.path_polyline)
  {
    inset.path.push_back({ p[0], p[1] });
  }
  if (sample.path_point.size() == 2)
  {
    inset.current = render::Point2{ sample.path_point[0], sample.path_point[1] };
  }
  inset.past_points = static_cast<std::size_t>(std::lround(
                        std::clamp(sample.path_parameter, 0.0, 1.0) * (inset.path.size() - 1))) +
                      1;
  inset.u_label = plan.dynamic_coordinates[0];
  inset.v_label = plan.dynamic_coordinates[1];
  render::draw_checkerboard_inset(frame, inset, font);
}

imaging::Image path_picture(const Plan& plan, int size, PictureKit* kit)
{
  imaging::Image picture(size, size, imaging::srgb(1, 1, 1));
  if (plan.dynamic_coordinates.size() != 2)
  {
    return picture;
  }
  render::CheckerboardInset inset;
  const double margin = 0.02 * size;
  inset.rect = { margin, margin, size - margin, size - margin };
  inset.u_lo = plan.path_plane[0].lo;
  inset.u_hi = plan.path_plane[0].hi;
  inset.v_lo = plan.path_plane[1].lo;
  inset.v_hi = plan.path_plane[1].hi;
  for (const auto& p : plan.path_polyline)
  {
    inset.path.push_back({ p[0], p[1] });
  }
  for (const auto& f : plan.frames)
  {
    if (f.path_point.size() == 2)
    {
      inset.markers.push_back({ f.path_point[0], f.path_point[1] });
    }
  }
  inset.u_label = plan.dynamic_coordinates[0];
  inset.v_label = plan.dynamic_coordinates[1];
  inset.background = imaging::srgb(1, 1, 1);
  render::draw_checkerboard_inset(picture, inset, font_of(kit));
  return picture;
}

} // namespace frep::mapping
