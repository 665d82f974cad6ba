// The multimedia mapping: how each geometric coordinate x_i of an n-D FRep object drives one or
// more multimedia coordinates (world space, time, a spreadsheet grid, colour, transparency,
// transformations, sound) through the normalised unit interval. Plain data, no VTK: the JSON
// file (mapping_json.h), the VTK classes (vtkMultimediaMapping, vtkMultimediaMapper) and
// `frepkit map` all use it. Documentation/mapping-file.md describes the file format and meaning.
//
// Every channel maps the same way:
//     x in range [lo, hi]  ->  u = (x - lo) / (hi - lo) in [0, 1]  ->  v = curve(u) in [0, 1]
//                          ->  y = target.lo + v * (target.hi - target.lo)
// and back (inverse) where the curve is monotone.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace frep::mapping
{

struct Interval
{
  double lo = 0.0;
  double hi = 1.0;

  friend bool operator==(const Interval&, const Interval&) = default;
};

/// A map of [0, 1] onto [0, 1].
struct Curve
{
  enum class Kind
  {
    Linear,     ///< v = u
    Power,      ///< v = u^exponent (exponent > 0)
    EaseInOut,  ///< v = u^2 (3 - 2u) (smoothstep)
    Table,      ///< piecewise linear through `table` points (u, v), u from 0 to 1 increasing
    Expression, ///< a HyperFun expression of `t` (the unit value), e.g. "t*t"
  };
  Kind kind = Kind::Linear;
  double exponent = 1.0;
  std::vector<std::array<double, 2>> table;
  std::string expression;

  friend bool operator==(const Curve&, const Curve&) = default;
};

enum class WorldSystem
{
  Cartesian,   ///< axes x, y, z
  Cylindrical, ///< axes r, phi (radians), z: world = (r cos phi, r sin phi, z)
  Spherical,   ///< axes r, theta (polar, radians), phi (azimuth): world = r (sin t cos p, sin t sin p, cos t)
};

/// What a colour, transparency or light channel applies to.
enum class PhotometricTarget
{
  Shape,
  Background,
  Light,
};

/// One multimedia coordinate driven by a geometric coordinate.
struct Channel
{
  enum class Type
  {
    World,          ///< a world axis: the coordinate stays free, the shape extends along it
    Dynamic,        ///< physical time: frames of the animation (several: a path in their space)
    Spreadsheet,    ///< discrete node values on a grid axis of cells
    Fixed,          ///< one value for every frame and cell
    Colour,         ///< a colour map or one RGB channel
    Transparency,   ///< opacity (target: opacity interval, default [1, 0.2])
    Transformation, ///< rotation, scaling or translation of the elementary shape
    Audio,          ///< pitch, loudness or timbre of a voice of the sound track
    Projected,      ///< eliminated: the shape is the union over the range (a projection)
  };
  Type type = Type::Fixed;

  /// The geometric coordinate's interval (default: the coordinate's default interval of the
  /// model, or the range of an earlier channel of the same coordinate).
  std::optional<Interval> range;
  Curve curve;
  /// The multimedia coordinate's interval (meaning and default per type; see mapping-file.md).
  std::optional<Interval> target;

  // World
  int axis = 0; ///< 0, 1, 2: x/y/z (cartesian), r/phi/z (cylindrical), r/theta/phi (spherical)

  // Spreadsheet
  int grid_axis = 0;          ///< 0 columns (left to right), 1 rows (top to bottom), 2 layers
  std::vector<double> values; ///< node values of x (from "step" over the range, or listed)

  // Fixed
  double value = 0.0;

  // Projected: the projection's values are within this of the maximum (FRep/Project)
  double tolerance = 1e-4;

  // Colour
  std::string colormap = "viridis"; ///< a named map, or "red", "green", "blue" (one channel)
  PhotometricTarget applies_to = PhotometricTarget::Shape; ///< also Transparency

  // Transformation
  enum class Transform
  {
    Rotate,    ///< about `vector` through the world box centre, target in degrees
    Scale,     ///< uniform about the world box centre, target = factor
    Translate, ///< along `vector` (normalised), target in world units
  };
  Transform transform = Transform::Rotate;
  std::array<double, 3> vector{ 0.0, 0.0, 1.0 };

  // Audio
  enum class AudioParameter
  {
    Pitch,    ///< Hz (default target [220, 880])
    Loudness, ///< amplitude 0..1 (default target [0, 1])
    Timbre,   ///< brightness 0..1: share of the upper harmonics (default target [0, 1])
  };
  AudioParameter audio_parameter = AudioParameter::Pitch;
  int voice = 0; ///< several voices (tones) are mixed

  friend bool operator==(const Channel&, const Channel&) = default;
};

/// The channels of one geometric coordinate, in file order.
struct CoordinateMapping
{
  std::string name; ///< as the model names it: "x1", "x4", ...
  std::vector<Channel> channels;

  friend bool operator==(const CoordinateMapping&, const CoordinateMapping&) = default;
};

/// A path through the space of the dynamic coordinates (their order in `coordinates`).
struct Path
{
  enum class Interpolation
  {
    Polyline,
    CatmullRom, ///< centripetal Catmull-Rom through every control point
  };
  enum class Timing
  {
    ArcLength, ///< constant speed along the path
    Keys,      ///< control point k is reached at key_times[k] (seconds, increasing)
  };
  std::vector<std::string> coordinates;        ///< dynamic coordinate names, path axis order
  std::vector<std::vector<double>> points;     ///< control points in model units
  Interpolation interpolation = Interpolation::CatmullRom;
  bool closed = false;
  Timing timing = Timing::ArcLength;
  std::vector<double> key_times;

  friend bool operator==(const Path&, const Path&) = default;
};

struct WorldSettings
{
  WorldSystem system = WorldSystem::Cartesian;
  int resolution = 128; ///< samples along the longest world axis of the box
  double iso = 0.0;

  friend bool operator==(const WorldSettings&, const WorldSettings&) = default;
};

/// The animation's ghost (JSON "animation.ghost"): the union of every shape the path passes, the
/// model projected along the path's parameter (FRep/Project/path_family.h), meshed and drawn with
/// the frames' camera as one picture, ghost.png.
struct GhostSettings
{
  int resolution = 64;     ///< samples per axis of its mesh
  double tolerance = 1e-3; ///< the projection's: within it of the union's value (> 0)

  friend bool operator==(const GhostSettings&, const GhostSettings&) = default;
};

struct AnimationSettings
{
  double duration = 10.0; ///< seconds
  double fps = 24.0;
  std::optional<Path> path; ///< required with two or more dynamic coordinates
  std::optional<GhostSettings> ghost; ///< unset: no ghost (it costs a projected mesh)

  friend bool operator==(const AnimationSettings&, const AnimationSettings&) = default;
};

struct SpreadsheetSettings
{
  int cell_size = 256;  ///< pixels of a cell's picture (square)
  double spacing = 0.1; ///< gap between cells, a fraction of the cell
  bool labels = true;   ///< the coordinate values under each cell

  friend bool operator==(const SpreadsheetSettings&, const SpreadsheetSettings&) = default;
};

struct RenderSettings
{
  int width = 1280;
  int height = 720;
  std::array<double, 3> background{ 1.0, 1.0, 1.0 };
  std::array<double, 3> colour{ 0.85, 0.62, 0.38 }; ///< shape colour without a colour channel
  double azimuth = 35.0;  ///< degrees, camera around the world z axis
  double elevation = 25.0;
  bool inset = true; ///< frames: the dynamic-coordinate plane with the path and current point
  /// The world-space box the one camera of every cell and frame frames (xmin, ymin, zmin, xmax,
  /// ymax, zmax); unset = the plan's world box. A box that fits the shapes tightly makes them
  /// larger in the pictures (JSON "view_box").
  std::optional<std::array<double, 6>> view_box;
  /// Where the shape's colour comes from when no world coordinate has a colour channel:
  /// Uniform = `colour` (or the colour channels of non-world coordinates, per sample);
  /// Attributes = the model's s[1..3] as per-vertex RGB (JSON "colour_source": "attributes").
  enum class ColourSource
  {
    Uniform,
    Attributes,
  };
  ColourSource colour_source = ColourSource::Uniform;
  /// How cells and frames are drawn (JSON "method": one name for both, or {"cells": ...,
  /// "frames": ...}): Mesh = each section meshed on the world
  /// grid and rasterised; Raycast = drawn by rays from the function itself (no mesh: no facets,
  /// no detail lost below the grid; needs the cartesian system and linear world curves).
  enum class Method
  {
    Mesh,
    Raycast,
  };
  Method method = Method::Mesh;        ///< cells (the spreadsheet) and the shape alone
  Method frames_method = Method::Mesh; ///< animation frames (JSON "method": {"frames": ...})
  /// What a frame shows around the section (JSON "scene"): Page = the section in the middle of
  /// the background (with the inset if `inset`); Floor = the paper's Fig. 8: the plane of the
  /// two dynamic coordinates as a checkerboard floor (the spreadsheet's squares), the path drawn
  /// on it, the section standing on it at its point with its shadow (either method).
  enum class Scene
  {
    Page,
    Floor,
  };
  Scene scene = Scene::Page;

  friend bool operator==(const RenderSettings&, const RenderSettings&) = default;
};

struct AudioSettings
{
  int sample_rate = 44100;

  friend bool operator==(const AudioSettings&, const AudioSettings&) = default;
};

/// The map of the topology (JSON "topology"): the pieces and genus of every spreadsheet cell's
/// and animation frame's section, meshed at `resolution`, and where they change between two
/// neighbouring cells or two consecutive frames, located by `bisections` halvings of the step
/// (Project/space_time.h's locate_topology_changes); in the manifest, over the spreadsheet
/// (spreadsheet-topology.png) and along the animation (topology.png).
struct TopologySettings
{
  int resolution = 64; ///< samples per axis of each section's mesh
  int bisections = 4;  ///< a change located to 2^-bisections of a step (0 to 20)

  friend bool operator==(const TopologySettings&, const TopologySettings&) = default;
};

struct Spec
{
  int version = 1;
  std::string object;             ///< empty: the model's default object
  std::vector<double> parameters; ///< a[]
  std::vector<CoordinateMapping> coordinates;
  WorldSettings world;
  AnimationSettings animation;
  SpreadsheetSettings spreadsheet;
  RenderSettings render;
  AudioSettings audio;
  std::optional<TopologySettings> topology; ///< unset: no topology map (a mesh per section)

  friend bool operator==(const Spec&, const Spec&) = default;
};

} // namespace frep::mapping
