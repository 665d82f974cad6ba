// Bounds-safe access to HyperFun arrays and the few C conversions the original relies on.
//
// The original reads and writes its array arguments through raw pointers, trusting sizes it
// never checks (a 2-element centre, a colour table shorter than the map, ...). That is
// undefined behaviour there and not reproducible; here a read past the end gives 0 and a write
// past the end is dropped, so bad input never crashes. Every in-range access is unchanged.
#pragma once

#include "Library/library.h"
#include "Library/detail/scalar_ops.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

namespace frep::library
{

/// hfDConeX/Y/Z return this for a wrong-size point array (not kWrongDimension).
inline constexpr double kWrongDimensionCone = -11111111111.0;
/// hfDCylinder returns this for a wrong-size point array.
inline constexpr double kWrongDimensionCylinder = -11111111111.1;

/// a[i], or 0 when i is outside the array.
template<class T>
T at(std::span<T> a, std::int64_t i)
{
  if (i < 0 || static_cast<std::uint64_t>(i) >= a.size())
  {
    return T(0.0);
  }
  return a[static_cast<std::size_t>(i)];
}

/// a[i] = v when i is inside the array; dropped otherwise.
template<class T, class V>
void put(std::span<T> a, std::int64_t i, const V& v)
{
  if (i >= 0 && static_cast<std::uint64_t>(i) < a.size())
  {
    a[static_cast<std::size_t>(i)] = T(v);
  }
}

/// Size of an array argument, as the original's `dim` (an int).
template<class T>
std::int64_t size_of(std::span<T> a)
{
  return static_cast<std::int64_t>(a.size());
}

/// The value of C's `(double)(int)v` as x86-64 computes it (cvttsd2si): truncation toward zero
/// when the result fits in an int, INT_MIN otherwise (NaN, infinities, out of range). An int
/// converted back is never -0, hence the + 0.0 (trunc(-0.5) is -0). Generic: usable with a
/// symbolic scalar.
template<class T>
T c_int_value(const T& v)
{
  auto fits = logical_and(v > T(-2147483649.0), v < T(2147483648.0));
  return select(fits, trunc(v) + 0.0, T(-2147483648.0));
}

/// The same conversion as an integer, for double-only code that indexes with it.
inline std::int32_t c_int(double v)
{
  if (v > -2147483649.0 && v < 2147483648.0)
  {
    return static_cast<std::int32_t>(v);
  }
  return INT32_MIN;
}

} // namespace frep::library
