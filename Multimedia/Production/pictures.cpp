// produce, phase 5: the spreadsheet of cross-sections, the shape alone, the path picture.
#include "Production/detail/phases.h"

#include <array>

namespace frep::mapping::production
{
namespace
{

// The manifest's entry of the spreadsheet: its size, grid and every cell's values and place.
nlohmann::json spreadsheet_json(const Job& job,
  const imaging::Image& sheet,
  const std::vector<std::array<int, 4>>& rects)
{
  const Plan& plan = job.plan;
  nlohmann::json cells = nlohmann::json::array();
  for (std::size_t i = 0; i < plan.cells.size(); ++i)
  {
    const auto& c = plan.cells[i];
    nlohmann::json j = sample_json(c, job.coordinates.names);
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

void render_spreadsheet(const Job& job, Workers& workers, Record& record)
{
  const auto t0 = Clock::now();
  const Plan& plan = job.plan;
  const Spec& spec = job.spec();
  const int cell_px = spec.spreadsheet.cell_size;
  const imaging::Camera camera = plan_camera(plan, spec.render, 1.0, job.framing);
  std::vector<imaging::Image> pictures(plan.cells.size());
  Ledger cell_ledger;
  workers.parallel(plan.cells.size(),
    [&](std::size_t i, int worker)
    {
      Workers::Picture p =
        workers.picture(spec.render.method, plan.cells[i], camera, cell_px, cell_px, worker);
      pictures[i] = std::move(p.image);
      cell_ledger.add(p.mesh_seconds, p.render_seconds, 0.0);
      workers.advance();
    });
  std::vector<std::array<int, 4>> rects;
  const imaging::Image sheet = compose_spreadsheet(plan, pictures, spec, workers.kit(0), &rects);
  write_png_file(job.options.directory / "spreadsheet.png", sheet);
  record.files.push_back(spreadsheet_json(job, sheet, rects));
  record.sheet = sheet;
  record.sheet_rects = rects;
  record.stages.push_back({ "spreadsheet",
    seconds_since(t0),
    std::to_string(plan.cells.size()) + " cells, " + std::to_string(sheet.width) + "x" +
      std::to_string(sheet.height) + cell_ledger.text() });
}

void render_shape(const Job& job, Workers& workers, Record& record)
{
  const auto t0 = Clock::now();
  const Plan& plan = job.plan;
  const RenderSettings& render = job.spec().render;
  const imaging::Camera camera =
    plan_camera(plan, render, static_cast<double>(render.width) / render.height, job.framing);
  const Workers::Picture p = workers.picture(
    render.method, plan.still, camera, render.width, render.height, 0, workers.count());
  write_png_file(job.options.directory / "shape.png", p.image);
  const bool raycast = render.method == RenderSettings::Method::Raycast;
  nlohmann::json entry{ { "file", "shape.png" },
    { "kind", "shape" },
    { "width", p.image.width },
    { "height", p.image.height },
    { "method", raycast ? "raycast" : "mesh" } };
  if (!raycast)
  {
    entry["triangles"] = p.triangles;
  }
  record.files.push_back(entry);
  record.stages.push_back({ "shape",
    seconds_since(t0),
    raycast ? std::string("ray-cast") : std::to_string(p.triangles) + " triangles" });
}

void draw_path(const Job& job, Workers& workers, Record& record)
{
  const auto t0 = Clock::now();
  const Plan& plan = job.plan;
  const imaging::Image picture = path_picture(plan, 900, workers.kit(0));
  write_png_file(job.options.directory / "path.png", picture);
  record.files.push_back(
    { { "file", "path.png" }, { "kind", "path" }, { "coordinates", plan.dynamic_coordinates } });
  record.stages.push_back(
    { "path", seconds_since(t0), std::to_string(plan.frames.size()) + " points" });
}

} // namespace frep::mapping::production
