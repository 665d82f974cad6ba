// The weights of a metamorphosis's keys (Morph/lattice_weights.h): they sum to one, the corners
// are the corner keys exactly, linear is the paper's bilinear, the B-spline's are the Bernstein
// polynomials for 3 and 4 nodes and the Cox-de Boor recursion's otherwise, Catmull-Rom's pass
// through every key and reproduce a straight line between the end segments, and bad lattices are
// errors.
#include "Morph/lattice_weights.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace
{

using frep::morph::Interpolation;
using frep::morph::axis_weights;
using frep::morph::lattice_weights;

constexpr std::array<Interpolation, 3> kSchemes{ Interpolation::Linear, Interpolation::CatmullRom,
  Interpolation::BSpline };

double sum(const std::vector<double>& w)
{
  return std::accumulate(w.begin(), w.end(), 0.0);
}

// The clamped uniform B-spline basis N_{k,p}(t) by its recursive definition (a second,
// independent evaluation; 0/0 taken as 0).
double cox_de_boor(const std::vector<double>& knots, int k, int p, double t)
{
  if (p == 0)
  {
    const bool last = t == knots.back() && knots[k + 1] == knots.back() && knots[k] < knots[k + 1];
    return (knots[k] <= t && t < knots[k + 1]) || last ? 1.0 : 0.0;
  }
  double value = 0.0;
  if (knots[k + p] > knots[k])
    value += (t - knots[k]) / (knots[k + p] - knots[k]) * cox_de_boor(knots, k, p - 1, t);
  if (knots[k + p + 1] > knots[k + 1])
    value += (knots[k + p + 1] - t) / (knots[k + p + 1] - knots[k + 1]) *
             cox_de_boor(knots, k + 1, p - 1, t);
  return value;
}

} // namespace

TEST(LatticeWeights, SumToOneEverywhere)
{
  for (const Interpolation scheme : kSchemes)
  {
    for (int n = 2; n <= 9; ++n)
    {
      for (int s = 0; s <= 200; ++s)
      {
        const double t = s / 200.0;
        EXPECT_NEAR(sum(axis_weights(scheme, n, t)), 1.0, 1e-14)
          << frep::morph::interpolation_name(scheme) << " n=" << n << " t=" << t;
      }
    }
  }
}

TEST(LatticeWeights, EndsAreTheEndKeysExactlyAndNodesTheirKeys)
{
  for (const Interpolation scheme : kSchemes)
  {
    for (int n = 2; n <= 9; ++n)
    {
      std::vector<double> first(static_cast<std::size_t>(n), 0.0), last = first;
      first.front() = 1.0;
      last.back() = 1.0;
      EXPECT_EQ(axis_weights(scheme, n, 0.0), first);
      EXPECT_EQ(axis_weights(scheme, n, 1.0), last);
      EXPECT_EQ(axis_weights(scheme, n, -0.5), first); // clamped
      EXPECT_EQ(axis_weights(scheme, n, 7.0), last);
      if (scheme == Interpolation::BSpline)
        continue; // it approaches the inner keys only
      for (int i = 1; i < n - 1; ++i)
      {
        std::vector<double> alone(static_cast<std::size_t>(n), 0.0);
        alone[static_cast<std::size_t>(i)] = 1.0;
        EXPECT_EQ(axis_weights(scheme, n, static_cast<double>(i) / (n - 1)), alone)
          << frep::morph::interpolation_name(scheme) << " n=" << n << " node " << i;
      }
    }
  }
  EXPECT_TRUE(std::isnan(axis_weights(Interpolation::Linear, 3, NAN)[1]));
}

TEST(LatticeWeights, LinearOnTwoByTwoIsThePapersBilinear)
{
  // Meta5D = (Cat (1 - x4) + Robot x4) (1 - x5) + (NiHon (1 - x4) + Rob_let x4) x5: keys in
  // lattice order (x4 fastest) Cat, Robot, NiHon, Rob_let.
  const std::array<int, 2> nodes{ 2, 2 };
  for (const double x4 : { 0.0, 0.1, 0.25, 0.5, 0.8, 1.0 })
  {
    for (const double x5 : { 0.0, 0.3, 0.5, 0.9, 1.0 })
    {
      const std::array<double, 2> t{ x4, x5 };
      const std::vector<double> w = lattice_weights(Interpolation::Linear, nodes, t);
      ASSERT_EQ(w.size(), 4u);
      EXPECT_EQ(w[0], (1.0 - x4) * (1.0 - x5));
      EXPECT_EQ(w[1], x4 * (1.0 - x5));
      EXPECT_EQ(w[2], (1.0 - x4) * x5);
      EXPECT_EQ(w[3], x4 * x5);
    }
  }
}

