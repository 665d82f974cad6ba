// Headless software rendering of triangle meshes: z-buffered rasterisation with
// perspective-correct interpolation, per-pixel Blinn-Phong shading under a small light kit,
// two-sided lighting and supersampling anti-aliasing. No display, no OpenGL, no VTK: the CLI
// renders spreadsheets and animation frames on machines without X.
//
// How a picture is made (and why):
//  1. Setup: points are transformed to camera space, triangles clipped against the near plane
//     (and a wide guard band, so fixed-point coordinates cannot overflow), projected and snapped
//     to 1/256 pixel. Fixed-point edge functions with a top-left fill rule give watertight
//     meshes: no cracks between triangles, no pixel drawn twice along a shared edge.
//  2. Visibility: each horizontal band of the supersampled picture keeps, per sample, the
//     nearest depth and which triangle it belongs to. Bands are independent and see their
//     triangles in submission order (ties keep the earlier triangle), so the picture is the
//     same bit for bit whatever the number of threads.
//  3. Shading (deferred): each visible sample is shaded once, from its triangle's vertices, so
//     the cost does not grow with overdraw; then every pixel's samples are box-averaged.
// Opaque meshes share one depth buffer. A mesh with opacity < 1 gets its own layer: its nearest
// surface in front of the opaque geometry, shaded and composited over it with alpha = opacity
// (back surfaces of a transparent mesh are not seen through its front; layers are composited
// far to near by their bounding spheres' centres). Simple, and correct for one transparent shell
// over opaque shapes, the common case.
#pragma once

#include "Imaging/camera.h"
#include "Imaging/image.h"
#include "Imaging/lighting.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace frep::render
{

/// One triangle mesh to draw. The spans are only read during `Renderer::add` / `render_mesh`.
struct MeshInput
{
  std::span<const double> points;           ///< x, y, z per point
  std::span<const std::uint32_t> triangles; ///< 3 point ids per triangle (any winding)
  /// Optional: 3 per point, any length (normalised here). Empty: smooth normals from the
  /// area-weighted normals of the triangles around each point.
  std::span<const float> normals;
  /// Optional: linear r, g, b (0..1) per point. Empty: `colour` everywhere.
  std::span<const float> colours;
  std::array<float, 3> colour{ 0.8F, 0.8F, 0.8F }; ///< linear (see image.h)
  double opacity = 1.0;                            ///< 0..1; < 1 draws in its own layer
  /// Optional 4 x 4 row-major world transform: p' = M (x, y, z, 1). Normals follow by the
  /// inverse transpose. The bottom row should be 0 0 0 1 (no projective transforms).
  std::optional<std::array<double, 16>> transform;
};

/// What an `add` or `render_mesh` did. `error` non-empty: the input was malformed (array sizes)
/// and nothing of that mesh was drawn. Triangles with bad ids or non-finite points are skipped
/// and counted, never an error.
struct RenderReport
{
  std::string error;
  std::size_t triangles = 0;         ///< submitted
  std::size_t triangles_skipped = 0; ///< bad point ids, NaN/infinite coordinates, degenerate
  std::size_t triangles_clipped = 0; ///< crossing the near plane or the guard band
  bool ok() const { return error.empty(); }
};

/// Several meshes into one picture (shared depth buffer). Not copyable; not thread-safe itself
/// (it uses its own threads). Memory: 8 bytes per sample (width x height x supersample^2),
/// plus as much again per transparent mesh while resolving; sizes are capped at 32768 samples
/// per side.
class Renderer
{
public:
  /// A picture of width x height output pixels (the samples are `supersample` times finer).
  Renderer(int width,
    int height,
    const imaging::Camera& camera,
    const imaging::RenderStyle& style = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Rasterise one mesh (opaque meshes at once; transparent ones are kept for `resolve`).
  RenderReport add(const MeshInput& mesh);

  /// Shade, anti-alias and composite the picture over `target` (which must be width x height:
  /// otherwise an error and nothing drawn). Pixels no mesh covers keep the target's colour;
  /// edges blend with it. Each call composites again (call it on fresh targets, e.g. once per
  /// background, to get the same picture more than once).
  std::string resolve(imaging::Image& target) const;

private:
  struct State;
  std::unique_ptr<State> state_;
};

/// One mesh over `target` (its size is the picture's size): Renderer + add + resolve.
RenderReport render_mesh(imaging::Image& target,
  const imaging::Camera& camera,
  const MeshInput& mesh,
  const imaging::RenderStyle& style = {});

} // namespace frep::render
