// A cell's or frame's picture drawn by rays (Raycast/raycast.h) instead of meshing its section:
// the same specialisation (section_specialisation), world mapping, transform, colours, opacity
// and light as make_section + render_sample, so the two methods draw the same scene. The ray
// caster needs an affine world mapping (the cartesian system with linear world curves); for
// anything else `raycast_supported` says why and callers mesh instead.
#pragma once

#include "Mapping/mapping_plan.h"

#include "Raycast/raycast.h"
#include "Imaging/camera.h"
#include "Imaging/image.h"

#include "Compiler/model.h"

#include <functional>
#include <string>
#include <vector>

namespace frep::mapping
{

/// Whether the plan's pictures can be ray-cast; if not, `why` (when given) says why.
bool raycast_supported(const Plan& plan, std::string* why = nullptr);

/// The model -> world map of `sample` (world system, world channels, then the sample's
/// transform) as the ray caster's row-major 3 x 4 matrix. Requires raycast_supported(plan).
std::array<double, 12> raycast_world_map(const Plan& plan, const Sample& sample);

/// RunControl: threads (here 1 by default: the mapping draws many pictures side by side) or a
/// pool, cancel polled per tile (true stops), progress on the calling thread.
struct RaycastOptions : RunControl
{
  RaycastOptions() { threads = 1; }
  const raycast::Floor* floor = nullptr;
  bool self_shadows = false;
  /// The section's solid bounds when the caller has them (Framing::solid_of: the same tape and
  /// model box), so the ray caster does not search them again. Default none.
  const mesh::SolidBounds* bounds = nullptr;
};

struct RaycastPicture
{
  imaging::Image image;
  raycast::Statistics statistics;
  std::string error; ///< non-empty: nothing drawn ("cancelled" when cancelled)
  bool ok() const { return error.empty(); }
};

/// The sample's section drawn by rays over its background, with the render settings' colour
/// source (vertex colouring becomes per-hit colouring) and the sample's colour, opacity and light.
RaycastPicture raycast_sample(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& sample,
  const imaging::Camera& camera,
  int width,
  int height,
  const RaycastOptions& options = {});

} // namespace frep::mapping
