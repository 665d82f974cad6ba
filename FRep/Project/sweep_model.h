// A profile moved along a path as a compiled model (issue 28, item 2, for callers that hold a
// model rather than a HyperFun file: the VTK filter vtkFRepSweep, C++ projects): G(x, t) =
// F(p(x, t)), p the profile's point for x at t (sweep_text.h's moved_point_text: the path's
// point subtracted, and with Orientation::Tangent its frame turned back), composed into one tape
// (Compiler/combine.h's compose), so F may be any model: a mesh's distance, a volume, a composed
// or projected one. Projected along x[4] it is the volume the profile sweeps:
//
//   auto moved = frep::project::sweep_model({ ball, {} }, path);
//   auto swept = frep::project::project(moved.model, { { 4, 0.0, 1.0 } }, options);
#pragma once

#include "Compiler/combine.h"
#include "Compiler/load_model.h"
#include "Eval/interval.h"
#include "Project/sweep_text.h"

#include <array>

namespace frep::project
{

/// `profile` (its free coordinates, by its specialisation, three of them) moved along `path` as
/// x[4] goes 0 -> 1: a model of x[4] named "compose(<profile>)". Errors come back as one
/// diagnostic without a position: a path sweep_path_error refuses, a profile that is not 3-D.
LoadedModel sweep_model(const Operand& profile, const SweepPath& path);

/// A box that holds what a profile inside `profile_box` sweeps along `path` (which must pass
/// sweep_path_error): the box moved over the path's exact extent (its cubics' extremes), or with
/// Orientation::Tangent the ball about the profile's origin through the box's farthest corner.
std::array<Interval, 3> sweep_bounds(const SweepPath& path, const std::array<Interval, 3>& profile_box);

} // namespace frep::project
