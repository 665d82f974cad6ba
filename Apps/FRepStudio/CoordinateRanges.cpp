#include "CoordinateRanges.h"

#include <regex>
#include <sstream>

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

std::array<double, 2> CoordinateRanges::range(int index) const
{
  const auto found = overrides_.find(index);
  return found != overrides_.end() ? found->second : default_range(index);
}

std::array<double, 2> CoordinateRanges::default_range(int index)
{
  if (index < 3)
    return { -10.0, 10.0 };
  return { 0.0, 1.0 };
}

} // namespace frepstudio
