// Direct rendering of an FRep solid, without meshing: every picture sample casts a ray and finds
// the first point where F >= 0, robustly for any FRep (not only distance fields), then shades it
// with the gradient's normal under the same camera and lights as the mesh renderer
// (Imaging/camera.h, Imaging/lighting.h). Plain C++: no VTK, no OpenGL, no display.
//
// How the first root is found (and why it misses nothing the picture can show):
//  1. The picture is cut into tiles of samples. A tile's rays between two depths fill a convex
//     frustum piece; its model-space bounding box (the hull of its eight corners: the world
//     mapping is affine) goes to the interval evaluator. A piece where F < 0 for sure is empty
//     for all its rays at once; a piece where F >= 0 for sure is solid (its rays hit at their
//     entry). Ambiguous pieces split — in depth while they are deeper than wide, else in four on
//     the screen — front to back, so a ray stops at its first hit.
//  2. A piece whose open rays need few march steps in all (TraceOptions::march_budget: an
//     interval evaluation costs about 20 point evaluations) is marched without intervals; a
//     single ray's ambiguous stretch, once no deeper than a few footprints (the width of a
//     sample at that depth), is marched too. March steps are half a footprint, all the piece's
//     steps in one batch of the SIMD evaluator: a part thinner than that is below the picture's
//     resolution. The first sign change is refined by regula falsi (Illinois) to a thousandth
//     of the footprint, every bracketed ray of the batch in lock step (one batch of points per
//     step; each ray's steps are those it would take alone).
//  3. A piece's interval evaluation lets the pieces inside it skip what it dominates (an
//     IntervalFreeze: operands of decided maxima and far R-function operands keep the piece's
//     enclosure, and what only they read is not evaluated): sound, a little looser.
// Every value comes from the engine's exact evaluators; intervals only decide where to look,
// never what F is, so a pruned search finds the same roots as a brute-force march at the same
// step would.
//
// The picture is the same bit for bit for any number of threads: tiles are independent and each
// sample's search depends only on its own ray.
#pragma once

#include "Imaging/camera.h"
#include "Imaging/image.h"
#include "Imaging/lighting.h"

