#include "box_option.h"

#include "section_axes.h"
#include "number_format.h"
#include "user_error.h"

#include <cctype>
#include <cmath>
#include <optional>

namespace frepkit
{
namespace
{

const char* const kAxisNames[] = { "x", "y", "z" };

/// "x1=LO:HI,x2=LO:HI,x3=LO:HI" for the free coordinates.
std::string named_form(const std::vector<int>& free)
{
  std::string form;
  for (int index : free)
  {
    form += (form.empty() ? "x" : ",x") + std::to_string(index + 1) + "=LO:HI";
  }
  return form;
}

std::string free_list(const std::vector<int>& free)
{
  std::string names;
  for (std::size_t k = 0; k < free.size(); ++k)
  {
    names += (k == 0 ? "x" : ", x") + std::to_string(free[k] + 1);
  }
  return names;
}

/// The axis (0-based) that `name` names: a free coordinate (x4, x[4]) or an axis letter.
int axis_of(const std::string& name, const std::vector<int>& free, const std::string& entry)
{
  std::string lower;
  for (char c : name)
  {
    lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  for (std::size_t k = 0; k < free.size(); ++k)
  {
    if (lower == kAxisNames[k])
    {
      return static_cast<int>(k);
    }
  }
  const int index = coordinate_index(name);
  for (std::size_t k = 0; k < free.size(); ++k)
  {
    if (free[k] == index)
    {
      return static_cast<int>(k);
    }
  }
  const std::string axes = free.size() == 3 ? "x, y, z" : "x, y";
  if (index >= 0)
  {
    throw UserError("--box '" + entry + "': x" + std::to_string(index + 1) +
                    " is not a free coordinate (the box's axes are " + free_list(free) +
                    ", also called " + axes + ")");
  }
  throw UserError("--box '" + entry + "': unknown axis '" + name + "' (the box's axes are " +
                  free_list(free) + ", also called " + axes + ")");
}

void check_range(double lo, double hi, const std::string& what)
{
  if (!std::isfinite(lo) || !std::isfinite(hi))
  {
    throw UserError("--box: the bounds must be finite numbers (" + what + ")");
  }
  if (!(lo < hi))
  {
    throw UserError("--box " + what + ": the minimum " + format_short(lo) +
                    " is not less than the maximum " + format_short(hi));
  }
}

std::vector<double> parse_named(const std::vector<std::string>& entries,
  const std::vector<int>& free)
{
  const std::size_t n = free.size();
  std::vector<double> box(2 * n);
  std::vector<std::string> given(n);
  for (const std::string& entry : entries)
  {
    const auto equals = entry.find('=');
    const auto colon = equals == std::string::npos ? std::string::npos : entry.find(':', equals);
    const std::optional<double> lo = colon == std::string::npos
      ? std::nullopt
      : parse_number(entry.substr(equals + 1, colon - equals - 1));
    const std::optional<double> hi =
      colon == std::string::npos ? std::nullopt : parse_number(entry.substr(colon + 1));
    if (!lo || !hi)
    {
      throw UserError("--box '" + entry + "': expected NAME=LO:HI, e.g. " + named_form(free));
    }
    const int axis = axis_of(entry.substr(0, equals), free, entry);
    const std::size_t k = static_cast<std::size_t>(axis);
    if (!given[k].empty())
    {
      throw UserError("--box: x" + std::to_string(free[k] + 1) + " is given twice ('" +
                      given[k] + "' and '" + entry + "')");
    }
    check_range(*lo, *hi, entry);
    given[k] = entry;
    box[k] = *lo;
    box[k + n] = *hi;
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    if (given[k].empty())
    {
      throw UserError("--box: no range for x" + std::to_string(free[k] + 1) + " (axis " +
                      kAxisNames[k] + "); give one per axis: " + named_form(free));
    }
  }
  return box;
}

std::vector<double> parse_numbers(const std::vector<std::string>& entries,
  const std::vector<int>& free)
{
  const std::size_t n = free.size();
  std::string names;
  for (int pass = 0; pass < 2; ++pass)
  {
    for (std::size_t k = 0; k < n; ++k)
    {
      names += (names.empty() ? "" : ",") + std::string(kAxisNames[k]) + (pass == 0 ? "min" : "max");
    }
  }
  if (entries.size() != 2 * n)
  {
    throw UserError("--box needs " + std::to_string(2 * n) + " numbers " + names + " (got " +
                    std::to_string(entries.size()) + "), or a range per axis: " +
                    named_form(free));
  }
  std::vector<double> box;
  for (const std::string& entry : entries)
  {
    const std::optional<double> value = parse_number(entry);
    if (!value)
    {
      throw UserError("--box: '" + entry + "' is not a number (give " + names + ", or " +
                      named_form(free) + ")");
    }
    box.push_back(*value);
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::string axis = kAxisNames[k];
    if (std::isfinite(box[k]) && std::isfinite(box[k + n]) && !(box[k] < box[k + n]))
    {
      throw UserError("--box: " + axis + "min = " + format_short(box[k]) + " is not less than " +
                      axis + "max = " + format_short(box[k + n]) + " (the numbers are " + names +
                      ": all minima, then all maxima; or give ranges by name: " +
                      named_form(free) + ")");
    }
    check_range(box[k], box[k + n], axis + "min, " + axis + "max");
  }
  return box;
}

} // namespace

std::vector<double> parse_box(const std::vector<std::string>& entries, const std::vector<int>& free)
{
  if (entries.empty())
  {
    return {};
  }
  std::size_t named = 0;
  for (const std::string& entry : entries)
  {
    named += entry.find('=') != std::string::npos ? 1 : 0;
  }
  if (named == 0)
  {
    return parse_numbers(entries, free);
  }
  if (named != entries.size())
  {
    throw UserError("--box: give either numbers (all minima, then all maxima) or ranges by name (" +
                    named_form(free) + "), not both");
  }
  return parse_named(entries, free);
}

} // namespace frepkit
