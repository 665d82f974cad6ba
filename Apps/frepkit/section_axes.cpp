#include "section_axes.h"

#include "user_error.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>

namespace frepkit
{
namespace
{

std::string trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
  {
    return {};
  }
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> split_commas(const std::string& text)
{
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, ','))
  {
    parts.push_back(trim(part));
  }
  if (!text.empty() && text.back() == ',')
  {
    parts.push_back({});
  }
  return parts;
}

} // namespace

int coordinate_index(const std::string& name)
{
  std::string text = trim(name);
  if (text.size() < 2 || (text[0] != 'x' && text[0] != 'X'))
  {
    return -1;
  }
  text.erase(0, 1);
  if (text.front() == '[')
  {
    if (text.back() != ']')
    {
      return -1;
    }
    text = text.substr(1, text.size() - 2);
  }
  int index = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), index);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size() || index < 1)
  {
    return -1;
  }
  return index - 1;
}

std::optional<double> parse_number(const std::string& text)
{
  const std::string t = trim(text);
  double value = 0;
  const auto result = std::from_chars(t.data(), t.data() + t.size(), value);
  if (t.empty() || result.ec != std::errc() || result.ptr != t.data() + t.size())
  {
    return std::nullopt;
  }
  return value;
}

frep::Specialisation SectionAxes::specialisation(const std::vector<double>& parameters) const
{
  frep::Specialisation s;
  s.parameters = parameters;
  s.fixed = fixed;
  s.input_order = free;
  return s;
}

std::string SectionAxes::free_names() const
{
  std::string names;
  for (int index : free)
  {
    names += (names.empty() ? "x" : ", x") + std::to_string(index + 1);
  }
  return names;
}

SectionAxes parse_axes_option(const std::string& text, int x_dim)
{
  const std::vector<std::string> entries = split_commas(text);
  if (static_cast<int>(entries.size()) > x_dim)
  {
    throw UserError("--axes " + text + ": " + std::to_string(entries.size()) +
                    " entries, but the object has x[" + std::to_string(x_dim) + "]");
  }
  SectionAxes axes;
  axes.free.assign(3, -1);
  axes.fixed.assign(static_cast<std::size_t>(x_dim), 0.0);
  for (std::size_t i = 0; i < entries.size(); ++i)
  {
    const std::string& entry = entries[i];
    if (entry.size() == 1 && std::string("XYZxyz").find(entry[0]) != std::string::npos)
    {
      const int axis = std::toupper(static_cast<unsigned char>(entry[0])) - 'X';
      if (axes.free[static_cast<std::size_t>(axis)] >= 0)
      {
        throw UserError("--axes " + text + ": " + entry + " appears twice");
      }
      axes.free[static_cast<std::size_t>(axis)] = static_cast<int>(i);
      axes.fixed[i] = std::nullopt;
      continue;
    }
    const std::optional<double> value = parse_number(entry);
    if (!value)
    {
      throw UserError("--axes " + text + ": '" + entry +
                      "' is neither X, Y, Z nor a number (entry " + std::to_string(i + 1) + ")");
    }
    axes.fixed[i] = *value;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    if (axes.free[static_cast<std::size_t>(axis)] < 0)
    {
      throw UserError("--axes " + text + ": " + std::string(1, static_cast<char>('X' + axis)) +
                      " is missing (X, Y and Z must each appear once)");
    }
  }
  return axes;
}

SectionAxes default_axes(int x_dim, int axis_count)
{
  if (x_dim < axis_count)
  {
    throw UserError("the object has x[" + std::to_string(x_dim) + "]: " + std::to_string(axis_count) +
                    " coordinates are needed");
  }
  SectionAxes axes;
  axes.fixed.assign(static_cast<std::size_t>(x_dim), 0.0);
  for (int i = 0; i < axis_count; ++i)
  {
    axes.free.push_back(i);
    axes.fixed[static_cast<std::size_t>(i)] = std::nullopt;
  }
  return axes;
}

SectionAxes parse_fix_free(const std::vector<std::string>& fix,
  const std::vector<std::string>& free,
  int x_dim)
{
  const std::string dimension = "the object has x[" + std::to_string(x_dim) + "]";
  SectionAxes axes;
  axes.fixed.assign(static_cast<std::size_t>(x_dim), std::nullopt);
  std::vector<bool> is_fixed(static_cast<std::size_t>(x_dim), false);
  for (const std::string& entry : fix)
  {
    const auto equals = entry.find('=');
    const int index = equals == std::string::npos ? -1 : coordinate_index(entry.substr(0, equals));
    const std::optional<double> value =
      equals == std::string::npos ? std::nullopt : parse_number(entry.substr(equals + 1));
    if (index < 0 || !value)
    {
      throw UserError("--fix '" + entry + "': expected xN=VALUE, e.g. x4=0.5");
    }
    if (index >= x_dim)
    {
      throw UserError("--fix '" + entry + "': " + dimension);
    }
    if (is_fixed[static_cast<std::size_t>(index)])
    {
      throw UserError("--fix: x" + std::to_string(index + 1) + " is fixed twice");
    }
    is_fixed[static_cast<std::size_t>(index)] = true;
    axes.fixed[static_cast<std::size_t>(index)] = *value;
  }
  if (free.empty())
  {
    for (int i = 0; i < x_dim; ++i)
    {
      if (!is_fixed[static_cast<std::size_t>(i)])
      {
        axes.free.push_back(i);
      }
    }
  }
  else
  {
    for (const std::string& name : free)
    {
      const int index = coordinate_index(name);
      if (index < 0)
      {
        throw UserError("--free '" + name + "': expected a coordinate name such as x1");
      }
      if (index >= x_dim)
      {
        throw UserError("--free '" + name + "': " + dimension);
      }
      if (is_fixed[static_cast<std::size_t>(index)])
      {
        throw UserError("--free '" + name + "': it is also fixed by --fix");
      }
      if (std::find(axes.free.begin(), axes.free.end(), index) != axes.free.end())
      {
        throw UserError("--free: " + trim(name) + " is listed twice");
      }
      axes.free.push_back(index);
    }
    for (int i = 0; i < x_dim; ++i)
    {
      if (!is_fixed[static_cast<std::size_t>(i)] &&
          std::find(axes.free.begin(), axes.free.end(), i) == axes.free.end())
      {
        throw UserError(
          "x" + std::to_string(i + 1) + " is neither fixed (--fix) nor free (--free)");
      }
    }
  }
  if (axes.free.size() != 2 && axes.free.size() != 3)
  {
    throw UserError(
      std::to_string(axes.free.size()) + " free coordinates (" +
      (axes.free.empty() ? std::string("none") : axes.free_names()) + "; " + dimension +
      "): a slice needs 2 (an image or contour) or 3 (a surface or volume); fix the others "
      "with --fix xN=VALUE");
  }
  return axes;
}

} // namespace frepkit
