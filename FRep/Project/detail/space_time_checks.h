// The checks the space-time queries share: a time coordinate and a box of the others that fit
// the model, tolerances that make sense. Each returns "" or the reason.
#pragma once

#include "Compiler/model.h"
#include "Eval/interval.h"
#include "Project/projection.h"
#include "Project/space_time.h"

#include <string>
#include <vector>

namespace frep::project::detail
{

std::string check_time(const Model& model, const CoordinateRange& time);
std::string check_space(const Model& model, const std::vector<Interval>& space);
std::string check_tolerances(const SpaceTimeOptions& options);

/// What section_measures and topology_events check: time, space of 2 or 3 coordinates, steps
/// and samples.
std::string check_sections(const Model& model, const CoordinateRange& time,
  const std::vector<Interval>& space, int steps, int samples);

/// The input order with time (1-based coordinate) first and the other coordinates after it.
std::vector<int> time_first_order(int x_dim, int time_coordinate);

} // namespace frep::project::detail
