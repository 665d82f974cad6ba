// The bounds of a solid {F >= 0} over its free coordinates, from the interval evaluator: a box
// is split (each axis in turn, in halves); cells where F < 0 for sure are dropped, and the
// bounding box of the rest encloses every point where F >= 0 (or where F may fail). The one
// such search of the project: the ray caster clips its rays to it, and frepkit, vtkHyperFunSource
// and Python take it as the default box of a model.
#pragma once

#include "Compiler/tape.h"
#include "Eval/interval.h"

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace frep::mesh
{

struct SolidBounds
{
  enum class Status
  {
    Bounded,  ///< `box` encloses the solid
    Empty,    ///< F < 0 everywhere in the box searched
    Unbounded ///< the solid reaches the edge of the search box (e.g. a half-space), or the
              ///< search ran out of its budget of interval evaluations (loose enclosures in n-D)
  };
  Status status = Status::Empty;
  std::vector<Interval> box; ///< one interval per tape input; valid when Bounded
  std::size_t interval_evaluations = 0;
  double seconds = 0.0;

  bool bounded() const { return status == Status::Bounded; }
};

/// The bounds of {F >= 0} inside `box` (one interval per tape input), to within 1 / 2^depth of
/// the box on each axis, without a margin. Never Unbounded: the solid may touch `box`.
/// NaN or infinite enclosures are never culled (a cell is dropped only when F < 0 for sure).
/// With `budget` > 0, a walk that needs more interval evaluations stops and says Unbounded.
SolidBounds solid_bounds_in(const std::shared_ptr<const Tape>& tape,
  std::span<const Interval> box,
  int depth = 5,
  std::size_t budget = 0);

struct SolidBoundsOptions
{
  double search = 1000.0; ///< the search box is [-search, search] on every axis
  double margin = 0.05;   ///< added on each side, as a fraction of the extent on that axis
  int depth = 5;          ///< levels per axis of each pass (see find_solid_bounds)
  int max_passes = 12;
  /// Interval evaluations per pass before the search gives up (Unbounded): a solid whose
  /// enclosures stay loose costs up to 2^(depth n) cells in n dimensions otherwise.
  std::size_t budget = 200000;
};

/// The solid's own box: solid_bounds_in over the search box, then again over the box found
/// (each pass narrows it to within 1 / 2^depth of the last) until it stops shrinking, plus the
/// margin. Unbounded when the first pass finds the solid at the search box's edge; Empty when no
/// cell may hold F >= 0. Errors (no inputs, a bad option) throw std::invalid_argument.
SolidBounds find_solid_bounds(const std::shared_ptr<const Tape>& tape,
  const SolidBoundsOptions& options = {});

} // namespace frep::mesh
