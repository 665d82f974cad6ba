// The model a plan's sections are cut from: the model itself, or, when the mapping eliminates
// coordinates by projection (channel type "projected"), the model projected over their ranges
// (FRep/Project): inside where some value of them in the range puts the point inside. Made
// once per run, before any section, by every client of the plan (produce, vtkMultimediaMapper),
// so the cells, the frames, the framing and the ray caster all see the same object.
#pragma once

#include "Mapping/mapping_plan.h"

#include "Compiler/model.h"

#include <memory>
#include <string>
#include <vector>

namespace frep::mapping
{

struct SectionModel
{
  std::shared_ptr<const Model> model; ///< null when `error` says why
  std::string error;
  bool ok() const { return model != nullptr; }
};

/// `model` when `plan.projected` is empty; else its projection along those coordinates with
/// a[] = `parameters` (the coordinates keep their numbers, the projected ones are read by
/// nothing; the tolerance is the smallest of the channels'). The projected model's own a[] is
/// unused, so the sections' parameters may stay what they were.
SectionModel section_model(
  std::shared_ptr<const Model> model, const Plan& plan, const std::vector<double>& parameters);

} // namespace frep::mapping
