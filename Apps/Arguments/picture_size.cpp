#include "picture_size.h"

#include <charconv>

namespace frepkit
{
namespace
{

std::string_view trim(std::string_view text)
{
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos)
  {
    return {};
  }
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::optional<int> side(std::string_view text)
{
  text = trim(text);
  int value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() ||
      value < 1 || value > kMaxPictureSide)
  {
    return std::nullopt;
  }
  return value;
}

} // namespace

std::optional<PictureSize> parse_picture_size(std::string_view text, std::string* error)
{
  const auto separator = text.find_first_of("xX,");
  std::optional<int> width, height;
  if (separator != std::string_view::npos &&
      text.find_first_of("xX,", separator + 1) == std::string_view::npos)
  {
    width = side(text.substr(0, separator));
    height = side(text.substr(separator + 1));
  }
  if (!width || !height)
  {
    if (error != nullptr)
    {
      *error = "expected WIDTHxHEIGHT or WIDTH,HEIGHT (e.g. 640x480 or 640,480), each a whole "
               "number of pixels from 1 to " +
               std::to_string(kMaxPictureSide) + "; got '" + std::string(text) + "'";
    }
    return std::nullopt;
  }
  return PictureSize{ *width, *height };
}

} // namespace frepkit
