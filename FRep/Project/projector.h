// Projection, the operation that lowers an object's dimension (the paper: "the Cartesian
// product, which increases an object's dimension, and projection, which decreases it"): for a
// tape F(x', t) whose last k inputs t are eliminated over a box T,
//
//   P(x') = max over t in T of F(x', t),
//
// inside wherever some t puts the point inside. A point value of P is a maximum, found by
// branch and bound over T with the one region walker: a box's enclosure is an upper bound (and
// culls the box when it cannot beat the best value by more than the tolerance), the value at
// its centre a lower bound. What comes out is F itself at the best t found, so
//
//   P - tolerance <= value <= P
//
// wherever the search does not end in the band's ends first: a value >= band is a lower bound
// of P (the point is well inside), a value < -band says P < -band + tolerance (well outside).
// The sign is P's wherever |P| > tolerance. The boxes of a point are bounded
// (max_boxes); where a point needs more (an enclosure that does not shrink: a tape with opaque
// calls, a NaN), the value is still F at the best t found and `resolved` says it was cut short.
#pragma once

#include "Compiler/tape.h"
#include "Eval/interval.h"
#include "Eval/region_walker.h"

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace frep::project
{

struct ProjectorOptions
{
  /// The value is within this of the maximum (> 0). Default 1e-4.
  double tolerance = 1e-4;
  /// Beyond +-band only the sign and |value| >= band are kept (> tolerance; infinity: the value
  /// within the tolerance everywhere). The mesher and the ray caster need values only near the
  /// surface. Default 0.1.
  double band = 0.1;
  /// Boxes of T enclosed per point before the search stops (>= 1). Default 4096.
  std::size_t max_boxes = 4096;
  /// Boxes of T enclosed per enclosure of P over a box of x' (>= 1): more gives tighter
  /// enclosures (the mesher culls more) at more cost per box. Default 32.
  std::size_t enclosure_boxes = 32;
};

/// P at one point: the value, where in T it was found and whether the search ended by the
/// tolerance (true) or by max_boxes.
struct Maximum
{
  double value = 0.0;
  std::vector<double> at; ///< the eliminated inputs' values where F = value
  bool resolved = true;
  std::size_t boxes = 0; ///< boxes of T enclosed
};

/// Not thread-safe: one per thread (the walker and evaluators keep scratch).
class Projector
{
public:
  /// `tape`'s last ranges.size() inputs are eliminated over `ranges` (finite, lo <= hi), the
  /// first ones kept. Throws std::invalid_argument when they do not fit (checked by
  /// check_projection first at API edges).
  Projector(std::shared_ptr<const Tape> tape, std::vector<Interval> ranges,
    const ProjectorOptions& options = {});
  ~Projector();
  Projector(const Projector&) = delete;
  Projector& operator=(const Projector&) = delete;

  std::size_t kept() const { return kept_; }

  /// The eliminated inputs' ranges from now on (as many as before; finite, lo <= hi).
  void set_ranges(std::span<const Interval> ranges);

  /// P(kept) to the tolerance.
  Maximum maximise(std::span<const double> kept);

  /// Only whether P(kept) >= threshold: the search stops at the first value that reaches it
  /// (then value >= threshold) and skips the boxes whose enclosure stays below it (a value below
  /// the threshold says P < threshold + tolerance).
  Maximum maximise(std::span<const double> kept, double threshold);

  /// Encloses P over a box of the kept inputs. Sound for the point values maximise() returns
  /// too: its lower end is lowered by the tolerance.
  IntervalResult enclose(std::span<const Interval> kept);

  /// P and its gradient by the kept inputs: F's gradient at the maximiser (right where the
  /// maximiser is unique). `gradient` has kept() items.
  double gradient(std::span<const double> kept, std::span<double> gradient);

private:
  Maximum run_search(std::span<const double> kept);
  struct Search;
  std::shared_ptr<const Tape> tape_;
  std::vector<Interval> ranges_;
  ProjectorOptions options_;
  std::size_t kept_ = 0;
  std::unique_ptr<Search> search_;
};

} // namespace frep::project
