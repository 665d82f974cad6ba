// The model the section view and the spreadsheet cut their sections from when coordinates are
// ticked "projected" in the model panel: the model projected along them over their sliders'
// ranges (FRep/Project; the coordinates keep their numbers, the projected ones are read by
// nothing). Made again only when the model, the ranges or the parameters change, so moving
// another slider reuses it (and its per-thread searches).
#pragma once

#include "Compiler/model.h"
#include "Project/projection.h"

#include <memory>
#include <string>
#include <vector>

namespace frepstudio
{

class ProjectedModel
{
public:
  /// `model` itself when `axes` is empty; else its projection along `axes` with a[] =
  /// `parameters` (baked in: the result's own a[] are unused). Null when refused, `error` says
  /// why.
  std::shared_ptr<const frep::Model> get(const std::shared_ptr<const frep::Model>& model,
    const std::vector<frep::project::CoordinateRange>& axes, const std::vector<double>& parameters,
    std::string& error);

private:
  std::shared_ptr<const frep::Model> source_;
  std::vector<frep::project::CoordinateRange> axes_;
  std::vector<double> parameters_;
  std::shared_ptr<const frep::Model> projected_;
};

} // namespace frepstudio
