// The camera of the headless renderer: where the eye is, what it looks at, and how the view is
// projected onto the picture. `fit_box` frames a box (its bounding sphere or its corners),
// `fit_points` the outline of points (a solid seen from the camera's direction): one camera for
// a whole spreadsheet or animation, so all cells and frames are framed alike and shapes stay
// comparable.
#pragma once

#include <array>
#include <span>

namespace frep::imaging
{

using Vec3 = std::array<double, 3>;

struct Camera
{
  Vec3 position{ 0.0, -5.0, 0.0 };
  Vec3 focal_point{ 0.0, 0.0, 0.0 };
  /// Need not be orthogonal to the view direction (it is made so); must not be parallel to it.
  Vec3 view_up{ 0.0, 0.0, 1.0 };
  /// Perspective: the full vertical field of view, degrees (0 < angle < 180).
  double view_angle_deg = 30.0;
  /// Orthographic (parallel) projection instead of perspective ...
  bool orthographic = false;
  /// ... showing parallel_scale world units from the view centre to the top edge.
  double parallel_scale = 1.0;
  /// Geometry nearer than this distance along the view direction is clipped away (> 0).
  double near_distance = 0.01;
};

/// The camera's orthonormal frame: right, up and forward (from the eye towards the focal point).
/// A degenerate camera (eye on the focal point, up parallel to the view) gets a usable frame.
struct CameraFrame
{
  Vec3 right;
  Vec3 up;
  Vec3 forward;
};
CameraFrame camera_frame(const Camera& camera);

struct FitOptions
{
  double view_angle_deg = 30.0;
  bool orthographic = false;
  /// The bounding sphere's diameter as a fraction of the picture's shorter side.
  double fill = 0.9;
  /// Fit the box's corners as seen from the view direction instead of its bounding sphere: the
  /// sphere about their farthest distance from the view axis, the camera moved back by their
  /// largest depth towards it (so no corner leaves the picture). Tighter for boxes fitted to a
  /// solid, where the box's sphere leaves a round shape less than half the picture.
  bool fit_corners = false;
  /// fit_points only: this fraction of the picture's height (0..0.5) is kept free at the
  /// bottom (a caption's band); the fill applies to the rest.
  double free_bottom = 0.0;
};

/// A camera looking at the centre of the box [lo, hi] from the direction (azimuth, elevation),
/// far enough that the box's bounding sphere spans `fill` of the shorter side of a picture of
/// width / height = aspect. Directions, with z up: elevation is the angle above the xy plane;
/// azimuth turns counter-clockwise about +z (seen from above) starting from -y, so azimuth 0,
/// elevation 0 looks along +y with x to the right; azimuth 90 looks along -x with y to the
/// right. View up stays continuous through elevation +-90 (looking straight down or up).
Camera fit_box(const Vec3& lo,
  const Vec3& hi,
  double aspect,
  double azimuth_deg,
  double elevation_deg,
  const FitOptions& options = {});

/// The camera's frame (right, up, forward) for the direction (azimuth, elevation), as fit_box
/// orients its cameras.
CameraFrame view_frame(double azimuth_deg, double elevation_deg);

/// The nearest camera looking from (azimuth, elevation) (fit_box's directions and view up) that
/// sees every point within `fill` of the picture's half width and of its half height (width /
/// height = aspect): the points' own outline frames the picture, not a sphere or a box around
/// them, so a round solid given by points on it fills the picture where its box's corners seen
/// obliquely would leave it half as wide. Perspective (the view axis shifted so that the points
/// nearer the eye and those farther away both reach the fill, on each axis of the picture) or
/// orthographic (centred on the points' extent), by `options` (fit_corners does not apply). The
/// focal point is on the view axis at the middle of the points' depths. `margin` (world units)
/// widens every point across the view (e.g. by the spacing of the rays that found them). Non-finite
/// points are skipped; with none, fit_box's unit sphere at the origin; with one place only,
/// fit_box's unit sphere there.
Camera fit_points(std::span<const Vec3> points,
  double aspect,
  double azimuth_deg,
  double elevation_deg,
  const FitOptions& options = {},
  double margin = 0.0);

/// fit_points for the view direction of `direction` (its frame: position towards focal point,
/// view up) instead of an azimuth and elevation, for views the user turns (FRepStudio's section
/// view). The projection is `options`' (view angle, orthographic); the camera's own distance and
/// focal point do not matter. Points all at one place: the same view moved to look at it; no
/// finite point: `direction` with `options`' projection.
Camera fit_points(std::span<const Vec3> points,
  double aspect,
  const Camera& direction,
  const FitOptions& options = {},
  double margin = 0.0);

} // namespace frep::imaging
