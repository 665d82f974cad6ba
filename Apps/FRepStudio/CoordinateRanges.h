// The interval of every coordinate of a model, as FRepStudio shows it: x1..x3 span the box that is
// meshed, x4.. are the slider ranges. Defaults are hfp's box [-10, 10] for x1..x3 and the unit
// interval [0, 1] for x4 and beyond (the paper's "time" coordinates); a model file can say
// otherwise with comment lines the HyperFun language ignores:
//   -- frepstudio: x4 = [0, 2]
//   -- frepstudio: x1 = [-4, 4]
#pragma once

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

  /// The interval of coordinate `index` (0-based: x[index + 1]).
  std::array<double, 2> range(int index) const;
  /// True when the file set coordinate `index` itself.
  bool is_from_file(int index) const { return overrides_.count(index) != 0; }

  static std::array<double, 2> default_range(int index);

private:
  std::map<int, std::array<double, 2>> overrides_;
};

} // namespace frepstudio