TEST(LatticeWeights, BSplineIsBernsteinForThreeAndFourNodesAndCoxDeBoorBeyond)
{
  for (int s = 1; s < 100; ++s)
  {
    const double t = s / 100.0, r = 1.0 - t;
    const std::vector<double> q = axis_weights(Interpolation::BSpline, 3, t);
    const std::vector<double> c = axis_weights(Interpolation::BSpline, 4, t);
    const std::array<double, 3> bq{ r * r, 2 * t * r, t * t };
    const std::array<double, 4> bc{ r * r * r, 3 * t * r * r, 3 * t * t * r, t * t * t };
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(q[k], bq[k], 1e-15) << "t=" << t;
    for (std::size_t k = 0; k < 4; ++k)
      EXPECT_NEAR(c[k], bc[k], 1e-15) << "t=" << t;
  }
  for (int n = 5; n <= 8; ++n)
  {
    std::vector<double> knots(4, 0.0);
    for (int j = 1; j < n - 3; ++j)
      knots.push_back(static_cast<double>(j) / (n - 3));
    knots.insert(knots.end(), 4, 1.0);
    for (int s = 1; s < 64; ++s)
    {
      const double t = s / 64.0;
      const std::vector<double> w = axis_weights(Interpolation::BSpline, n, t);
      for (int k = 0; k < n; ++k)
      {
        EXPECT_NEAR(w[static_cast<std::size_t>(k)], cox_de_boor(knots, k, 3, t), 1e-14)
          << "n=" << n << " t=" << t << " k=" << k;
        EXPECT_GE(w[static_cast<std::size_t>(k)], 0.0);
      }
    }
  }
}

TEST(LatticeWeights, CatmullRomIsTheCardinalSplineOfTension0)
{
  // Inside the end segments it reproduces a straight line (sum_k w_k k = t (n - 1)), and its
  // weights are the matrix form's 0.5 [-u^3 + 2u^2 - u, 3u^3 - 5u^2 + 2, -3u^3 + 4u^2 + u,
  // u^3 - u^2] on the nodes around the segment.
  const int n = 6;
  for (int s = 1; s < 300; ++s)
  {
    const double t = s / 300.0;
    const std::vector<double> w = axis_weights(Interpolation::CatmullRom, n, t);
    const double place = t * (n - 1);
    const int i = static_cast<int>(std::floor(place));
    const double u = place - i;
    if (i >= 1 && i <= n - 3)
    {
      double line = 0.0;
      for (int k = 0; k < n; ++k)
        line += w[static_cast<std::size_t>(k)] * k;
      EXPECT_NEAR(line, place, 1e-13) << "t=" << t;
      const std::array<double, 4> m{ 0.5 * (-u * u * u + 2 * u * u - u),
        0.5 * (3 * u * u * u - 5 * u * u + 2), 0.5 * (-3 * u * u * u + 4 * u * u + u),
        0.5 * (u * u * u - u * u) };
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(w[static_cast<std::size_t>(i - 1 + k)], m[static_cast<std::size_t>(k)], 1e-15);
    }
    for (const double v : w)
      EXPECT_GE(v, -2.0 / 27.0 - 1e-15); // its lowest lobe
  }
}

TEST(LatticeWeights, TensorProductFirstAxisFastestAndCornersExact)
{
  const std::array<int, 3> nodes{ 3, 2, 4 };
  const std::array<double, 3> t{ 0.3, 0.6, 0.45 };
  for (const Interpolation scheme : kSchemes)
  {
    const std::vector<double> w = lattice_weights(scheme, nodes, t);
    ASSERT_EQ(w.size(), 24u);
    const std::vector<double> a = axis_weights(scheme, 3, 0.3), b = axis_weights(scheme, 2, 0.6),
                              c = axis_weights(scheme, 4, 0.45);
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i)
          EXPECT_EQ(w[static_cast<std::size_t>(i + 3 * (j + 2 * k))], a[i] * b[j] * c[k]);
    EXPECT_NEAR(sum(w), 1.0, 1e-14);
    // Each corner of the parameter cube is its corner key alone, exactly.
    for (int corner = 0; corner < 8; ++corner)
    {
      const std::array<double, 3> at{ corner & 1 ? 1.0 : 0.0, corner & 2 ? 1.0 : 0.0,
        corner & 4 ? 1.0 : 0.0 };
      const std::vector<double> v = lattice_weights(scheme, nodes, at);
      const std::size_t key = (corner & 1 ? 2 : 0) + 3 * ((corner & 2 ? 1 : 0) + 2 * (corner & 4 ? 3 : 0));
      for (std::size_t k = 0; k < v.size(); ++k)
        EXPECT_EQ(v[k], k == key ? 1.0 : 0.0) << "corner " << corner << " key " << k;
    }
  }
}

TEST(LatticeWeights, BadLatticesAreErrors)
{
  EXPECT_THROW(axis_weights(Interpolation::Linear, 1, 0.5), std::invalid_argument);
  EXPECT_THROW(axis_weights(Interpolation::BSpline, 0, 0.5), std::invalid_argument);
  const std::array<int, 2> nodes{ 2, 2 };
  const std::array<double, 1> one{ 0.5 };
  EXPECT_THROW(lattice_weights(Interpolation::Linear, nodes, one), std::invalid_argument);
  EXPECT_THROW(lattice_weights(Interpolation::Linear, std::span<const int>(), std::span<const double>()),
    std::invalid_argument);
  const std::array<int, 2> huge{ 2048, 2048 };
  const std::array<double, 2> t{ 0.5, 0.5 };
  EXPECT_THROW(lattice_weights(Interpolation::Linear, huge, t), std::invalid_argument);
  try
  {
    const std::array<int, 2> bad{ 2, 1 };
    lattice_weights(Interpolation::Linear, bad, t);
    ADD_FAILURE() << "a lattice axis of 1 node was accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("has 1)"), std::string::npos) << e.what();
  }
  EXPECT_EQ(frep::morph::interpolation_from_name("catmull-rom"), Interpolation::CatmullRom);
  EXPECT_FALSE(frep::morph::interpolation_from_name("cubic"));
}
