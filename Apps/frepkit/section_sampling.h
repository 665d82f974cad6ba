// frepkit slice's sampled image or volume: the engine's grid sampler (FRep/Sample/grid_sampler.h)
// over the --box/--grid grid, F and, when asked, s[1..m], stored whole. Grids larger than
// kMaxSectionSamples are refused before anything is allocated.
#pragma once

#include "Compiler/tape.h"
#include "Mesh/surface.h"
#include "section_writers/section_image.h"

#include <memory>

namespace frepkit
{

/// 2^27 samples: 1 GiB of F values (plus s[] arrays). Images and volumes beyond are refused
/// (SampleOptions::max_samples: the engine's limit, lowered to what slice holds in memory).
constexpr double kMaxSectionSamples = 134217728.0;

/// Samples `tape` (one input per axis of `grid`: 2 or 3) over `grid`. With `sign_only` (no
/// attributes), only each sample's side of `iso` is exact: a tile the engine proves wholly on one
/// side holds a bound of F on that side (frep::SampleOptions::sign_only), as a picture needs.
/// Throws UserError when the grid has too many samples; Ctrl-C cancels (UserError).
SampledSection sample_section(std::shared_ptr<const frep::Tape> tape,
  const frep::GridSpec& grid,
  bool attributes,
  int threads,
  bool show_progress,
  bool sign_only = false,
  double iso = 0.0);

} // namespace frepkit
