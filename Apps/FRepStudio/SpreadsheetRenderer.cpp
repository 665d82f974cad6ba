#include "SpreadsheetRenderer.h"

#include "SectionMeshConversion.h"

#include "Compiler/attribute_rgb.h"
#include "Mesh/surface.h"
#include "Render/image.h"
#include "Render/mesh_renderer.h"

#include <cmath>
#include <optional>

namespace frepstudio
{

QImage render_cell(const CellRequest& request, const std::shared_ptr<frep::ThreadPool>& pool,
  const std::function<bool()>& keep_going)
{
  if (!request.model || request.model->x_dim() < 3)
    return {};
  frep::Specialisation specialisation;
  specialisation.parameters = request.parameters;
  specialisation.fixed.assign(static_cast<std::size_t>(request.model->x_dim()), std::nullopt);
  for (std::size_t k = 0; k < request.fixed_values.size() && k + 3 < specialisation.fixed.size();
       ++k)
    specialisation.fixed[k + 3] = request.fixed_values[k];
  const auto tape = request.model->specialise(specialisation);

  frep::mesh::Grid grid;
  grid.lo = request.lo;
  grid.hi = request.hi;
  grid.samples = { request.resolution, request.resolution, request.resolution };
  frep::mesh::ExtractOptions options;
  options.pool = pool;
  options.progress = [&keep_going](double) { return keep_going(); };
  const frep::mesh::ExtractResult result = frep::mesh::extract_surface(tape, grid, options);
  if (!result.ok())
    return {};

  // The 3-D view's default direction (SectionView), closer than where the box's bounding sphere
  // would fit: the box's corners leave the picture, but the shapes (usually well inside the
  // box) are large enough to read in a small cell.
  constexpr double kFill = 1.3;
  const double angle = 30.0;
  frep::render::Camera camera;
  camera.view_angle_deg = angle;
  frep::render::Vec3 centre{};
  double radius = 0;
  for (int i = 0; i < 3; ++i)
  {
    centre[i] = (request.lo[i] + request.hi[i]) / 2;
    radius += std::pow((request.hi[i] - request.lo[i]) / 2, 2);
  }
  radius = std::sqrt(radius);
  const double distance = radius / std::sin(angle / 2 * M_PI / 180) / kFill;
  const frep::render::Vec3 direction{ 1, 0.8, 2.2 };
  const double length = std::sqrt(1 + 0.64 + 4.84);
  for (int i = 0; i < 3; ++i)
    camera.position[i] = centre[i] + direction[i] / length * distance;
  camera.focal_point = centre;
  camera.view_up = { 0, 1, 0 };

  frep::render::Image picture(request.pixels, request.pixels,
    frep::render::srgb(0.24, 0.26, 0.31));
  std::vector<float> colours;
  frep::render::MeshInput mesh;
  mesh.points = result.surface.points;
  mesh.triangles = result.surface.cells;
  mesh.normals = result.surface.normals;
  if (colouring_for(*tape, request.s_dim) == SectionColouring::Rgb)
  {
    const frep::mesh::Surface& surface = result.surface;
    for (const frep::AttributeRgb& c : frep::attribute_colours(surface.attributes,
           static_cast<std::size_t>(surface.attribute_count),
           surface.point_count()))
      for (float component : c)
        colours.push_back(frep::render::srgb_to_linear(component));
    mesh.colours = colours;
  }
  else
  {
    // hfp's face colour (50, 200, 80), as in the 3-D view.
    mesh.colour = { frep::render::srgb_to_linear(50 / 255.0F),
      frep::render::srgb_to_linear(200 / 255.0F), frep::render::srgb_to_linear(80 / 255.0F) };
  }
  frep::render::RenderStyle style;
  style.threads = 1; // cells are small; the mesher already uses the cores
  if (!frep::render::render_mesh(picture, camera, mesh, style).ok() || !keep_going())
    return {};

  QImage image(picture.width, picture.height, QImage::Format_RGB888);
  for (int y = 0; y < picture.height; ++y)
  {
    uchar* row = image.scanLine(y);
    for (int x = 0; x < picture.width; ++x)
    {
      const float* p = picture.pixel(x, y);
      for (int c = 0; c < 3; ++c)
        row[3 * x + c] = static_cast<uchar>(
          std::lround(std::clamp(frep::render::linear_to_srgb(p[c]), 0.0F, 1.0F) * 255));
    }
  }
  return image;
}

} // namespace frepstudio