#include "Compiler/tape.h"
#include "Eval/interval.h"
#include "Eval/run_control.h"
#include "Mesh/solid_bounds.h"

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace frep::raycast
{

/// The surface colour at a hit: the model-space point and the tape's outputs there (F, s[1..]).
/// Called from several threads at once: it must not change shared state. Returns linear RGB.
using ColourFunction =
  std::function<std::array<float, 3>(const std::array<double, 3>& model_point,
    std::span<const double> outputs)>;

/// The colour rule of the mesh path for a tape with outputs F, s[1..]: s[1..3] read as floats
/// (as the mesher stores attributes), made RGB by attribute_rgb (Compiler/attribute_rgb.h, the
/// one rule of every output that colours by s[]) and returned linear; a missing s[k] is 0.
ColourFunction attribute_colours();

/// The solid to draw: F >= 0 inside, cut by its model box (the cut faces are drawn as caps, as
/// the mesher closes its surfaces), placed in the world by an affine map.
struct Shape
{
  /// Three inputs (model coordinates, in the order of `box`); outputs F and optionally s[].
  std::shared_ptr<const Tape> tape;
  std::array<Interval, 3> box{};
  /// Model -> world, row-major 3 x 4: w = M m + t with M = columns 0..2, t = column 3. Must be
  /// invertible. Default: identity.
  std::array<double, 12> to_world{ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
  std::array<float, 3> colour{ 0.8F, 0.8F, 0.8F }; ///< linear; when `colour_function` is empty
  ColourFunction colour_function;
  double opacity = 1.0; ///< 0..1: composited over what is behind (back surfaces are not seen)
  /// The solid's bounds inside `box` when the caller has them already (solid_bounds(tape, box),
  /// e.g. to fit a camera first): render and lowest_z then use them instead of searching again.
  /// They must come from this tape and box. Empty: render and lowest_z search themselves.
  std::optional<mesh::SolidBounds> bounds;
};

/// The bounds of the solid {F >= 0} inside `box` (one interval per tape input), as the ray
/// caster clips its rays and frames its shadow map and lowest_z to them, and as cameras frame
/// solids: Mesh/solid_bounds.h's solid_bounds_in to 1/16 of `box` on each axis, then once more
/// over the box found (so to 1/256 of `box`; no margin). Bounded or Empty; throws
/// std::invalid_argument as solid_bounds_in does (no tape, a box of another size).
mesh::SolidBounds solid_bounds(const std::shared_ptr<const Tape>& tape,
  std::span<const Interval> box);

/// A checkerboard floor: the plane z = height of the world, squares of `square` world units
/// starting at `origin`, `columns` x `rows` of them (the rest of the plane is not drawn), with
/// an optional polyline drawn on it (world x, y pairs) and a marked point.
struct Floor
{
  double height = 0.0;
  std::array<double, 2> origin{ 0.0, 0.0 };
  double square = 1.0;
  int columns = 8;
  int rows = 8;
  std::array<float, 3> light{ 0.92F, 0.92F, 0.90F }; ///< linear colours of the two squares
  std::array<float, 3> dark{ 0.35F, 0.37F, 0.42F };
  std::vector<double> path;        ///< x0, y0, x1, y1, ... in world units
  double path_width = 0.1;         ///< world units
  std::array<float, 3> path_colour{ 0.80F, 0.10F, 0.05F };
  bool shadows = true; ///< the shape's shadow from the key light (the first light)
};

/// A floor under the box [lo, hi] (world), a little wider than it: 8 x 8 squares centred
/// under the box at height lo[2] (callers that draw a solid raise lo[2] to its lowest_z first,
/// so the solid stands on the floor). `lo` and `hi` are widened in x and y to the floor, so a
/// camera fitted to them sees all of it.
Floor floor_under(std::array<double, 3>& lo, std::array<double, 3>& hi);

/// The lowest world z of `shape`'s solid as the ray caster draws it (F >= 0, cut by the box),
/// seen by rays cast straight up: a `pixels` x `pixels` orthographic picture over the solid's
/// bounds, then one as large over the 4 x 4 pixels around the lowest hit. Its error is about
/// the slope there times 1 / (8 pixels) of the solid's width (none on a flat or a round
/// bottom's lowest ray); a part thinner than a ray's spacing can be missed, as in any picture.
/// Empty when no ray meets the solid. `threads`: 0 = all cores.
std::optional<double> lowest_z(const Shape& shape, int pixels = 128, int threads = 1);

/// What a camera looking along `view.forward` must see to see the whole of `shape`'s solid: the
/// first hit of each ray of an orthographic picture of `pixels` x `pixels` rays along
/// view.forward (view.up up) covering the solid's bounds (solid_bounds). A camera looking
/// along that direction, perspective or not, that sees these points sees the solid: at each
/// place of the picture the nearest point limits it. To within `spacing`, the distance between
/// neighbouring rays (widen by it); a part thinner than that may be missed, as in any picture.
struct Silhouette
{
  std::vector<imaging::Vec3> points; ///< world points; empty when no ray meets the solid
  double spacing = 0.0;             ///< world units between neighbouring rays
};
Silhouette silhouette(const Shape& shape,
  const imaging::CameraFrame& view,
  int pixels = 48,
  int threads = 1);

struct Style
{
  /// The mesh renderer's lights, ambient, specular, shininess and supersample (per axis, 1..4),
  /// so that ray-cast and meshed pictures match. Its `threads` is the mesh renderer's: the ray
  /// caster's threads come from render()'s RunControl.
  imaging::RenderStyle render;
  /// The shape casts shadows on itself (one more ray per lit sample towards the key light).
  bool self_shadows = false;
  double shadow_factor = 0.35; ///< light left in a shadow, 0..1
};

struct Statistics
{
  std::size_t rays = 0;                 ///< primary rays (one per pixel, more at edges)
  std::size_t edge_pixels = 0;          ///< pixels that got supersample^2 rays
  std::size_t rays_in_box = 0;          ///< ... that meet the model box
  std::size_t hits = 0;                 ///< ... that meet the solid
  std::size_t interval_evaluations = 0; ///< frustum pieces and ray stretches
  std::size_t point_evaluations = 0;    ///< march steps and bisection
  std::size_t shadow_rays = 0;
  double shadow_seconds = 0.0; ///< of which: the key light's shadow map
  double edge_seconds = 0.0;   ///< ... the supersampled edge pixels
  double seconds = 0.0;
};

struct Result
{
  std::string error; ///< non-empty: bad input, nothing drawn
  Statistics statistics;
  bool ok() const { return error.empty(); }
};

/// Draws `shape` (and the floor, if given) over `target` (its size is the picture's size):
/// pixels neither covers keep the target's colour, edges blend with it. `depth`, when given,
/// receives per output pixel the world distance from the eye along the view direction of the
/// nearest sample drawn (infinity where nothing was). `run` (Eval/run_control.h): the threads
/// or pool to trace on (default: all cores); `cancel` is polled per tile from any thread;
/// `progress` is called on the calling thread only (never from the pool's other threads, so a
/// VTK filter may pass UpdateProgress), with rising fractions in [0, 1] as tiles finish (steps
/// of at least 0.01), and with 1 when the picture is complete. Either stops the picture (it is
/// then incomplete and the result says "cancelled").
Result render(imaging::Image& target,
  const imaging::Camera& camera,
  const Shape& shape,
  const Floor* floor = nullptr,
  const Style& style = {},
  std::vector<float>* depth = nullptr,
  const RunControl& run = {});

} // namespace frep::raycast
