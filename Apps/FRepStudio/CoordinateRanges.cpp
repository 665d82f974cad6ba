#include "CoordinateRanges.h"

#include "Mesh/coordinate_bounds.h"

#include <algorithm>
#include <exception>
#include <optional>
#include <regex>
#include <sstream>
#include <vector>

namespace frepstudio
{

CoordinateRanges CoordinateRanges::from_model_text(const std::string& text)
{
  static const std::regex directive(
    R"(--\s*frepstudio:\s*x\s*(\d+)\s*=\s*\[\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\])");
  CoordinateRanges ranges;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line))
  {
    std::smatch match;
    if (!std::regex_search(line, match, directive))
      continue;
    try
    {
      const int coordinate = std::stoi(match[1].str());
      const double lo = std::stod(match[2].str());
      const double hi = std::stod(match[3].str());
      if (coordinate >= 1 && lo < hi)
        ranges.overrides_[coordinate - 1] = { lo, hi };
    }
    catch (const std::exception&)
    {
      // A malformed number: the line is a comment to the language, so it is simply not a range.
    }
  }
  return ranges;
}

CoordinateRanges CoordinateRanges::with_solid_bounds(const frep::Model& model) const
{
  constexpr int kSpace = 3; // x1..x3: the box; x4.. are always given (a line, or [0, 1])
  CoordinateRanges ranges = *this;
  ranges.found_.clear();
  ranges.note_.clear();
  const int n = model.x_dim();
  std::vector<std::optional<frep::Interval>> given(static_cast<std::size_t>(n));
  std::string unranged; // "x1, x2, x3": the coordinates the solid's bounds are for
  for (int i = 0; i < n; ++i)
  {
    if (i >= kSpace || is_from_file(i))
    {
      const auto r = range(i);
      given[static_cast<std::size_t>(i)] = frep::Interval{ r[0], r[1] };
    }
    else
    {
      unranged += (unranged.empty() ? "x" : ", x") + std::to_string(i + 1);
    }
  }
  if (unranged.empty())
    return ranges; // the file sets the whole box: nothing to search
  const auto fallback = default_range(0);
  try
  {
    const frep::mesh::CoordinateBounds bounds =
      frep::mesh::find_coordinate_bounds(model, {}, given, { fallback[0], fallback[1] });
    for (int i = 0; i < std::min(n, kSpace); ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      if (bounds.found[k])
        ranges.found_[i] = { bounds.ranges[k].lo, bounds.ranges[k].hi };
    }
    if (bounds.rule == frep::mesh::CoordinateBounds::Rule::None)
      ranges.note_ = bounds.note;
  }
  catch (const std::exception& e)
  {
    ranges.found_.clear();
    ranges.note_ = std::string("the solid's bounds: ") + e.what();
  }
  if (!ranges.note_.empty())
  {
    std::ostringstream keep;
    keep << ranges.note_ << "; " << unranged << " keep [" << fallback[0] << ", " << fallback[1]
         << "] (a line \"-- frepstudio: x1 = [lo, hi]\" sets a box)";
    ranges.note_ = keep.str();
  }
  return ranges;
}

std::array<double, 2> CoordinateRanges::range(int index) const
{
  if (const auto line = overrides_.find(index); line != overrides_.end())
    return line->second;
  if (const auto solid = found_.find(index); solid != found_.end())
    return solid->second;
  return default_range(index);
}

std::array<double, 2> CoordinateRanges::default_range(int index)
{
  if (index < 3)
    return { -10.0, 10.0 };
  return { 0.0, 1.0 };
}

} // namespace frepstudio
