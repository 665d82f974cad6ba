// Comparable fields for a metamorphosis (issue 29, item 2): a key shape's signed distance,
// sampled. Blending keys whose values are bounded (like the Homotopic Fun keys' tanh) makes every
// point deep inside one key and far outside the other change side at the same parameter: the
// shape pops. Distances do not saturate, so points change side one after another.
//
// The distance is an exact Euclidean distance transform (Felzenszwalb and Huttenlocher's lower
// envelope of parabolas, axis by axis) of the key's inside samples on a grid over its solid's
// padded bounds: accurate to about a cell. The metamorphosis uses it only beyond a band of two
// cells and only on the key's own side (morph_text.h): the key's values, and so its zero set and
// topology, are kept exactly.
#pragma once

#include "Compiler/tape.h"
#include "Shapes/volume_field.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace frep::morph
{

/// How a metamorphosis makes its keys' values comparable.
enum class Normalisation
{
  None,    ///< each key's values as they are (the paper)
  Distance ///< beyond a band about the surface, the key's sampled signed distance is added
};

/// "none", "distance"; nullopt else.
std::optional<Normalisation> normalisation_from_name(std::string_view name);
std::string_view normalisation_name(Normalisation normalisation);

struct KeyDistance
{
  /// Signed distance (> 0 inside) at the samples. Origin and spacing are dyadic (multiples of
  /// 1/1024), so that they survive a decimal file (.vti) exactly.
  shapes::VolumeGrid grid;
  double band = 0.0; ///< two cells: where the distance is not trusted, the key's own F is used
  std::string error; ///< non-empty: not measured (not 3-D, unbounded, empty, ...)
  bool ok() const { return error.empty(); }
};

/// The sampled signed distance of the solid {F >= 0} of `tape` (3 coordinates) on `samples`
/// points per axis over its bounds padded by an eighth of their largest side. Never throws.
KeyDistance measure_key_distance(const std::shared_ptr<const Tape>& tape, int samples = 96);

} // namespace frep::morph
