#include "Language/names.h"

#include <algorithm>
#include <cctype>

namespace frep
{

std::string lower_case(std::string_view text)
{
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool is_identifier(std::string_view text)
{
  return !text.empty() && std::isalpha(static_cast<unsigned char>(text.front())) &&
         std::all_of(text.begin(), text.end(),
           [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

} // namespace frep
