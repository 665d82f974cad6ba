// frepkit map, phase 4: the spreadsheet of cross-sections, the shape alone, the path picture.
#include "map_phases.h"

#include <array>

namespace frepkit::map_run
{
namespace
{

// The manifest's entry of the spreadsheet: its size, grid and every cell's values and place.
nlohmann::json spreadsheet_json(const MapInputs& in,
  const frep::render::Image& sheet,
  const std::vector<std::array<int, 4>>& rects)
{
  const mapping::Plan& plan = in.plan;
  nlohmann::json cells = nlohmann::json::array();
  for (std::size_t i = 0; i < plan.cells.size(); ++i)
  {
    const auto& c = plan.cells[i];
    nlohmann::json j = sample_json(c, in.coordinates.names);
    j["cell"] = { c.cell[0], c.cell[1], c.cell[2] };
    if (i < rects.size())
    {
      j["rect"] = rects[i]; // x, y, width, height of the cell's picture in spreadsheet.png
    }
    cells.push_back(j);
  }
  return { { "file", "spreadsheet.png" },
    { "kind", "spreadsheet" },
    { "width", sheet.width },
    { "height", sheet.height },
    { "grid", { plan.grid_shape[0], plan.grid_shape[1], plan.grid_shape[2] } },
    { "cells", cells } };
}

} // namespace

void render_spreadsheet(const MapInputs& in,
  MapWorkers& workers,
  const fs::path& out_dir,
  MapRecord& record)
{
  const auto t0 = Clock::now();
  const mapping::Plan& plan = in.plan;
  const mapping::Spec& spec = in.spec;
  const int cell_px = spec.spreadsheet.cell_size;
  const frep::render::Camera camera = mapping::plan_camera(plan, spec.render, 1.0);
  std::vector<frep::render::Image> pictures(plan.cells.size());
  Ledger cell_ledger;
  workers.parallel(plan.cells.size(),
    [&](std::size_t i, int worker)
    {
      const auto m0 = Clock::now();
      const mapping::Section section = workers.section(plan.cells[i], worker);
      const auto r0 = Clock::now();
      pictures[i] =
        mapping::render_sample(plan, section, plan.cells[i], camera, cell_px, cell_px, spec.render);
      cell_ledger.add(std::chrono::duration<double>(r0 - m0).count(), seconds_since(r0), 0.0);
      workers.advance();
    });
  std::vector<std::array<int, 4>> rects;
  const frep::render::Image sheet =
    mapping::compose_spreadsheet(plan, pictures, spec, workers.kit(0), &rects);
  write_png_file(out_dir / "spreadsheet.png", sheet);
  record.files.push_back(spreadsheet_json(in, sheet, rects));
  record.stages.push_back({ "spreadsheet",
    seconds_since(t0),
    std::to_string(plan.cells.size()) + " cells, " + std::to_string(sheet.width) + "x" +
      std::to_string(sheet.height) + cell_ledger.text() });
}

void render_shape(const MapInputs& in,
  MapWorkers& workers,
  const fs::path& out_dir,
  MapRecord& record)
{
  const auto t0 = Clock::now();
  const mapping::Plan& plan = in.plan;
  const mapping::RenderSettings& render = in.spec.render;
  const frep::render::Camera camera =
    mapping::plan_camera(plan, render, static_cast<double>(render.width) / render.height);
  const mapping::Section section = workers.section(plan.still, 0);
  const frep::render::Image picture = mapping::render_sample(
    plan, section, plan.still, camera, render.width, render.height, render, workers.count());
  write_png_file(out_dir / "shape.png", picture);
  record.files.push_back({ { "file", "shape.png" },
    { "kind", "shape" },
    { "width", picture.width },
    { "height", picture.height },
    { "triangles", section.surface.cell_count() } });
  record.stages.push_back(
    { "shape", seconds_since(t0), std::to_string(section.surface.cell_count()) + " triangles" });
}

void draw_path(const MapInputs& in, MapWorkers& workers, const fs::path& out_dir, MapRecord& record)
{
  const auto t0 = Clock::now();
  const mapping::Plan& plan = in.plan;
  const frep::render::Image picture = mapping::path_picture(plan, 900, workers.kit(0));
  write_png_file(out_dir / "path.png", picture);
  record.files.push_back(
    { { "file", "path.png" }, { "kind", "path" }, { "coordinates", plan.dynamic_coordinates } });
  record.stages.push_back(
    { "path", seconds_since(t0), std::to_string(plan.frames.size()) + " points" });
}

} // namespace frepkit::map_run
