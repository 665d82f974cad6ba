// Internal: the first root of F along every ray of a tile (see raycast.h, "How the first root is
// found"). One tracer per thread: it owns its region walker (the simplified tapes of the pieces
// it is in).
#pragma once

#include "Raycast/raycast.h"
#include "Raycast/detail/view_rays.h"

#include "Eval/region_walker.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace frep::raycast::detail
{

enum class HitKind : std::uint8_t
{
  None,
  Surface, ///< F changes sign along the ray
  Cap      ///< the ray enters the box inside the solid: the box's face
};

struct Hit
{
  double lambda = std::numeric_limits<double>::infinity(); ///< depth (ViewRays)
  HitKind kind = HitKind::None;
  std::uint8_t face = 0; ///< Cap: the box face (view_rays.h, entry_face)
};

struct TraceOptions
{
  /// March step along a ray, in footprints (the world width of a sample at that depth).
  double step = 0.5;
  /// Refinement stops when the root is bracketed to this many footprints.
  double tolerance = 1e-3;
  /// A single ray's ambiguous stretch is marched once it is at most this many footprints deep
  /// (deeper: split in two, each half checked by intervals first).
  double leaf_depth = 2.0;
  /// A piece whose open rays need at most this many march steps in all is marched without
  /// an interval evaluation (which costs about as much as 20 point evaluations).
  double march_budget = 24.0;
  /// Simplify the tape per piece of at least this many samples (0: never).
  int simplify_area = 16;
  /// Depth below which nothing is searched (perspective: the near plane).
  double from = 0.0;
};

class PieceTracer
{
public:
  /// Rays search `clip` (a box around the solid inside the model box `box`, or `box` itself);
  /// a ray entering `clip` inside the solid through a face of `box` hits a cap.
  PieceTracer(std::shared_ptr<const Tape> tape,
    const std::array<Interval, 3>& box,
    const std::array<Interval, 3>& clip,
    const ViewRays& view,
    const TraceOptions& options);

  /// The hits of samples [x0, x1) x [y0, y1), row-major into `hits` ((x1-x0) * (y1-y0)).
  /// `active`, when given (same layout), says which samples to trace; the others get no hit
  /// and cost nothing, while the traced ones share the tile's pieces.
  void trace_tile(int x0, int y0, int x1, int y1, std::span<Hit> hits,
    const unsigned char* active = nullptr);

  /// Counters since construction (rays, rays_in_box, hits, interval and point evaluations).
  const Statistics& statistics() const { return stats_; }

private:
  struct Ray
  {
    Vec3 o{}, d{};
    double in = 1.0, out = 0.0;                                    ///< inside the box
    double outside = -std::numeric_limits<double>::infinity(); ///< a depth known outside
    bool done = true;
  };

  /// `region`: the piece's place in the walk (its tape and what the pieces around it let it skip).
  void piece(
    int x0, int y0, int x1, int y1, double l0, double l1, const RegionWalker::Region& region);
  double march_steps(int x0, int y0, int x1, int y1, double l0, double l1) const;
  void solid(
    int x0, int y0, int x1, int y1, double l0, double l1, const RegionWalker::Region& region);
  /// Marches the rays `which` (indices into the tile) over [l0, l1], all steps in one batch.
  void march(std::span<const std::size_t> which, double l0, double l1,
    const RegionWalker::Region& region);
  /// The point of depth lambda of the ray, clamped into the box (where the tapes are exact),
  /// appended to xs_, ys_, zs_.
  void push_point(const Ray& ray, double lambda);
  /// F at the points xs_, ys_, zs_ into values_ (the region's tape).
  void evaluate_points(const RegionWalker::Region& region);
  /// Brackets the root of ray `ray` between a depth outside and one inside; a value not yet
  /// known is NaN with its `known` flag false. refine_brackets() finds every bracketed root.
  void bracket(std::size_t ray, double outside, double f_out, bool out_known, double inside,
    double f_in, bool in_known);
  /// Refines every pending bracket in lock step (one batch of points per step for all of them)
  /// and sets the rays' surface hits.
  void refine_brackets(const RegionWalker::Region& region);
  void set_hit(Ray& ray, Hit& hit, double lambda, HitKind kind);

  std::array<Interval, 3> model_box_;
  std::array<Interval, 3> box_; // where rays search
  const ViewRays& view_;
  TraceOptions options_;
  RegionWalker walker_; // the tapes simplified per piece, the freezes, the point evaluation
  struct March
  {
    std::size_t ray;
    double start, end;
    int steps;
    std::size_t first; // its first value in values_
  };
  std::vector<March> marches_;
  // A root being refined (regula falsi with the Illinois rule, per ray).
  struct Bracket
  {
    std::size_t ray;
    double outside, f_out, inside, f_in;
    double tolerance = 0.0;
    int stale = 0; // +1: the outside end kept twice in a row, -1: the inside end
    int steps = 0;
    bool out_known, in_known;
    bool open = true;
    double next = 0.0;
  };
  std::vector<Bracket> brackets_;
  std::vector<double> xs_, ys_, zs_, values_;
  Statistics stats_;
  // The current tile.
  int tx0_ = 0, ty0_ = 0, tw_ = 0;
  std::vector<Ray> rays_;
  Hit* hits_ = nullptr;
  std::size_t open_ = 0; // rays of the tile still searching
};

} // namespace frep::raycast::detail
