// The normal matrix: surface normals move by the inverse transpose of a map's 3 x 3 (linear)
// part, so that they stay perpendicular to the surface under non-uniform scaling. The cofactor
// matrix cof(A) = det(A) A^-T is that up to scale — normals are renormalised after, so the scale
// does not matter — and needs no division (it exists for a singular A too). Multiplied by the
// sign of det(A) it also keeps normals on their side under mirrors. Used by the renderer for a
// mesh's transform and by the scene for world mappings and sample transforms.
#pragma once

#include <array>

namespace frep::render
{

/// Row-major 3 x 3.
using Matrix3 = std::array<double, 9>;

/// The upper-left 3 x 3 (the linear part) of a row-major 4 x 4.
constexpr Matrix3 linear_part(const std::array<double, 16>& m)
{
  return { m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10] };
}

/// cof(A) = det(A) * (A^-1)^T.
constexpr Matrix3 cofactor_matrix(const Matrix3& m)
{
  const double a = m[0], b = m[1], c = m[2], d = m[3], e = m[4], f = m[5], g = m[6], h = m[7],
               i = m[8];
  return { e * i - f * h,
    -(d * i - f * g),
    d * h - e * g,
    -(b * i - c * h),
    a * i - c * g,
    -(a * h - b * g),
    b * f - c * e,
    -(a * f - c * d),
    a * e - b * d };
}

/// det(A) from A and its cofactor matrix (expansion along the first row).
constexpr double determinant(const Matrix3& m, const Matrix3& cofactors)
{
  return m[0] * cofactors[0] + m[1] * cofactors[1] + m[2] * cofactors[2];
}

constexpr double determinant(const Matrix3& m)
{
  return determinant(m, cofactor_matrix(m));
}

/// sign(det A) * cof(A): the inverse transpose up to a positive scale, so normals keep their
/// side under mirrors (det < 0).
constexpr Matrix3 normal_matrix(const Matrix3& m)
{
  Matrix3 cof = cofactor_matrix(m);
  if (determinant(m, cof) < 0.0)
  {
    for (double& v : cof)
    {
      v = -v;
    }
  }
  return cof;
}

/// The normal matrix of a row-major 4 x 4's linear part.
constexpr Matrix3 normal_matrix(const std::array<double, 16>& m)
{
  return normal_matrix(linear_part(m));
}

/// q * v.
constexpr std::array<double, 3> apply(const Matrix3& q, const std::array<double, 3>& v)
{
  return { q[0] * v[0] + q[1] * v[1] + q[2] * v[2],
    q[3] * v[0] + q[4] * v[1] + q[5] * v[2],
    q[6] * v[0] + q[7] * v[1] + q[8] * v[2] };
}

} // namespace frep::render
