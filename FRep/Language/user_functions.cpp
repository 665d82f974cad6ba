#include "user_functions.h"

#include "Language/names.h"

#include <algorithm>
#include <cctype>

namespace frep
{
namespace
{

// Words the lexer keeps for itself: a function named so could never be called.
bool reserved(std::string_view key)
{
  static constexpr std::string_view kWords[] = { "x", "a", "s", "and", "or", "not", "xor", "array",
    "if", "then", "else", "endif", "while", "loop", "endloop" };
  return std::find(std::begin(kWords), std::end(kWords), key) != std::end(kWords);
}

} // namespace

std::string user_function_error(std::string_view name)
{
  return "User function " + std::string(name) + " failed";
}

std::string user_function_signature(const UserFunction& function)
{
  std::string s = function.name + "(";
  for (std::size_t i = 0; i < function.kinds.size(); ++i)
  {
    if (i > 0)
    {
      s += ", ";
    }
    if (function.kinds[i] == ArgKind::Array)
    {
      s += "array";
      const int size = i < function.array_sizes.size() ? function.array_sizes[i] : 0;
      if (size > 0)
      {
        s += "[" + std::to_string(size) + "]";
      }
    }
    else
    {
      s += "real";
    }
  }
  return s + ")";
}

std::string UserFunctionRegistry::add(UserFunction function)
{
  const std::string& name = function.name;
  if (!is_identifier(name))
  {
    return "user function '" + name +
      "': a name is letters, digits and '_', starting with a letter";
  }
  const std::string key = lower_case(name);
  if (reserved(key))
  {
    return "user function '" + name + "': the name is a word of the language";
  }
  if (find_function(key))
  {
    return "user function '" + name + "': the name is a library function of HyperFun";
  }
  if (find(key))
  {
    return "user function '" + name + "' is registered twice";
  }
  if (!function.point)
  {
    return "user function '" + name + "' has no point form";
  }
  if (function.kinds.size() > static_cast<std::size_t>(kMaxFunctionArity))
  {
    return "user function '" + name + "': " + std::to_string(function.kinds.size()) +
      " arguments, at most " + std::to_string(kMaxFunctionArity) + " are allowed";
  }
  for (ArgKind k : function.kinds)
  {
    if (k != ArgKind::Real && k != ArgKind::Array)
    {
      return "user function '" + name + "': an argument is a real or an array";
    }
  }
  if (!function.array_sizes.empty())
  {
    if (function.array_sizes.size() != function.kinds.size())
    {
      return "user function '" + name + "': " + std::to_string(function.array_sizes.size()) +
        " array sizes for " + std::to_string(function.kinds.size()) + " arguments";
    }
    for (int size : function.array_sizes)
    {
      if (size < 0)
      {
        return "user function '" + name + "': a negative array size";
      }
    }
  }
  keys_.push_back(key);
  functions_.push_back(std::make_shared<const UserFunction>(std::move(function)));
  return {};
}

std::optional<int> UserFunctionRegistry::find(std::string_view name) const
{
  const std::string key = lower_case(name);
  const auto it = std::find(keys_.begin(), keys_.end(), key);
  if (it == keys_.end())
  {
    return std::nullopt;
  }
  return static_cast<int>(it - keys_.begin());
}

std::string UserFunctionRegistry::merge(const UserFunctionRegistry& other)
{
  std::string first;
  for (const auto& f : other.functions_)
  {
    std::string e = add(*f);
    if (first.empty())
    {
      first = std::move(e);
    }
  }
  return first;
}

} // namespace frep
