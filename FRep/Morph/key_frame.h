// Where a key shape of a metamorphosis sits and how large it is (issue 29, item 4: keys aligned
// as the blend proceeds): the centroid of its solid and the d-th root of its volume, from the
// inside samples of a grid over the solid's own bounds (Mesh/solid_bounds.h's search, then the
// sampler's sign-only pass). The morph's moving frame blends these with the keys' weights, so a
// key is evaluated where it would be if it had travelled and grown into the blend's place.
#pragma once

#include "Compiler/tape.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frep::morph
{

/// How a metamorphosis aligns its keys as the blend proceeds.
enum class Alignment
{
  None,           ///< every key in place (the paper)
  Centroid,       ///< each key moved so that its centroid follows the blended centroid
  CentroidAndSize ///< moved and scaled (about its centroid) to the blended size, F scaled alike
};

/// "none", "centroid", "size" (the names of frepkit's --align and the manifests); nullopt else.
std::optional<Alignment> alignment_from_name(std::string_view name);
std::string_view alignment_name(Alignment alignment);

struct KeyFrame
{
  std::vector<double> centroid; ///< one per coordinate
  double size = 0.0;            ///< volume^(1/d), in the model's units
  std::size_t inside = 0;       ///< inside samples it was measured from
  std::string error;            ///< non-empty: not measured (unbounded, empty, ...)
  bool ok() const { return error.empty(); }
};

/// The frame of the solid {F >= 0} of `tape` (every input a coordinate), measured on
/// `samples`^d grid points over its bounds. Never throws.
KeyFrame measure_key_frame(const std::shared_ptr<const Tape>& tape, int samples = 48);

} // namespace frep::morph
