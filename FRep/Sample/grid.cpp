#include "Sample/grid.h"

#include <algorithm>
#include <sstream>

namespace frep
{

std::string check_grid_size(std::span<const std::int64_t> samples, double limit,
  const char* option)
{
  double total = 1.0;
  for (const std::int64_t n : samples)
  {
    total *= static_cast<double>(n);
  }
  // Indices are 64-bit and the mesher keys a grid edge as vertex * 4 + axis.
  limit = std::min(limit, 1e18);
  if (total <= limit)
  {
    return {};
  }
  std::ostringstream message;
  message << "grid: ";
  for (std::size_t a = 0; a < samples.size(); ++a)
  {
    message << (a == 0 ? "" : " x ") << samples[a];
  }
  message << " = " << total << " samples is more than the limit of " << limit << " (" << option
          << ")";
  return message.str();
}

} // namespace frep
