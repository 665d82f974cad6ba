// The elementary shape of one spreadsheet cell or animation frame: the model cut at the
// sample's values of the non-world coordinates (the engine's specialisation: a 3-D tape), its
// surface meshed over the plan's model box (interval-culled, watertight, oriented), mapped into
// world space (world system and world channels' targets), coloured per vertex when the mapping
// asks for it, and moved by the sample's transform. Shared by vtkMultimediaMapper and
// `frepkit map`, so both produce the same geometry.
#pragma once

#include "Mapping/mapping_plan.h"
#include "Mapping/unit_map.h"

#include "Compiler/model.h"
#include "Eval/run_control.h"
#include "Mesh/surface.h"

#include <memory>
#include <string>
#include <vector>

namespace frep::mapping
{

/// The run control (threads or a shared pool, progress that may stop, cancel) goes to the mesher
/// as it is: one settings struct for long work (Eval/run_control.h).
struct SectionOptions : RunControl
{
  bool normals = true;
  /// Grid samples per world axis; {0, 0, 0} = the plan's.
  std::array<int, 3> samples{ 0, 0, 0 };
};

struct Section
{
  /// World-space triangles (3-D) or segments in z = 0 (2-D), outward normals, s[] attributes.
  mesh::Surface surface;
  /// RGB in 0..1 per point when the plan colours vertices; empty = the sample's uniform colour.
  std::vector<float> colours;
  mesh::ExtractStatistics statistics;
  std::string error;
  bool cancelled = false;
  bool ok() const { return error.empty() && !cancelled; }
};

/// The specialisation of `model` for `sample`: its non-world values fixed, the world
/// coordinates free in world-axis order (the tape's inputs are x, y[, z] of the model box).
Specialisation section_specialisation(const Plan& plan,
  const Sample& sample,
  const std::vector<double>& parameters);

/// Meshes the section of `model` for `sample` (see the file comment). Never throws for bad
/// input: see Section::error.
Section make_section(const Model& model,
  const std::vector<double>& parameters,
  const Plan& plan,
  const Sample& sample,
  const SectionOptions& options = {});

/// Model-box points (world-axis order) -> world space, per the plan's system and the world
/// channels' curves and targets. Built once per plan (curves may be compiled expressions).
class WorldMapping
{
public:
  /// Null with `error` set when a world curve does not compile.
  static std::unique_ptr<WorldMapping> make(const Plan& plan, std::string& error);
  std::array<double, 3> to_world(const std::array<double, 3>& model_point) const;
  /// d(world)/d(model) at the point, row-major, by central differences.
  std::array<double, 9> jacobian(const std::array<double, 3>& model_point) const;
  /// The world box holding the image of `model_box` (world-axis order): each axis's range
  /// through its channel (the ends for a monotone curve, else 1025 points), then the
  /// cylindrical or spherical system's extremes (curvilinear_box). Flat in z for 2-D sections.
  std::array<Interval, 3> world_box(const std::array<Interval, 3>& model_box) const;

private:
  WorldMapping() = default;
  int axes_ = 3;
  WorldSystem system_ = WorldSystem::Cartesian;
  std::array<Interval, 3> box_{};
  std::array<ChannelMap, 3> maps_{};
};

} // namespace frep::mapping
