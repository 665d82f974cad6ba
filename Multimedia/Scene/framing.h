// What the mapping's pictures frame: the solids the cells and frames show, not the plan's model
// box. A mapping without ranges samples -10..10 on each world axis; a unit-size shape in it was a
// few pixels wide. Each sample's solid is bounded inside the model box by the ray caster's search
// (raycast::solid_bounds: the engine's solid_bounds_in, to 1/256 of the box) and seen from the
// camera's direction (raycast::silhouette: rays along the view), carried to world space and moved
// by the sample's transform; the union over every cell and frame is what the one camera fits,
// so shapes stay comparable from cell to cell and frame to frame. The model box keeps its
// meaning for meshing and ray casting: only the camera (and, in the floor scene, the board's
// size and the shape's anchor) change. A render.view_box in the mapping wins over all this.
#pragma once

#include "Mapping/mapping_plan.h"
#include "Mapping/mapping_spec.h"

#include "Imaging/camera.h"

#include "Compiler/model.h"
#include "Eval/run_control.h"
#include "Mesh/solid_bounds.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace frep::mapping
{

/// What the one camera of a plan's cells and frames frames (frame_solids). Empty: no sample
/// has a solid, or the settings have a view_box of their own.
struct Framing
{
  /// The world box holding every sample's solid: the floor scene's shape box and the view of
  /// 2-D sections.
  std::optional<std::array<Interval, 3>> box;
  /// Eight world points whose outline, seen from the settings' azimuth and elevation, holds the
  /// outline of every sample's solid: the corners of the union of their extents across and
  /// along the view (of the silhouette's points when the plan can be ray-cast, widened by the
  /// rays' spacing; else of the solid's world box). What plan_camera fits (imaging::fit_points):
  /// a round shape fills the picture where its box's corners seen obliquely would leave it
  /// about half as wide.
  std::vector<imaging::Vec3> outline;
  /// Each frame's solid's world box (plan.frames' order; empty: no solid): where the floor
  /// scene's camera must see a shape standing on the board.
  std::vector<std::optional<std::array<Interval, 3>>> frames;
  /// The bounds of each framed 3-D section's solid in the plan's model box (raycast::solid_bounds
  /// of its tape), by the bits of the sample's coordinate values (equal values, equal tape; bits,
  /// because a world coordinate's value is NaN): ray casting a framed sample uses them instead
  /// of searching again (solid_of; draw_sample does).
  std::map<std::vector<std::uint64_t>, mesh::SolidBounds> solids;
  std::vector<double> parameters; ///< the a[] values the solids were bounded with
  std::array<Interval, 3> model_box{}; ///< the plan's model box they were bounded in
  /// frame_solids was stopped (cancel, or progress returning false): nothing is framed.
  bool cancelled = false;
  bool empty() const { return !box; }
  /// `sample`'s solid bounds if this framing holds them for this plan's model box and these
  /// parameters, else null.
  const mesh::SolidBounds* solid_of(const Plan& plan,
    const Sample& sample,
    const std::vector<double>& parameters) const;
};

/// The world box holding `sample`'s solid: its section's tape (section_specialisation) bounded
/// inside the plan's model box (raycast::solid_bounds), mapped to world space (WorldMapping:
/// the world system and the world channels) and moved by the sample's transform (the hull of
/// the moved corners). A 2-D section's box is flat in z. Empty when no part of the model box may
/// hold the solid, or when the section cannot be made (its picture reports why).
std::optional<std::array<Interval, 3>> solid_world_box(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& sample);

/// The framing of every cell, every frame and the still — the same whatever a run draws, so the
/// spreadsheet, the shape alone and the frames share one framing, and frames kept from an
/// earlier run match new ones — seen from `settings`' azimuth and elevation. Empty when the
/// settings have a view_box (the user's box wins) or no sample has a solid (the plan's world
/// box). `run` (Eval/run_control.h): the samples are spread over its pool or threads (default
/// all cores); `cancel` is polled before each sample; `progress` is called on the calling thread
/// with the fraction of samples seen. Stopped by either: an empty framing with `cancelled` set.
Framing frame_solids(const RenderSettings& settings,
  const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const RunControl& run = {});

/// The box the pictures show: the settings' view_box, else the framing's box, else the plan's
/// world box.
std::array<Interval, 3> shown_box(const Plan& plan,
  const RenderSettings& settings,
  const Framing& framing = {});

} // namespace frep::mapping
