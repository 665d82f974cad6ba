// Which model coordinates x[1..n] drive the axes of a mesh, contour or image, and which are fixed:
// `--axes X,Y,Z,0.25` (mesh; hfp's -x; formerly --map), `--fix x4=0.5 --free x1,x2` (slice,
// render), or the default (the first coordinates drive the axes, any others are fixed at 0).
// (Not a "mapping": that word names the multimedia mapping, Multimedia/Mapping.)
#pragma once

#include "Compiler/model.h"

#include <optional>
#include <string>
#include <vector>

namespace frepkit
{

struct SectionAxes
{
  /// 0-based x indices driving the output axes, in axis order (X, Y[, Z]).
  std::vector<int> free;
  /// One entry per coordinate x[1..x_dim]: the fixed value, or nullopt for a free coordinate.
  std::vector<std::optional<double>> fixed;

  /// The tape specialisation: fixed coordinates folded in, free ones as inputs in axis order.
  frep::Specialisation specialisation(const std::vector<double>& parameters) const;
  /// "x1, x2, x3" (1-based names of the free coordinates).
  std::string free_names() const;
};

/// --axes: a comma-separated list, one entry per coordinate x[1], x[2], ...: X, Y and Z (each
/// exactly once, case-insensitive) say which coordinate each axis drives, numbers fix the
/// others. Coordinates beyond the list are fixed at 0. Throws UserError for a bad list or one
/// longer than x_dim.
SectionAxes parse_axes_option(const std::string& text, int x_dim);

/// The first `axis_count` coordinates drive the axes, the rest are fixed at 0. Throws UserError
/// when x_dim < axis_count.
SectionAxes default_axes(int x_dim, int axis_count);

/// --fix "x4=0.5,x5=0.25" (also "x[4]=0.5") and --free "x1,x2" (optional: default = the
/// coordinates not fixed, in increasing order). Every coordinate must be fixed or free, the free
/// count must be 2 or 3. Throws UserError otherwise.
SectionAxes parse_fix_free(const std::vector<std::string>& fix,
  const std::vector<std::string>& free,
  int x_dim);

/// "x4" or "x[4]" (spaces around allowed) -> 3, the 0-based index; -1 for anything else.
int coordinate_index(const std::string& name);

/// A number the whole of `text` spells (no trailing garbage), else nullopt.
std::optional<double> parse_number(const std::string& text);

} // namespace frepkit
