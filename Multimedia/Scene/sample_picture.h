// One cell's or frame's picture, by either method the render settings offer: the section meshed
// (make_section) and rasterised (render_sample), or drawn by rays (raycast_sample); on the floor
// scene's board, the solid stood on its lowest point first. The one way a sample becomes a
// picture: `frepkit map` (Multimedia/Production), FRepStudio's spreadsheet cells and the tests
// all call it, so the same sample gives the same picture everywhere.
#pragma once

#include "Compiler/model.h"
#include "Eval/run_control.h"
#include "Imaging/camera.h"
#include "Imaging/image.h"
#include "Mapping/mapping_plan.h"
#include "Mapping/mapping_spec.h"
#include "Raycast/raycast.h"
#include "Scene/framing.h"

#include <cstddef>
#include <string>
#include <vector>

namespace frep::mapping
{

/// RunControl: the pool or threads every part of the work runs on (meshing, rasterising, rays;
/// here 1 thread by default: the mapping draws many pictures side by side), cancel polled
/// between blocks and tiles (true stops). Progress is not reported.
struct DrawOptions : RunControl
{
  DrawOptions() { threads = 1; }
  /// The floor scene's board (floor_scene.h): drawn with the sample, which stands on it.
  const raycast::Floor* floor = nullptr;
  /// Grid samples per world axis when meshing; {0, 0, 0} = the plan's.
  std::array<int, 3> samples{ 0, 0, 0 };
};

struct SamplePicture
{
  imaging::Image image;
  std::size_t triangles = 0;      ///< of the meshed section (0 when ray-cast)
  std::size_t failed_samples = 0; ///< grid samples whose evaluation failed (meshing)
  double mesh_seconds = 0.0;      ///< meshing (0 when ray-cast)
  double render_seconds = 0.0;    ///< rasterising or ray casting
  std::string error;              ///< non-empty: nothing drawn
  bool cancelled = false;         ///< `cancel` stopped the work: nothing drawn
  bool ok() const { return error.empty() && !cancelled; }
};

/// `sample`'s picture, width x height, seen by `camera` (plan_camera or frame_camera), drawn by
/// `method` with `settings`' colours and light and the framing's view of 2-D sections. Never
/// throws for bad input: see SamplePicture::error.
SamplePicture draw_sample(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& sample,
  const imaging::Camera& camera,
  int width,
  int height,
  const RenderSettings& settings,
  RenderSettings::Method method,
  const DrawOptions& options = {},
  const Framing& framing = {});

} // namespace frep::mapping
