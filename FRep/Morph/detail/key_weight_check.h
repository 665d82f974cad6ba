// Internal: a metamorphosis's key weights (morph_text.h's KeyWeight) checked before any text is
// written: each names a key, no key twice, a scheme whose weights are never negative, and an
// expression that compiles where the text puts it (a diagnostic at its own column otherwise).
#pragma once

#include "Compiler/load_model.h"
#include "Language/diagnostic.h"
#include "Morph/morph_text.h"

#include <string>
#include <vector>

namespace frep::morph::detail
{

/// One expression per key of `key_names` (lattice order, lower-case object names; empty: the
/// key weighs 1), or an empty vector when no key has a weight. Problems go to `diagnostics`.
std::vector<std::string> key_weight_expressions(const MorphSpec& spec,
  const std::vector<std::string>& key_names,
  int d,
  int a_dim,
  const LoadOptions& key_options,
  std::vector<Diagnostic>& diagnostics);

} // namespace frep::morph::detail
