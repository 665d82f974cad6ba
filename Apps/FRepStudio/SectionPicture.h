// A section drawn by rays (FRepKit::Raycast), without a mesh, into a QImage: the spreadsheet's
// ray-cast cells and the 3-D view's "High quality" picture. No OpenGL: it runs on worker threads.
#pragma once

#include "SectionSpec.h"
#include "Compiler/model.h"
#include "Imaging/camera.h"
#include "Imaging/image.h"

#include <QImage>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace frepstudio
{

struct SectionPictureRequest : SectionSpec
{
  frep::imaging::Camera camera;       ///< in x1..x3 (the section is drawn where it is)
  int width = 160;
  int height = 160;
  /// sRGB background, from the bottom row to the top row (a vertical gradient, as VTK's).
  std::array<float, 3> background_bottom{ 0.24F, 0.26F, 0.31F };
  std::array<float, 3> background_top{ 0.24F, 0.26F, 0.31F };
  int supersample = 2; ///< rays per pixel axis at silhouettes
  int threads = 0;     ///< 0 = all cores
};

/// The section's picture; a null image when cancelled (`keep_going` returned false), when the
/// model has fewer than three coordinates, or when the model cannot be specialised.
QImage section_picture(const SectionPictureRequest& request,
  const std::function<bool()>& keep_going);

/// The renderer's linear picture as an 8-bit sRGB QImage.
QImage to_qimage(const frep::imaging::Image& picture);

/// hfp's face colour (50, 200, 80), the sections' colour when the model has no s[] colours.
std::array<float, 3> default_face_colour_linear();

} // namespace frepstudio
