#include "SectionPicture.h"

#include "SectionMeshConversion.h"
#include "SectionTape.h"

#include "Raycast/raycast.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace frepstudio
{

std::array<float, 3> default_face_colour_linear()
{
  return { frep::imaging::srgb_to_linear(50 / 255.0F), frep::imaging::srgb_to_linear(200 / 255.0F),
    frep::imaging::srgb_to_linear(80 / 255.0F) };
}

QImage to_qimage(const frep::imaging::Image& picture)
{
  QImage image(picture.width, picture.height, QImage::Format_RGB888);
  for (int y = 0; y < picture.height; ++y)
  {
    uchar* row = image.scanLine(y);
    for (int x = 0; x < picture.width; ++x)
    {
      const float* p = picture.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        row[3 * x + c] = static_cast<uchar>(
          std::lround(std::clamp(frep::imaging::linear_to_srgb(p[c]), 0.0F, 1.0F) * 255));
    }
  }
  return image;
}

QImage section_picture(const SectionPictureRequest& request,
  const std::function<bool()>& keep_going)
{
  if (!request.model || request.model->x_dim() < 3 || request.width < 1 || request.height < 1)
    return {};
  frep::raycast::Shape shape;
  try
  {
    shape.tape = section_tape(*request.model, request.parameters, request.fixed_values);
  }
  catch (const std::exception&)
  {
    return {}; // the mesh worker reports the same failure in the status line
  }
  for (int i = 0; i < 3; ++i)
    shape.box[i] = { request.lo[i], request.hi[i] };
  // The mesh path's colours: s[1..3] as RGB when the model sets them, else hfp's green.
  if (colouring_for(*shape.tape, request.s_dim) == SectionColouring::Rgb)
    shape.colour_function = frep::raycast::attribute_colours();
  else
    shape.colour = default_face_colour_linear();

  frep::imaging::Image picture(request.width, request.height, frep::imaging::srgb(0, 0, 0));
  for (int y = 0; y < picture.height; ++y)
  {
    // Row 0 is the top of the picture.
    const float t = picture.height > 1 ? 1.0F - static_cast<float>(y) / (picture.height - 1) : 0;
    std::array<float, 3> colour;
    for (int c = 0; c < 3; ++c)
      colour[c] = frep::imaging::srgb_to_linear(
        request.background_bottom[c] + t * (request.background_top[c] - request.background_bottom[c]));
    for (int x = 0; x < picture.width; ++x)
      std::copy(colour.begin(), colour.end(), picture.pixel(x, y));
  }
  frep::raycast::Style style;
  style.render.supersample = std::clamp(request.supersample, 1, 4);
  frep::RunControl run;
  run.threads = request.threads;
  run.cancel = [&keep_going] { return keep_going && !keep_going(); };
  const frep::raycast::Result result =
    frep::raycast::render(picture, request.camera, shape, nullptr, style, nullptr, run);
  if (!result.ok() || (keep_going && !keep_going()))
    return {};
  return to_qimage(picture);
}

} // namespace frepstudio
