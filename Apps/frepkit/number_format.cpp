#include "number_format.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace frepkit
{

std::string format_double(double value)
{
  if (std::isnan(value))
  {
    return "nan";
  }
  if (std::isinf(value))
  {
    return value > 0 ? "inf" : "-inf";
  }
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string format_short(double value)
{
  if (!std::isfinite(value))
  {
    return format_double(value);
  }
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

} // namespace frepkit
