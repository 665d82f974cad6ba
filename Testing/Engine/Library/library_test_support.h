// Helpers for calling the library with literal arguments in tests.
#pragma once

#include "Library/library.h"

#include <cstring>
#include <initializer_list>
#include <variant>
#include <vector>

namespace frep::library::test
{

/// One argument: a real, or an array the test keeps (so it can inspect in-place effects).
using Value = std::variant<double, std::vector<double>*>;

inline std::vector<Arg<double>> make_args(std::initializer_list<Value> values)
{
  std::vector<Arg<double>> args;
  for (const Value& v : values)
  {
    Arg<double> a;
    if (const double* d = std::get_if<double>(&v))
    {
      a.real = *d;
    }
    else
    {
      std::vector<double>* array = std::get<std::vector<double>*>(v);
      a.array = std::span<double>(array->data(), array->size());
    }
    args.push_back(a);
  }
  return args;
}

/// library::call with the given arguments; `context` receives any abort.
inline double lib(FunctionId id, std::initializer_list<Value> values, DoubleContext& context)
{
  std::vector<Arg<double>> args = make_args(values);
  return call(id, args, context);
}

inline double lib(FunctionId id, std::initializer_list<Value> values)
{
  DoubleContext context;
  return lib(id, values, context);
}

/// Bitwise equality (NaNs equal each other; -0 differs from +0).
inline bool same_bits(double a, double b)
{
  if (a != a && b != b)
  {
    return true;
  }
  return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace frep::library::test
