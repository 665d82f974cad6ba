#include "ast.h"

#include <algorithm>
#include <cctype>

namespace frep::ast
{
namespace
{

std::string lower(std::string_view text)
{
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

} // namespace

int find_object(const Program& program, std::string_view name)
{
  const std::string wanted = lower(name);
  for (std::size_t i = 0; i < program.objects.size(); ++i)
  {
    if (program.objects[i].name == wanted)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

int select_default_object(const Program& program)
{
  return select_object(program, default_object_name);
}

int select_object(const Program& program, std::string_view name, NameMatch match)
{
  if (program.objects.empty())
  {
    return -1;
  }
  if (match == NameMatch::IgnoreCase)
  {
    const int found = find_object(program, name);
    return found >= 0 ? found : 0;
  }
  for (std::size_t i = 0; i < program.objects.size(); ++i)
  {
    if (program.objects[i].name == name)
    {
      return static_cast<int>(i);
    }
  }
  return 0;
}

} // namespace frep::ast
