#include "ast.h"

#include "Language/names.h"

#include <algorithm>
#include <cctype>

namespace frep::ast
{
int find_object(const Program& program, std::string_view name)
{
  const std::string wanted = lower_case(name);
  for (std::size_t i = 0; i < program.objects.size(); ++i)
  {
    if (program.objects[i].name == wanted)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

int own_object_count(const Program& program)
{
  return static_cast<int>(program.objects.size()) - program.first_own_object;
}

int select_default_object(const Program& program)
{
  return select_object(program, default_object_name);
}

int select_object(const Program& program, std::string_view name, NameMatch match)
{
  if (own_object_count(program) <= 0)
  {
    return -1;
  }
  const std::string wanted = match == NameMatch::IgnoreCase ? lower_case(name) : std::string(name);
  for (std::size_t i = static_cast<std::size_t>(program.first_own_object);
       i < program.objects.size(); ++i)
  {
    if (program.objects[i].name == wanted)
    {
      return static_cast<int>(i);
    }
  }
  return program.first_own_object;
}

} // namespace frep::ast
