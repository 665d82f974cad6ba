#include "points_reader.h"

#include "user_error.h"

#include <charconv>
#include <string_view>

namespace frepkit
{
namespace
{

bool is_space(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// Splits a line into whitespace-separated fields.
std::vector<std::string_view> fields_of(std::string_view line)
{
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && is_space(line[i]))
    {
      ++i;
    }
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i]))
    {
      ++i;
    }
    if (i > start)
    {
      fields.push_back(line.substr(start, i - start));
    }
  }
  return fields;
}

bool parse_number(std::string_view text, double& value)
{
  if (!text.empty() && text.front() == '+')
  {
    text.remove_prefix(1);
  }
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

} // namespace

PointsReader::PointsReader(std::istream& in, std::string source_name, int dimension)
  : in_(in)
  , source_name_(std::move(source_name))
  , dimension_(dimension)
{
}

std::size_t PointsReader::read(std::size_t max_points, std::vector<std::vector<double>>& columns)
{
  columns.resize(static_cast<std::size_t>(dimension_));
  for (auto& column : columns)
  {
    column.clear();
  }
  std::size_t count = 0;
  while (count < max_points && std::getline(in_, line_))
  {
    ++line_number_;
    const std::vector<std::string_view> fields = fields_of(line_);
    if (fields.empty() || fields.front().front() == '#')
    {
      continue;
    }
    const std::string where = source_name_ + ":" + std::to_string(line_number_) + ": ";
    if (fields.size() != static_cast<std::size_t>(dimension_))
    {
      throw UserError(where + "expected " + std::to_string(dimension_) +
        " coordinates (the object's x dimension), found " + std::to_string(fields.size()));
    }
    for (int k = 0; k < dimension_; ++k)
    {
      double value = 0;
      if (!parse_number(fields[static_cast<std::size_t>(k)], value))
      {
        throw UserError(where + "coordinate " + std::to_string(k + 1) + " is not a number: \"" +
          std::string(fields[static_cast<std::size_t>(k)].substr(0, 40)) + "\"");
      }
      columns[static_cast<std::size_t>(k)].push_back(value);
    }
    ++count;
  }
  if (in_.bad())
  {
    throw UserError(source_name_ + ": read error");
  }
  return count;
}

} // namespace frepkit
