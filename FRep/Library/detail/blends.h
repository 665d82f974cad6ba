// Blending set operations of LIBRARY.md section 2a, generic over the scalar type.
// (The restriction functions R_hfBlendUni/Int of the original are not registered, so a1 = 0 or
// a2 = 0 simply produces IEEE inf/NaN here too.)
#pragma once

#include "Library/library.h"
#include "Library/detail/scalar_ops.h"

#include <span>

namespace frep::library
{

// hfBlendUni / hfBlendInt(f1, f2, a0, a1, a2): R-union / R-intersection plus the displacement
// a0 / (1 + (f1/a1)^2 + (f2/a2)^2).
template<bool Union, class T, class Ctx>
T blend(std::span<Arg<T>> args, Ctx&)
{
  const T& f1 = args[0].real;
  const T& f2 = args[1].real;
  const T& a0 = args[2].real;
  const T& a1 = args[3].real;
  const T& a2 = args[4].real;
  T d = a0 / (1.0 + (f1 / a1) * (f1 / a1) + (f2 / a2) * (f2 / a2));
  T root = sqrt(f1 * f1 + f2 * f2);
  if constexpr (Union)
  {
    return f2 + f1 + root + d;
  }
  else
  {
    return f2 + f1 - root + d;
  }
}

} // namespace frep::library
