// frepkit render MODEL --fix x4=0.5,x5=0.5 -o picture.png: one picture of a 3-D cross-section
// drawn directly from the function by rays (Raycast/raycast.h): no mesh, so no facets and no
// detail lost below a grid. The camera frames the solid's outline (or, --frame box, the box)
// from --view azimuth,elevation like the mapping's pictures (raycast::frame_shape); --floor puts a checkerboard floor under the shape, at its lowest point,
// with its shadow.
#pragma once

#include "projection_option.h"
#include "user_inputs.h"

#include <optional>
#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace frepkit
{

struct RenderOptions
{
  UserInputs user; ///< --library, --shape
  ProjectionInput projection; ///< --project, --project-tolerance
  std::string model;
  std::string output;
  std::optional<std::string> object;
  std::vector<double> parameters;
  std::vector<std::string> fix;
  std::vector<std::string> free;
  std::vector<std::string> box;               ///< --box entries (parse_box), default -10..10
  std::string size = "800x600";               ///< WIDTHxHEIGHT or WIDTH,HEIGHT in pixels
  std::vector<double> view{ 35.0, 25.0 };     ///< azimuth, elevation in degrees
  std::vector<double> colour{ 0.85, 0.62, 0.38 };    ///< sRGB 0..1
  std::vector<double> background{ 1.0, 1.0, 1.0 }; ///< sRGB 0..1
  int supersample = 2;
  bool floor = false;
  std::string frame = "solid"; ///< what the camera frames: "solid" (its silhouette) or "box"
  bool shadows = false; ///< the shape's shadows on itself
  int threads = 0;
  bool quiet = false;
};

CLI::App* add_render_command(CLI::App& app, RenderOptions& options);

int run_render(const RenderOptions& options);

} // namespace frepkit
