// Real roots of polynomials up to degree 4, transcribed operation for operation from the
// original's quartic.c (Ferrari's method through the resolvent cubic) because the SARDF
// operations pick a particular root from its output and must match it bit for bit.
#pragma once

namespace frep::library
{

/// Up to 5 roots. Entries at index >= count are 0 (the original leaves them uninitialised; its
/// callers read value[1] even when fewer roots were found).
struct Roots
{
  int count = 0;
  double value[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 };
};

/// Real roots of c4 x^4 + c3 x^3 + c2 x^2 + c1 x + c0 = 0, in the original's order.
Roots quartic_roots(double c4, double c3, double c2, double c1, double c0);

} // namespace frep::library
