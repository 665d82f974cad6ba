// The Planner behind make_plan (mapping_plan.cpp), private to FRepKit::MultimediaMapping: the class and the
// helpers its parts share. Its work is in three files, in the order make_plan runs it:
// planner_channels.cpp (every channel resolved, the placing channels checked),
// planner_checks.cpp (world, spreadsheet, animation, renderer), planner_samples.cpp (the cells
// and frames filled, only when nothing is wrong).
#pragma once

#include "Mapping/mapping_plan.h"
#include "Mapping/path.h"
#include "Mapping/unit_map.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace frep::mapping::planning
{

/// "%g" of a value, for messages and labels.
std::string format_value(double v);
/// "a, b, c".
std::string name_list(const std::vector<std::string>& names);
/// The file's name of a channel type ("world", "spreadsheet", ...).
const char* type_name(Channel::Type t);

// One channel with everything make_plan needs resolved.
struct Resolved
{
  const Channel* channel = nullptr;
  int coordinate = -1; ///< model index
  std::string place;   ///< "coordinates.x4[1]"
  Interval range;
  Interval target;
  ChannelMap map;
  bool map_ok = false;
};

class Planner
{
public:
  Planner(const Spec& spec, const ModelCoordinates& model)
    : spec_(spec)
    , model_(model)
  {
  }

  PlanResult run()
  {
    resolve_channels();
    check_placing();
    check_world();
    check_spreadsheet();
    check_animation();
    check_render();
    check_channel_values();
    if (result_.ok())
    {
      fill_projected();
      fill_cells();
      fill_frames();
      fill_still();
    }
    return std::move(result_);
  }

private:
  void error(std::string place, std::string message)
  {
    result_.errors.push_back({ std::move(place), std::move(message) });
  }
  Plan& plan() { return result_.plan; }
  std::size_t n() const { return model_.names.size(); }
  Interval model_interval(std::size_t i) const
  {
    return i < model_.intervals.size() ? model_.intervals[i] : Interval{};
  }
  bool is_world(std::size_t i) const { return find(i, Channel::Type::World) != nullptr; }

  // --- channels: planner_channels.cpp
  void resolve_channels();
  const Resolved* find(std::size_t i, Channel::Type type) const;
  // Each coordinate is free (world) or gets a value per sample: fixed everywhere, or a
  // spreadsheet value in the cells and/or a dynamic value in the frames (one coordinate may
  // drive both the spreadsheet and the animation, as x4 and x5 of Meta5D do).
  void check_placing();
  void check_channel_values();
  /// The plan's projected coordinates (before the samples: base_sample reads them).
  void fill_projected();
  // --- checks of the world, spreadsheet, animation and renderer: planner_checks.cpp
  void check_world();
  void check_spreadsheet();
  // The ray caster's needs (an affine world mapping) and the floor scene's (ray-cast, two
  // dynamic coordinates).
  void check_render();
  void check_animation();
  // --- samples: planner_samples.cpp
  Sample base_sample() const;
  /// The photometric, transformation and audio channels at this sample's values, in file
  /// order (transformations compose in that order: a later one applies after an earlier one).
  void apply_channels(Sample& s) const;
  /// "x4 = 0.25, x5 = 0.5" over the coordinates for which `shown` holds, in model order.
  std::string label(const Sample& s, const std::vector<bool>& shown) const;
  /// The dynamic coordinates' values at frame k (time k / fps), and the path parameter.
  void place_frame(Sample& s, std::size_t k) const;
  void fill_cells();
  void fill_frames();
  /// The shape with nothing varying: the first cell, else the first frame, else the fixed
  /// values with the channels applied (a mapping of world and fixed coordinates only).
  void fill_still();

  const Spec& spec_;
  const ModelCoordinates& model_;
  PlanResult result_;
  std::vector<std::vector<Resolved>> by_coordinate_; ///< per model coordinate, file order
  std::vector<const Resolved*> values_;              ///< the channels applied per sample
  std::array<int, 3> grid_{ -1, -1, -1 };            ///< model coordinate per grid axis
  std::vector<int> dynamic_;                         ///< dynamic coordinates, path axis order
  std::optional<SampledPath> path_;
  std::size_t frame_count_ = 0;
};

} // namespace frep::mapping::planning
