#include "SpreadsheetRenderer.h"

#include "SectionMeshConversion.h"
#include "SectionPicture.h"
#include "SectionTape.h"

#include "Compiler/attribute_rgb.h"
#include "Mesh/surface.h"
#include "Imaging/image.h"
#include "Render/mesh_renderer.h"

#include <cmath>
#include <optional>
#include <stdexcept>

namespace frepstudio
{

namespace
{

// The 3-D view's default direction (SectionView), closer than where the box's bounding sphere
// would fit: the box's corners leave the picture, but the shapes (usually well inside the
// box) are large enough to read in a small cell.
frep::imaging::Camera cell_camera(const CellRequest& request)
{
  constexpr double kFill = 1.3;
  const double angle = 30.0;
  frep::imaging::Camera camera;
  camera.view_angle_deg = angle;
  frep::imaging::Vec3 centre{};
  double radius = 0;
  for (int i = 0; i < 3; ++i)
  {
    centre[i] = (request.lo[i] + request.hi[i]) / 2;
    radius += std::pow((request.hi[i] - request.lo[i]) / 2, 2);
  }
  radius = std::sqrt(radius);
  const double distance = radius / std::sin(angle / 2 * M_PI / 180) / kFill;
  const frep::imaging::Vec3 direction{ 1, 0.8, 2.2 };
  const double length = std::sqrt(1 + 0.64 + 4.84);
  for (int i = 0; i < 3; ++i)
    camera.position[i] = centre[i] + direction[i] / length * distance;
  camera.focal_point = centre;
  camera.view_up = { 0, 1, 0 };
  return camera;
}

constexpr std::array<float, 3> kCellBackground{ 0.24F, 0.26F, 0.31F }; // sRGB

QImage raycast_cell(const CellRequest& request, const std::function<bool()>& keep_going)
{
  SectionPictureRequest picture;
  static_cast<SectionSpec&>(picture) = request;
  picture.camera = cell_camera(request);
  picture.width = picture.height = request.pixels;
  picture.background_bottom = picture.background_top = kCellBackground;
  picture.supersample = 3; // small cells: silhouettes are most of what they show
  return section_picture(picture, keep_going);
}

} // namespace

QImage render_cell(const CellRequest& request, const std::shared_ptr<frep::ThreadPool>& pool,
  const std::function<bool()>& keep_going)
{
  if (!request.model || request.model->x_dim() < 3)
    return {};
  if (request.raycast)
    return raycast_cell(request, keep_going);
  std::shared_ptr<const frep::Tape> tape;
  try
  {
    tape = section_tape(*request.model, request.parameters, request.fixed_values);
  }
  catch (const std::exception&)
  {
    return {};
  }

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

  const frep::imaging::Camera camera = cell_camera(request);
  frep::imaging::Image picture(request.pixels, request.pixels,
    frep::imaging::srgb(kCellBackground[0], kCellBackground[1], kCellBackground[2]));
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
        colours.push_back(frep::imaging::srgb_to_linear(component));
    mesh.colours = colours;
  }
  else
  {
    mesh.colour = default_face_colour_linear(); // as in the 3-D view
  }
  frep::imaging::RenderStyle style;
  style.threads = 1; // cells are small; the mesher already uses the cores
  if (!frep::render::render_mesh(picture, camera, mesh, style).ok() || !keep_going())
    return {};
  return to_qimage(picture);
}

} // namespace frepstudio
