// The multimedia mapping from C++, without a JSON file and without VTK: a 4-D model (a ball that
// turns into a torus as x4 goes from 0 to 1, Examples/mapping/morph4d.hf) mapped with x1..x3 onto
// world space and x4 onto the columns of a spreadsheet and onto pitch; each cell's section is
// meshed and measured, and the spreadsheet is drawn headless into a PPM picture.
//
//   build/bin/frep_example_multimedia_mapping Examples/mapping/morph4d.hf spreadsheet.ppm
#include "Mapping/mapping_plan.h"
#include "Mapping/mapping_spec.h"
#include "Scene/framing.h"
#include "Scene/pictures.h"
#include "Scene/section_mesh.h"

#include "Compiler/model.h"
#include "Compiler/load_model.h"
#include "Mesh/mesh_topology.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

int main(int argc, char** argv)
{
  if (argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " MODEL.hf OUT.ppm\n";
    return 1;
  }
  const frep::LoadedModel compiled = frep::load_model(frep::ModelSource::file(argv[1]));
  if (!compiled.ok())
  {
    std::cerr << compiled.message();
    return 1;
  }
  const frep::Model& model = *compiled.model;

  // 1. The mapping, in code: the same structure the JSON file describes.
  namespace fm = frep::mapping;
  fm::Spec spec;
  for (int k = 0; k < 3; ++k)
  {
    fm::Channel world;
    world.type = fm::Channel::Type::World;
    world.axis = k;
    world.range = fm::Interval{ -2.4, 2.4 };
    spec.coordinates.push_back({ std::string("x") + char('1' + k), { world } });
  }
  fm::Channel columns;
  columns.type = fm::Channel::Type::Spreadsheet;
  columns.grid_axis = 0;
  columns.values = { 0.0, 0.25, 0.5, 0.75, 1.0 };
  fm::Channel pitch;
  pitch.type = fm::Channel::Type::Audio;
  pitch.audio_parameter = fm::Channel::AudioParameter::Pitch;
  pitch.range = fm::Interval{ 0, 1 };
  pitch.target = fm::Interval{ 220, 440 };
  spec.coordinates.push_back({ "x4", { columns, pitch } });
  spec.world.resolution = 64;
  spec.spreadsheet.cell_size = 160;

  // 2. The plan: every cell's coordinate values and channel values.
  const fm::PlanResult planned = fm::make_plan(spec, fm::hyperfun_coordinates(model.x_dim()));
  if (!planned.ok())
  {
    std::cerr << fm::format_errors(planned.errors);
    return 1;
  }
  const fm::Plan& plan = planned.plan;

  // 3. Each cell: the model cut at its x4 (a 3-D tape), meshed, measured and drawn, with one
  // camera framing the solids of all cells (not the model box).
  fm::PictureKit kit;
  const fm::Framing framing = fm::frame_solids(spec.render, model, {}, plan);
  const frep::imaging::Camera camera = fm::plan_camera(plan, spec.render, 1.0, framing);
  std::vector<frep::imaging::Image> pictures;
  for (const fm::Sample& cell : plan.cells)
  {
    const fm::Section section = fm::make_section(model, {}, plan, cell);
    if (!section.ok())
    {
      std::cerr << cell.label << ": " << section.error << "\n";
      return 1;
    }
    const frep::mesh::MeshTopology t = frep::mesh::analyse_topology(section.surface);
    std::printf("%s: %zu triangles, volume %.3f, genus %lld, pitch %.1f Hz\n",
      cell.label.c_str(),
      t.triangles,
      t.signed_volume,
      (2 - t.euler_characteristic) / 2,
      cell.voices.empty() ? 0.0 : cell.voices[0].pitch);
    pictures.push_back(fm::render_sample(plan,
      section,
      cell,
      camera,
      spec.spreadsheet.cell_size,
      spec.spreadsheet.cell_size,
      spec.render));
  }
  const frep::imaging::Image sheet = fm::compose_spreadsheet(plan, pictures, spec, &kit);
  const std::string error = frep::imaging::write_ppm(sheet, argv[2]);
  if (!error.empty())
  {
    std::cerr << error << "\n";
    return 1;
  }
  std::printf("spreadsheet %dx%d written to %s\n", sheet.width, sheet.height, argv[2]);
  return 0;
}
