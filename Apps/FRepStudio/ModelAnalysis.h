// Parsing and compiling a model's text, and the coordinate ranges of the object to be shown (the
// box of x1..x3 from the solid's own bounds: CoordinateRanges): what the editor's debounced,
// background analysis produces. Pure engine code (no Qt widgets), safe to run on any thread.
#pragma once

#include "CoordinateRanges.h"

#include "Compiler/load_model.h"
#include "Compiler/model.h"
#include "Language/ast.h"
#include "Language/diagnostic.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace frepstudio
{

struct ObjectSummary
{
  std::string name; ///< lower-case, as the language stores it
  int x_dim = 0;
  int a_dim = 0;
  int s_dim = 1;
  std::shared_ptr<const frep::Model> model; ///< null when it did not compile
  /// Every coordinate's interval: what the section, the sliders and the spreadsheet use. The
  /// file's lines and [0, 1] for x4.. only until `searched`; then also the solid's bounds for
  /// x1..x3 (CoordinateRanges::with_solid_bounds).
  CoordinateRanges ranges;
  bool searched = false; ///< `ranges` has the solid's bounds (or the note why not)
};

struct ModelAnalysis
{
  std::uint64_t generation = 0; ///< which request this answers (newer ones win)
  std::string file_name;        ///< as used in the diagnostics
  std::shared_ptr<const frep::ast::Program> program;
  /// Parse errors, else compile errors of any object, each file:line:col.
  std::vector<frep::Diagnostic> diagnostics;
  std::vector<ObjectSummary> objects;
  int default_object = -1; ///< `my_model`, else the first object (the original's rule)
  CoordinateRanges file_ranges; ///< the file's `-- frepstudio:` lines only
  double seconds = 0;           ///< parse + compile + bounds time

  bool ok() const { return program != nullptr && diagnostics.empty(); }
};

/// Parses `text` (a .vm tape when `file_name` ends in .vm) and compiles every object; `options`:
/// the libraries and functions it may call (--library, --shape; Documentation/user-functions.md).
/// When the text has no error, it also searches the solid's bounds of the object to be shown
/// (ranges, searched): `shown_object` (in any case) when the text has it, else the default
/// object; the others' are searched when picked (StudioMainWindow). The search costs 1 ms for a
/// ball, 0.3 s for Meta5D: one object, not all six of meta5d.hf.
ModelAnalysis analyse_model(const std::string& text,
  const std::string& file_name,
  std::uint64_t generation,
  const frep::LoadOptions& options = {},
  const std::string& shown_object = {});

} // namespace frepstudio
