// hfA_NoiseP and hfA_Turbulence: Ken Perlin's gradient noise (perlin.h noise3) and the
// turbulence sum over octaves. Double-only (table lookups by value).
//
// The original fills its permutation and gradient tables on first use from the C/R random
// generator, so its values depend on the process's random state and are not reproducible (the
// conformance suite only parses these calls). Here the tables are built the same way (gradients
// ((rand % 512) - 256) / 256 normalised, a random permutation) but from a fixed-seed generator,
// once, into an immutable table: deterministic and thread-safe, no mutable global state.
#include "Library/detail/array_access.h"
#include "Library/detail/library_double.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace frep::library
{
namespace
{

constexpr int kB = 0x100;
constexpr int kBM = 0xff;
constexpr double kN = 0x1000;

struct PerlinTables
{
  std::array<int, kB + kB + 2> p{};
  std::array<std::array<double, 3>, kB + kB + 2> g3{};
};

/// splitmix64: a small, well-mixed fixed-seed generator standing in for rand().
struct SplitMix64
{
  std::uint64_t state;

  std::uint32_t next()
  {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return static_cast<std::uint32_t>((z ^ (z >> 31)) >> 33); // 31 bits, like RAND_MAX
  }
};

PerlinTables make_tables()
{
  PerlinTables t;
  SplitMix64 rng{ 0x48797065724675ULL }; // "HyperFu"
  int i = 0;
  for (i = 0; i < kB; i++)
  {
    t.p[i] = i;
    for (int j = 0; j < 3; j++)
    {
      t.g3[i][j] = static_cast<double>(static_cast<int>(rng.next() % (kB + kB)) - kB) / kB;
    }
    double s =
      std::sqrt(t.g3[i][0] * t.g3[i][0] + t.g3[i][1] * t.g3[i][1] + t.g3[i][2] * t.g3[i][2]);
    if (s == 0.0)
    {
      // A zero gradient would normalise to NaN; the original would produce NaN noise there.
      t.g3[i] = { 1.0, 0.0, 0.0 };
      s = 1.0;
    }
    for (int j = 0; j < 3; j++)
    {
      t.g3[i][j] = t.g3[i][j] / s;
    }
  }
  while (--i)
  {
    const int k = t.p[i];
    const int j = static_cast<int>(rng.next() % kB);
    t.p[i] = t.p[j];
    t.p[j] = k;
  }
  for (i = 0; i < kB + 2; i++)
  {
    t.p[kB + i] = t.p[i];
    t.g3[kB + i] = t.g3[i];
  }
  return t;
}

const PerlinTables& tables()
{
  static const PerlinTables instance = make_tables(); // initialised once, thread-safe
  return instance;
}

double s_curve(double t)
{
  return t * t * (3. - 2. * t);
}

double lerp(double t, double a, double b)
{
  return a + t * (b - a);
}

/// perlin.h noise3, with C's (int) conversion as x86-64 performs it for huge inputs.
double noise3(const double vec[3])
{
  const PerlinTables& tb = tables();
  int b0[3], b1[3];
  double r0[3], r1[3];
  for (int i = 0; i < 3; ++i)
  {
    const double t = vec[i] + kN;
    const int ti = c_int(t);
    b0[i] = ti & kBM;
    b1[i] = (b0[i] + 1) & kBM;
    r0[i] = t - ti;
    r1[i] = r0[i] - 1.;
  }
  const int i = tb.p[b0[0]];
  const int j = tb.p[b1[0]];
  const int b00 = tb.p[i + b0[1]];
  const int b10 = tb.p[j + b0[1]];
  const int b01 = tb.p[i + b1[1]];
  const int b11 = tb.p[j + b1[1]];
  const double t = s_curve(r0[0]);
  const double sy = s_curve(r0[1]);
  const double sz = s_curve(r0[2]);
  auto at3 = [&](int index, double rx, double ry, double rz)
  {
    const auto& q = tb.g3[index];
    return rx * q[0] + ry * q[1] + rz * q[2];
  };
  double u = at3(b00 + b0[2], r0[0], r0[1], r0[2]);
  double v = at3(b10 + b0[2], r1[0], r0[1], r0[2]);
  double a = lerp(t, u, v);
  u = at3(b01 + b0[2], r0[0], r1[1], r0[2]);
  v = at3(b11 + b0[2], r1[0], r1[1], r0[2]);
  double b = lerp(t, u, v);
  const double c = lerp(sy, a, b);
  u = at3(b00 + b1[2], r0[0], r0[1], r1[2]);
  v = at3(b10 + b1[2], r1[0], r0[1], r1[2]);
  a = lerp(t, u, v);
  u = at3(b01 + b1[2], r0[0], r1[1], r1[2]);
  v = at3(b11 + b1[2], r1[0], r1[1], r1[2]);
  b = lerp(t, u, v);
  const double d = lerp(sy, a, b);
  return lerp(sz, c, d);
}

} // namespace

// hfA_NoiseP(x): noise3 at x[1..3] (size of x not checked by the original).
double a_noise_p(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  const double v[3] = { at(x, 0), at(x, 1), at(x, 2) };
  return noise3(v);
}

// hfA_Turbulence(x, freq): sum over freq, freq/2, ... >= 1 of |2 noise3(freq x) - 1| / freq.
// An infinite freq never halves below 1 (the original loops forever): NaN here.
double a_turbulence(DoubleArgs args, DoubleContext&)
{
  auto x = args[0].array;
  double freq = args[1].real;
  if (std::isinf(freq) && freq > 0)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double t = 0;
  for (; freq >= 1.0; freq /= 2)
  {
    const double xt[3] = { at(x, 0) * freq, at(x, 1) * freq, at(x, 2) * freq };
    t += std::fabs((2 * noise3(xt) - 1.0)) / freq;
  }
  return t;
}

} // namespace frep::library
