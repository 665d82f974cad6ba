// The pictures of a multimedia mapping, drawn headless with FRepKit's software renderer
// (Mapping/Render; the packaged VTK renders only through X, and `frepkit map` must not need a
// display): a cell or frame's section with one camera for every cell and frame (framing the
// solids: Scene/framing.h), the spreadsheet of cells with their labels, a frame's inset (the
// plane of the dynamic coordinates as a checkerboard with the path and the current point) and
// the path picture.
#pragma once

#include "Mapping/mapping_plan.h"
#include "Scene/framing.h"
#include "Scene/section_mesh.h"

#include "Raycast/raycast.h"

#include "Imaging/camera.h"
#include "Imaging/image.h"
#include "Render/text.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace frep::mapping
{

/// What drawing needs besides the geometry: a font (one per thread: FreeType faces are not
/// shared between threads). Without a font (none installed) pictures have no labels.
struct PictureKit
{
  PictureKit();
  std::optional<render::Font> font;
  std::string font_error; ///< why there is no font
};

/// The camera for every cell and frame of the plan, seen from the settings' azimuth and
/// elevation for the aspect ratio width / height: the settings' view_box when they have one
/// (box_camera); else the framing's outline, the solids seen from that direction (frame_solids,
/// Scene/framing.h), within 92% of the picture's width or height (imaging::fit_points); else,
/// with an empty framing, the plan's world box (box_camera).
imaging::Camera plan_camera(const Plan& plan,
  const RenderSettings& settings,
  double aspect,
  const Framing& framing = {});

/// The fraction of a frame's height (pixels) that decorate_frame's caption takes at the bottom.
double caption_band(int height);

/// The camera of the animation frames of width x height pixels (the page scene): plan_camera's
/// with the caption's band at the bottom kept free (caption_band), so the shape stays clear of
/// it.
imaging::Camera frame_camera(const Plan& plan,
  const RenderSettings& settings,
  int width,
  int height,
  const Framing& framing = {});

/// A camera that sees the box [lo, hi] from (azimuth, elevation) (imaging::fit_box's angles) with
/// its eight corners filling 92% of the picture of width / height = aspect, along its width or
/// its height, whichever the box reaches first (tighter than fit_box's fit_corners, which keeps
/// them in the circle of the shorter side).
imaging::Camera box_camera(const std::array<double, 3>& lo,
  const std::array<double, 3>& hi,
  double aspect,
  double azimuth,
  double elevation);

/// The section drawn with the sample's colour (or the section's vertex colours), opacity and
/// light intensity over the sample's background. A 2-D section (segments) is drawn as seen
/// from +z, fitted to the shown box (shown_box: the settings' view_box, else the framing's box,
/// else the world box). `threads` 0 = all cores. With `floor` (the floor scene, floor_scene.h),
/// the checkerboard, the path and the section's shadow are drawn with it.
imaging::Image render_sample(const Plan& plan,
  const Section& section,
  const Sample& sample,
  const imaging::Camera& camera,
  int width,
  int height,
  const RenderSettings& settings,
  int threads = 1,
  const raycast::Floor* floor = nullptr,
  const Framing& framing = {});

/// The cells (pictures in plan order: column fastest, then row, then layer) on the plan's grid
/// with gaps, each labelled with its coordinate values, the grid coordinates named along the
/// top and left edges. Layers (a third grid axis) are stacked as blocks left to right.
/// `rects`, when given, receives each cell picture's place (x, y, width, height in pixels).
imaging::Image compose_spreadsheet(const Plan& plan,
  const std::vector<imaging::Image>& cells,
  const Spec& spec,
  PictureKit* kit,
  std::vector<std::array<int, 4>>* rects = nullptr);

/// Draws the frame's caption (its time and coordinate values) and, when the settings ask for
/// it and there are two dynamic coordinates, the inset of the dynamic plane in a corner.
void decorate_frame(imaging::Image& frame,
  const Plan& plan,
  const Sample& sample,
  const RenderSettings& settings,
  PictureKit* kit);

/// The plane of the two dynamic coordinates with the path and every frame's point marked,
/// `size` pixels square.
imaging::Image path_picture(const Plan& plan, int size, PictureKit* kit);

} // namespace frep::mapping
