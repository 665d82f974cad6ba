// A mapping resolved against a model: the world box and axes, the spreadsheet cells and the
// animation frames, each with the values of the non-world coordinates and the channel values
// (colour, opacity, transform, audio) that hold for it. Everything the mapper, the renderer and
// the audio synthesis need, computed once; no VTK, no evaluation of the model.
#pragma once

#include "Mapping/mapping_spec.h"

#include "Project/path_pieces.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace frep::mapping
{

/// What the model offers the mapping: its coordinates' names and default intervals.
struct ModelCoordinates
{
  std::vector<std::string> names;  ///< "x1".."xn" (or the model's own names)
  std::vector<Interval> intervals; ///< default interval per coordinate
};

/// The sound of one voice at one instant.
struct Voice
{
  double pitch = 440.0;  ///< Hz
  double loudness = 0.5; ///< amplitude 0..1
  double timbre = 0.0;   ///< 0 pure tone .. 1 bright
};

/// One spreadsheet cell or animation frame.
struct Sample
{
  /// Per model coordinate: its value here; NaN for the world (free) coordinates.
  std::vector<double> values;
  std::array<int, 3> cell{ -1, -1, -1 }; ///< spreadsheet grid index (column, row, layer)
  double time = 0.0;                     ///< seconds (frames)
  double path_parameter = 0.0;           ///< 0..1 along the path (frames)
  std::vector<double> path_point;        ///< the dynamic coordinates' values (frames)

  /// Uniform shape colour (RGB 0..1) for this sample: the render default, or set by a colour
  /// channel of a dynamic/spreadsheet/fixed coordinate.
  std::array<double, 3> colour{ 0.85, 0.62, 0.38 };
  double opacity = 1.0;
  std::array<double, 3> background{ 1.0, 1.0, 1.0 };
  double light_intensity = 1.0;
  /// World transform of the elementary shape, row-major 4x4 (identity by default).
  std::array<double, 16> transform{ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  std::vector<Voice> voices; ///< one per voice index used by audio channels (empty: silent)

  /// "x4 = 0.25, x5 = 0.5": the spreadsheet/dynamic coordinates' values, for labels.
  std::string label;
};

/// Per-vertex colour from a world coordinate, or from the model's s[] attributes.
struct VertexColouring
{
  enum class Source
  {
    None,
    WorldCoordinate, ///< colour map over the model coordinate `coordinate` (a world one)
    Attributes,      ///< s[1..3] as RGB in 0..1 (the model's own colours)
  };
  Source source = Source::None;
  int coordinate = -1; ///< model coordinate index (Source::WorldCoordinate)
  Interval range;      ///< that coordinate's range
  Curve curve;
  std::string colormap; ///< named map or "red"/"green"/"blue"
};

/// A coordinate eliminated by projection (channel type "projected"): the sections are cut from
/// the model projected over `range` (Scene/section_model.h), inside where some value of the
/// coordinate in the range puts the point inside.
struct ProjectedCoordinate
{
  int coordinate = -1; ///< model index
  Interval range;
  double tolerance = 1e-4; ///< the projection's values are within this of the maximum
};

struct Plan
{
  /// World axis k (0..2) is driven by model coordinate world_coordinates[k]; -1 when only two
  /// coordinates are world (a 2-D elementary shape: image or contour).
  std::array<int, 3> world_coordinates{ -1, -1, -1 };
  WorldSystem system = WorldSystem::Cartesian;
  /// The box sampled in model units, per world axis (the world channels' ranges).
  std::array<Interval, 3> model_box{};
  /// Per world axis: the world channel's curve and target (target default = its range), i.e.
  /// model value x -> axis value target.lo + curve(u) * (target.hi - target.lo); for the
  /// cylindrical and spherical systems the axis value is r / phi / z or r / theta / phi.
  std::array<Curve, 3> world_curves{};
  std::array<Interval, 3> world_targets{};
  /// The box in world space that holds the elementary shape (after the world system and the
  /// world channels' targets), used for one camera for every cell and frame.
  std::array<Interval, 3> world_box{};
  std::array<int, 3> samples{ 0, 0, 0 }; ///< grid samples per world axis (resolution)

  std::array<int, 3> grid_shape{ 0, 0, 0 };  ///< spreadsheet columns, rows, layers (0 = none)
  std::vector<Sample> cells;                 ///< column fastest, then row, then layer
  std::vector<std::string> grid_coordinates; ///< the coordinate name on each grid axis

  std::vector<Sample> frames; ///< animation frames, frame k at time k / fps
  std::vector<std::string> dynamic_coordinates;
  std::vector<std::vector<double>> path_polyline; ///< the path, finely sampled (for the inset)
  /// The path as polynomial pieces (SampledPath::pieces) through the model coordinates
  /// path_model_coordinates (0-based, in the path's order): the ghost's path. Empty without a path.
  std::vector<project::PathPiece> path_pieces;
  std::vector<int> path_model_coordinates;
  std::array<Interval, 2> path_plane{};           ///< the dynamic plane's ranges (inset axes)

  /// The elementary shape when nothing varies (a mapping of world and fixed coordinates
  /// only), else the first cell or frame: `frepkit map` draws it as shape.png.
  Sample still;

  /// The coordinates eliminated by projection, in model order (empty: none). Their samples'
  /// values are their ranges' middles, read by nothing once the model is projected.
  std::vector<ProjectedCoordinate> projected;

  VertexColouring vertex_colouring;
  int voice_count = 0; ///< 0: no audio channel, no sound track
};

/// An error found while resolving: where (a JSON-path-like place such as
/// "coordinates.x4[1].range") and what.
struct PlanError
{
  std::string place;
  std::string message;

  friend bool operator==(const PlanError&, const PlanError&) = default;
};

/// "place: message" (or the message alone when the place is empty), one error per line.
std::string format_errors(const std::vector<PlanError>& errors);

struct PlanResult
{
  Plan plan;
  std::vector<PlanError> errors; ///< empty = success
  bool ok() const { return errors.empty(); }
};

/// Whether the plan's model -> world mapping is affine (three world coordinates, the cartesian
/// system, linear world curves): what the ray caster needs. If not, `why` says why (a phrase
/// that follows "the ray caster").
bool world_is_affine(const Plan& plan, std::string* why = nullptr);

/// The bounding box in world space of the region a box of axis values maps onto in the
/// cylindrical (r, phi, z) or spherical (r, theta, phi) system, angles in radians: the extremes
/// lie at the ends and at the multiples of pi/2 of each angle's interval.
std::array<Interval, 3> curvilinear_box(WorldSystem system, const std::array<Interval, 3>& axes);

/// Resolves `spec` against the model's coordinates: every coordinate must be mapped (world,
/// dynamic, spreadsheet, fixed or projected), world axes distinct and 2 or 3 of them, ranges of non-zero
/// width, frames >= 1, a path with >= 2 points over exactly the dynamic coordinates, ...
/// All problems are reported, not only the first.
PlanResult make_plan(const Spec& spec, const ModelCoordinates& model);

/// The coordinates of a HyperFun model with `dimension` coordinates: "x1".."xn", each over hfp's
/// default box -10..10 (what a channel without a range of its own maps).
ModelCoordinates hyperfun_coordinates(int dimension);

} // namespace frep::mapping
