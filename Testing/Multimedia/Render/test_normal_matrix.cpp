// The normal matrix (Render/normal_matrix.h): cofactors of a known non-uniform scale, equality
// with the inverse transpose up to a positive scale, the sign under mirrors.
#include "Render/normal_matrix.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frep::render
{
namespace
{

Matrix3 transpose(const Matrix3& m)
{
  return { m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8] };
}

// The inverse by Gauss-Jordan elimination with partial pivoting (independent of cofactors).
Matrix3 inverse(Matrix3 a)
{
  Matrix3 inv{ 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  for (int col = 0; col < 3; ++col)
  {
    int pivot = col;
    for (int r = col + 1; r < 3; ++r)
    {
      pivot = std::abs(a[r * 3 + col]) > std::abs(a[pivot * 3 + col]) ? r : pivot;
    }
    for (int c = 0; c < 3; ++c)
    {
      std::swap(a[col * 3 + c], a[pivot * 3 + c]);
      std::swap(inv[col * 3 + c], inv[pivot * 3 + c]);
    }
    const double p = a[col * 3 + col];
    for (int c = 0; c < 3; ++c)
    {
      a[col * 3 + c] /= p;
      inv[col * 3 + c] /= p;
    }
    for (int r = 0; r < 3; ++r)
    {
      if (r == col)
      {
        continue;
      }
      const double f = a[r * 3 + col];
      for (int c = 0; c < 3; ++c)
      {
        a[r * 3 + c] -= f * a[col * 3 + c];
        inv[r * 3 + c] -= f * inv[col * 3 + c];
      }
    }
  }
  return inv;
}

void expect_near(const Matrix3& a, const Matrix3& b, double tolerance)
{
  for (int k = 0; k < 9; ++k)
  {
    EXPECT_NEAR(a[k], b[k], tolerance) << "entry " << k;
  }
}

TEST(NormalMatrix, NonUniformScale)
{
  const std::array<double, 16> scale{ 2, 0, 0, 5, 0, 3, 0, 6, 0, 0, 4, 7, 0, 0, 0, 1 };
  EXPECT_EQ(linear_part(scale), (Matrix3{ 2, 0, 0, 0, 3, 0, 0, 0, 4 }));
  // cof(diag(2, 3, 4)) = diag(12, 8, 6) = det * diag(1/2, 1/3, 1/4), det = 24.
  EXPECT_EQ(cofactor_matrix(linear_part(scale)), (Matrix3{ 12, 0, 0, 0, 8, 0, 0, 0, 6 }));
  EXPECT_EQ(determinant(linear_part(scale)), 24.0);
  EXPECT_EQ(normal_matrix(scale), (Matrix3{ 12, 0, 0, 0, 8, 0, 0, 0, 6 }));
  // The normal of the plane x/2 + y/3 = 1 after scaling (the plane x + y = 1 before) is (1, 1, 0)
  // moved by the normal matrix: (12, 8, 0), perpendicular to the scaled plane's direction
  // (2, -3, 0).
  const std::array<double, 3> n = apply(normal_matrix(scale), { 1, 1, 0 });
  EXPECT_EQ(n, (std::array<double, 3>{ 12, 8, 0 }));
  EXPECT_EQ(n[0] * 2 + n[1] * -3, 0.0);
}

TEST(NormalMatrix, IsTheInverseTransposeTimesDeterminant)
{
  const Matrix3 a{ 1.5, 0.2, -0.7, 0.3, 2.5, 0.4, -0.6, 0.1, 0.8 };
  const double det = determinant(a);
  ASSERT_GT(det, 0.0);
  Matrix3 expected = transpose(inverse(a));
  for (double& v : expected)
  {
    v *= det;
  }
  expect_near(cofactor_matrix(a), expected, 1e-12);
  expect_near(normal_matrix(a), expected, 1e-12);
}

TEST(NormalMatrix, MirrorKeepsTheSide)
{
  // A mirror in x with a non-uniform scale: det < 0, the cofactors point normals inward; the
  // normal matrix is the inverse transpose up to a POSITIVE scale.
  const Matrix3 mirror{ -2, 0, 0, 0, 1, 0, 0, 0, 3 };
  EXPECT_EQ(determinant(mirror), -6.0);
  EXPECT_EQ(cofactor_matrix(mirror), (Matrix3{ 3, 0, 0, 0, -6, 0, 0, 0, -2 }));
  EXPECT_EQ(normal_matrix(mirror), (Matrix3{ -3, 0, 0, 0, 6, 0, 0, 0, 2 }));
  const Matrix3 inverse_transpose = transpose(inverse(mirror));
  const Matrix3 q = normal_matrix(mirror);
  for (int k = 0; k < 9; ++k)
  {
    EXPECT_NEAR(q[k], 6.0 * inverse_transpose[k], 1e-12) << "entry " << k;
  }
}

TEST(NormalMatrix, SingularMapHasCofactors)
{
  // A projection onto z = 0 has no inverse; its cofactors still exist (normals go to +-z).
  const Matrix3 flatten{ 1, 0, 0, 0, 1, 0, 0, 0, 0 };
  EXPECT_EQ(determinant(flatten), 0.0);
  EXPECT_EQ(cofactor_matrix(flatten), (Matrix3{ 0, 0, 0, 0, 0, 0, 0, 0, 1 }));
}

} // namespace
} // namespace frep::render
