// A model driven along a path through some of its own coordinates (issue 28, item 6): Meta5D
// along its animation path through (x4, x5). G(x1..xn, t) is F with the path coordinates replaced
// by the path's point at t = x[n + 1] in [0, 1] (F's own values of them are read by nothing), one
// composed model (Compiler/combine.h's compose) whose tape holds F's and the path's, so that
// projected along x[n + 1] (projection.h) the projector evaluates what reads x1..xn alone once
// per point: the union of every shape the path passes, the animation's ghost.
//
//   auto family = frep::project::path_family(meta5d, { 4, 5 }, pieces, {});
//   auto ghost = frep::project::project(family.model, { { 6, 0.0, 1.0 } }, options);
#pragma once

#include "Compiler/load_model.h"
#include "Project/path_pieces.h"

#include <memory>
#include <vector>

namespace frep::project
{

/// `model` (with a[] = `parameters`) along the path `pieces` through `path_coordinates` (1-based,
/// distinct, at least one, one per coordinate of the pieces): a model of x[n + 1].
/// Errors (a coordinate the model lacks or given twice, pieces that do
/// not fit) come back as one diagnostic without a position. Named "compose(<model>)".
LoadedModel path_family(std::shared_ptr<const Model> model, const std::vector<int>& path_coordinates,
  const std::vector<PathPiece>& pieces, const std::vector<double>& parameters);

} // namespace frep::project
