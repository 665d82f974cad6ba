// The interval of every coordinate of a model, as FRepStudio shows it: x1..x3 span the box that is
// meshed (the section view, the spreadsheet cells and the ray-cast pictures frame that box), x4..
// are the slider ranges. The one place that decides them, in this order:
//  1. a model file's comment lines, which the HyperFun language ignores, always win:
//       -- frepstudio: x4 = [0, 2]
//       -- frepstudio: x1 = [-4, 4]
//  2. x4.. without a line: the unit interval [0, 1] (the paper's "time" coordinates);
//  3. x1..x3 without a line: the solid's own bounds with a 5% margin
//     (frep::mesh::find_coordinate_bounds, x4..'s intervals of 1. and 2. passed as given, so
//     that, when the n-D solid is not bounded, x1..x3 cover its sections at the centre and the
//     corners of the sliders' ranges: Meta5D's four key shapes);
//  4. x1..x3 of a solid that cannot be bounded (it reaches the search box's edge, like a
//     half-space, or its intervals are too loose to tell; or it is empty): hfp's box [-10, 10],
//     and note() says why (the window lists it once with the model's errors).
// from_model_text() does 1. and 2.; with_solid_bounds() adds 3. and 4. for one object.
#pragma once

#include "Compiler/model.h"

#include <array>
#include <map>
#include <string>

namespace frepstudio
{

class CoordinateRanges
{
public:
  /// Reads every `-- frepstudio: xN = [lo, hi]` line of a model's text (lo < hi; others ignored).
  static CoordinateRanges from_model_text(const std::string& text);

  /// These ranges completed for `model` (a[] = 0, the model panel's default): x1..x3 without a
  /// line get the solid's own bounds (rule 3), or keep [-10, 10] with a note (rule 4). Interval
  /// searches: about 1 ms for a ball, 0.3 s for Meta5D; call it off the UI thread. Never throws
  /// (an engine error becomes the note).
  CoordinateRanges with_solid_bounds(const frep::Model& model) const;

  /// The interval of coordinate `index` (0-based: x[index + 1]).
  std::array<double, 2> range(int index) const;
  /// True when the file set coordinate `index` itself.
  bool is_from_file(int index) const { return overrides_.count(index) != 0; }
  /// True when coordinate `index`'s interval is the solid's own bounds.
  bool is_from_solid(int index) const { return found_.count(index) != 0; }
  /// Why x1..x3 without a line keep [-10, 10] (rule 4), one sentence naming the box kept and how
  /// to choose one; empty otherwise.
  const std::string& note() const { return note_; }

  /// Rule 2 and 4's intervals: [-10, 10] for x1..x3, [0, 1] for x4...
  static std::array<double, 2> default_range(int index);

private:
  std::map<int, std::array<double, 2>> overrides_;
  std::map<int, std::array<double, 2>> found_;
  std::string note_;
};

} // namespace frepstudio
