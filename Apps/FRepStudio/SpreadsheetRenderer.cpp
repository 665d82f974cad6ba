#include "SpreadsheetRenderer.h"

#include "SectionMeshConversion.h"
#include "SectionPicture.h"
#include "SectionTape.h"

#include "Eval/thread_pool.h"
#include "Mapping/mapping_json.h"
#include "Scene/pictures.h"
#include "Scene/sample_picture.h"

#include <cmath>
#include <exception>

namespace frepstudio
{

namespace
{

namespace fm = frep::mapping;

constexpr std::array<double, 3> kCellBackground{ 0.24, 0.26, 0.31 }; // sRGB, the 3-D view's
constexpr std::array<double, 3> kFaceColour{ 50 / 255.0, 200 / 255.0, 80 / 255.0 }; // hfp's

// The 3-D view's default look (SectionView: y up, the camera towards (1, 0.8, 2.2) of the box's
// centre) in the mapping's world, whose up is z: x1 -> x, x2 -> z (up), x3 -> -y (a rotation
// about x, as Examples/homotopic/homotopic.json maps them), and that direction, (1, -2.2, 0.8)
// in the world, as the mapping's azimuth and elevation (imaging::fit_box's angles).
constexpr std::array<int, 3> kWorldAxis{ 0, 2, 1 };
const double kAzimuth = std::atan2(1.0, 2.2) * 180.0 / M_PI;                          // 24.4
const double kElevation = std::atan2(0.8, std::sqrt(1.0 + 2.2 * 2.2)) * 180.0 / M_PI; // 18.3

fm::Channel world_channel(int coordinate, double lo, double hi)
{
  fm::Channel c;
  c.type = fm::Channel::Type::World;
  c.axis = kWorldAxis[static_cast<std::size_t>(coordinate)];
  c.range = fm::Interval{ lo, hi };
  if (coordinate == 2)
    c.target = fm::Interval{ hi, lo }; // x3 grows towards -y: a rotation, not a mirror
  return c;
}

fm::Channel grid_channel(int grid_axis, const std::vector<double>& values)
{
  fm::Channel c;
  c.type = fm::Channel::Type::Spreadsheet;
  c.grid_axis = grid_axis;
  c.values = values;
  return c;
}

// The sheet's mapping as text without what only changes how cells are drawn: two sheets with
// the same text frame the same solids from the same direction.
std::string framing_key(fm::Spec spec)
{
  spec.render.method = fm::RenderSettings::Method::Mesh;
  spec.world.resolution = 0;
  spec.spreadsheet.cell_size = 0;
  spec.render.width = spec.render.height = 0;
  return fm::save_mapping(spec);
}

fm::Channel fixed_channel(double value)
{
  fm::Channel c;
  c.type = fm::Channel::Type::Fixed;
  c.value = value;
  return c;
}

} // namespace

fm::Spec sheet_mapping(const SheetRequest& request, bool model_colours)
{
  const CellRequest& base = request.base;
  fm::Spec spec;
  spec.parameters = base.parameters;
  for (int i = 0; i < 3; ++i)
    spec.coordinates.push_back({ "x" + std::to_string(i + 1),
      { world_channel(
        i, base.lo[static_cast<std::size_t>(i)], base.hi[static_cast<std::size_t>(i)]) } });
  for (int k = 0; k < static_cast<int>(base.fixed_values.size()); ++k)
  {
    const fm::Channel channel = k == request.row_coordinate ? grid_channel(1, request.row_values)
                                : k == request.column_coordinate
                                  ? grid_channel(0, request.column_values)
                                  : fixed_channel(base.fixed_values[static_cast<std::size_t>(k)]);
    spec.coordinates.push_back({ "x" + std::to_string(k + 4), { channel } });
  }
  spec.world.resolution = base.resolution;
  spec.spreadsheet.cell_size = base.pixels;
  spec.render.width = spec.render.height = base.pixels;
  spec.render.background = kCellBackground;
  spec.render.colour = kFaceColour;
  spec.render.azimuth = kAzimuth;
  spec.render.elevation = kElevation;
  spec.render.colour_source = model_colours ? fm::RenderSettings::ColourSource::Attributes
                                            : fm::RenderSettings::ColourSource::Uniform;
  spec.render.method =
    base.raycast ? fm::RenderSettings::Method::Raycast : fm::RenderSettings::Method::Mesh;
  return spec;
}

std::unique_ptr<SheetRenderer> SheetRenderer::prepare(const SheetRequest& request,
  const std::shared_ptr<frep::ThreadPool>& pool,
  const std::function<bool()>& keep_going,
  std::string* error,
  const std::shared_ptr<const SheetFraming>& previous,
  const std::function<void(double)>& progress)
{
  const CellRequest& base = request.base;
  if (!base.model || base.model->x_dim() < 4)
  {
    *error = "the spreadsheet needs a model with a coordinate beyond x1..x3";
    return nullptr;
  }
  bool model_colours = false;
  try
  {
    model_colours = colouring_for(*section_tape(*base.model, base.parameters, base.fixed_values),
                      base.s_dim) == SectionColouring::Rgb;
  }
  catch (const std::exception& e)
  {
    *error = e.what();
    return nullptr;
  }
  std::unique_ptr<SheetRenderer> sheet(new SheetRenderer());
  sheet->base_ = base;
  sheet->pool_ = pool;
  sheet->spec_ = sheet_mapping(request, model_colours);
  fm::PlanResult planned =
    fm::make_plan(sheet->spec_, fm::hyperfun_coordinates(base.model->x_dim()));
  if (!planned.ok())
  {
    *error = fm::format_errors(planned.errors);
    return nullptr;
  }
  sheet->plan_ = std::move(planned.plan);
  if (!keep_going())
    return nullptr;
  std::string key = framing_key(sheet->spec_);
  if (previous && previous->model == base.model && previous->mapping == key)
  {
    sheet->framing_ = previous;
  }
  else
  {
    frep::RunControl run;
    run.pool = pool;
    run.cancel = [&keep_going] { return !keep_going(); };
    if (progress)
      run.progress = [&progress](double f) { progress(f); return true; };
    auto framed = std::make_shared<SheetFraming>();
    framed->model = base.model;
    framed->mapping = std::move(key);
    framed->framing =
      fm::frame_solids(sheet->spec_.render, *base.model, base.parameters, sheet->plan_, run);
    if (framed->framing.cancelled)
      return nullptr;
    sheet->framing_ = std::move(framed);
  }
  sheet->camera_ = fm::plan_camera(sheet->plan_, sheet->spec_.render, 1.0, sheet->framing_->framing);
  return keep_going() ? std::move(sheet) : nullptr;
}

QImage SheetRenderer::cell(std::size_t i,
  const std::function<bool()>& keep_going,
  std::string* error) const
{
  if (i >= plan_.cells.size())
    return {};
  fm::DrawOptions options;
  options.pool = pool_;
  options.cancel = [&keep_going] { return !keep_going(); };
  // FRepStudio's cells sample `resolution` points on every axis (the mapping's resolution is
  // along the longest axis only).
  options.samples = { base_.resolution, base_.resolution, base_.resolution };
  const fm::SamplePicture p = fm::draw_sample(*base_.model,
    base_.parameters,
    plan_,
    plan_.cells[i],
    camera_,
    base_.pixels,
    base_.pixels,
    spec_.render,
    spec_.render.method,
    options,
    framing_->framing);
  if (!p.ok())
  {
    if (!p.cancelled)
      *error = p.error;
    return {};
  }
  return to_qimage(p.image);
}

} // namespace frepstudio
