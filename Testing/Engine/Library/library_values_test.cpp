// Direct calls of every library function with hand-checked values, the in-place effects on the
// caller's arrays, the wrong-dimension sentinels, and values the original interpreter produced
// (from the conformance suite's .expected files) for the functions with intricate code paths.
#include "library_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace frep::library::test
{
namespace
{

using F = FunctionId;
using V = std::vector<double>;
constexpr double kSentinel = -1111111111111.0;

// Bitwise comparison for values that must match the original exactly.
#define EXPECT_BITS(expected, actual) EXPECT_PRED2(same_bits, expected, actual)

TEST(LibraryPrimitives, ClosedFormValues)
{
  V x{ 1, 2, 3 };
  V zero{ 0, 0, 0 };
  V c{ 1, 1, 1 };
  EXPECT_EQ(lib(F::Sphere, { &x, &zero, 4.0 }), 16.0 - 1 - 4 - 9);
  EXPECT_EQ(lib(F::Sphere, { &x, &c, 2.0 }), 4.0 - 0 - 1 - 4);
  EXPECT_EQ(lib(F::Ellipsoid, { &x, &zero, 1.0, 2.0, 4.0 }), 1.0 - 1 - 1 - 0.5625);
  EXPECT_EQ(lib(F::CylinderX, { &x, &zero, 4.0 }), 16.0 - 4 - 9);
  EXPECT_EQ(lib(F::CylinderY, { &x, &zero, 4.0 }), 16.0 - 1 - 9);
  EXPECT_EQ(lib(F::CylinderZ, { &x, &zero, 4.0 }), 16.0 - 1 - 4);
  EXPECT_EQ(lib(F::EllCylX, { &x, &zero, 2.0, 4.0 }), 1.0 - 1 - 0.5625);
  EXPECT_EQ(lib(F::EllCylY, { &x, &zero, 1.0, 4.0 }), 1.0 - 1 - 0.5625);
  EXPECT_EQ(lib(F::EllCylZ, { &x, &zero, 1.0, 2.0 }), 1.0 - 1 - 1);
  V xz{ 3, 4, 0 };
  // torus Z, ring radius 5 through (3,4,0): r0^2 - 25 - 25 + 2*5*5 = r0^2
  EXPECT_EQ(lib(F::TorusZ, { &xz, &zero, 5.0, 1.0 }), 1.0);
  V xx{ 0, 3, 4 };
  EXPECT_EQ(lib(F::TorusX, { &xx, &zero, 5.0, 2.0 }), 4.0);
  V xy{ 3, 0, 4 };
  EXPECT_EQ(lib(F::TorusY, { &xy, &zero, 5.0, 0.5 }), 0.25);
  EXPECT_EQ(lib(F::ConeX, { &x, &zero, 2.0 }), 1.0 - 1 - 2.25);
  EXPECT_EQ(lib(F::ConeY, { &x, &zero, 2.0 }), 4.0 - 0.25 - 2.25);
  EXPECT_EQ(lib(F::ConeZ, { &x, &zero, 2.0 }), 9.0 - 0.25 - 1);
  EXPECT_EQ(lib(F::EllConeX, { &x, &zero, 2.0, 4.0 }), 1.0 - 1 - 0.5625);
  EXPECT_EQ(lib(F::EllConeY, { &x, &zero, 1.0, 4.0 }), 4.0 - 1 - 0.5625);
  EXPECT_EQ(lib(F::EllConeZ, { &x, &zero, 1.0, 2.0 }), 9.0 - 1 - 1);
  // superellipsoid with s1 = s2 = 1 is the ellipsoid
  EXPECT_EQ(lib(F::Superell, { &x, &zero, 2.0, 4.0, 6.0, 1.0, 1.0 }), 1.0 - (0.25 + 0.25) - 0.25);
}

TEST(LibraryPrimitives, BlockIsAnRIntersection)
{
  V v{ 0, 0, 0 };
  V x{ 1, 1, 1 };
  // each slab gives 1*1 = 1; 1 + 1 - sqrt(2), then that + 1 - sqrt(that^2 + 1)
  const double f = 2.0 - std::sqrt(2.0);
  EXPECT_EQ(lib(F::Block, { &x, &v, 2.0, 2.0, 2.0 }), f + 1.0 - std::sqrt(f * f + 1.0));
  EXPECT_EQ(lib(F::Block, { &x, &v, 2.0, -1.0, 2.0 }), kSentinel);
}

TEST(LibraryPrimitives, SkeletalPrimitives)
{
  V x{ 0, 0, 0 };
  V x0{ 0, 3 }, y0{ 0, 0 }, z0{ 0, 0 };
  V a{ 1, 1 }, b{ 2, 5 };
  // second centre at distance 3: 5 exp(-9)
  EXPECT_EQ(lib(F::Blobby, { &x, &x0, &y0, &z0, &a, &b, 0.5 }),
    (0.0 + 2.0 * std::exp(-0.0)) + 5.0 * std::exp(-1.0 * 9.0) - 0.5);
  V d{ 6, 4 };
  // metaball: first centre r = 0 <= d/3 -> b(1 - 0); second r = 3 in (4/3, 4): 1.5 b (1 - 3/4)^2
  EXPECT_EQ(
    lib(F::MetaBall, { &x, &x0, &y0, &z0, &b, &d, 1.0 }), 2.0 + 1.5 * 5 * 0.25 * 0.25 - 1.0);
  V dneg{ -1, 4 };
  EXPECT_EQ(lib(F::MetaBall, { &x, &x0, &y0, &z0, &b, &dneg, 0.0 }), 1.5 * 5 * 0.25 * 0.25);
  V ds{ 1, 2 };
  // soft: r = 0 gives 1; r = 3 > d = 2 gives nothing
  EXPECT_EQ(lib(F::Soft, { &x, &x0, &y0, &z0, &ds, 0.25 }), 0.75);
  V vect{ 0, 0, 0, 1, 0, 0 };
  V s{ 1, 1 };
  // 1/(1+0)^2 + 1/(1+1)^2
  EXPECT_EQ(lib(F::ConvPoint, { &x, &vect, &s, 0.0 }), 1.25);
}

TEST(LibraryPrimitives, NoiseG)
{
  V x{ 0, 0, 0 };
  EXPECT_EQ(lib(F::NoiseG, { &x, 2.5, 0.7, 1.4 }), 0.0);
  V x1{ 1, 0, 0 };
  // sy = sz = 0 -> serz = (a1/1.17) sin(0 + phase sy) = 0 -> product 0
  EXPECT_EQ(lib(F::NoiseG, { &x1, 2.5, 0.7, 1.4 }), 0.0);
}

TEST(LibraryPrimitives, WrongDimensionSentinels)
{
  V x4{ 1, 2, 3, 0 };
  V c{ 0, 0, 0 };
  V s{ 1 };
  for (F id : { F::Sphere, F::CylinderX, F::CylinderY, F::CylinderZ, F::ConeX, F::ConeY, F::ConeZ })
  {
    EXPECT_EQ(lib(id, { &x4, &c, 1.0 }), kSentinel) << function_info(id).spelling;
  }
  for (F id : { F::TorusX,
         F::TorusY,
         F::TorusZ,
         F::EllCylX,
         F::EllCylY,
         F::EllCylZ,
         F::EllConeX,
         F::EllConeY,
         F::EllConeZ,
         F::DTorusX,
         F::DTorusY,
         F::DTorusZ })
  {
    EXPECT_EQ(lib(id, { &x4, &c, 1.0, 1.0 }), kSentinel) << function_info(id).spelling;
  }
  EXPECT_EQ(lib(F::Ellipsoid, { &x4, &c, 1.0, 1.0, 1.0 }), kSentinel);
  EXPECT_EQ(lib(F::DEllipsoid, { &x4, &c, 1.0, 1.0, 1.0 }), kSentinel);
  EXPECT_EQ(lib(F::Block, { &x4, &c, 1.0, 1.0, 1.0 }), kSentinel);
  EXPECT_EQ(lib(F::Superell, { &x4, &c, 1.0, 1.0, 1.0, 1.0, 1.0 }), kSentinel);
  EXPECT_EQ(lib(F::NoiseG, { &x4, 1.0, 1.0, 1.0 }), kSentinel);
  EXPECT_EQ(lib(F::ConvPoint, { &x4, &c, &s, 0.0 }), kSentinel);
  EXPECT_EQ(lib(F::ConvLine, { &x4, &c, &c, &s, 0.0 }), kSentinel);
  EXPECT_EQ(lib(F::ConvCurve, { &x4, &c, &s, 0.0 }), kSentinel);
  EXPECT_EQ(lib(F::ConvLineR, { &x4, &c, &c, 1.0 }), kSentinel);
  EXPECT_EQ(lib(F::ConvTriangle, { &x4, &c, &s, 0.0 }), kSentinel);
  EXPECT_EQ(lib(F::ConvMesh, { &x4, &c, &c, &s, 0.0 }), kSentinel);
  EXPECT_EQ(lib(F::ConvArc, { &x4, &c, &s, &s, &c, &s, &s, 0.0 }), kSentinel);
  EXPECT_EQ(lib(F::BezierVolume, { &x4, 2.0, 2.0, 2.0, &c, &c }), kSentinel);
  // the distance cones and cylinder use their own sentinels
  EXPECT_EQ(lib(F::DConeX, { &x4, &c, 1.0 }), -11111111111.0);
  EXPECT_EQ(lib(F::DConeY, { &x4, &c, 1.0 }), -11111111111.0);
  EXPECT_EQ(lib(F::DConeZ, { &x4, &c, 1.0 }), -11111111111.0);
  EXPECT_EQ(lib(F::DCylinder, { &x4, &c, &c, 1.0 }), -11111111111.1);
  // parameter checks
  V x{ 1, 2, 3 };
  EXPECT_EQ(lib(F::Ellipsoid, { &x, &c, 1.0, 1e-7, 1.0 }), kSentinel);
  EXPECT_EQ(lib(F::EllCylZ, { &x, &c, 1.0, 0.0 }), kSentinel);
  EXPECT_EQ(lib(F::Superell, { &x, &c, 1.0, 1.0, 1.0, 1.0, -1e-7 }), kSentinel);
  EXPECT_EQ(lib(F::DEllipsoid, { &x, &c, 0.0, 1.0, 1.0 }), kSentinel);
}

TEST(LibraryPrimitives, ShortCentreArraysAreReadAsZeros)
{
  V x{ 1, 2, 3 };
  V c2{ 1, 2 }; // the original reads past the end (undefined); here the missing item is 0
  EXPECT_EQ(lib(F::Sphere, { &x, &c2, 4.0 }), 16.0 - 0 - 0 - 9);
}

TEST(LibraryBlends, BlendUnionAndIntersection)
{
  // f1 = 3, f2 = 4: sqrt = 5; d = a0 / (1 + 9 + 16) with a1 = a2 = 1
  EXPECT_EQ(lib(F::BlendUni, { 3.0, 4.0, 26.0, 1.0, 1.0 }), 4.0 + 3.0 + 5.0 + 1.0);
  EXPECT_EQ(lib(F::BlendInt, { 3.0, 4.0, 26.0, 1.0, 1.0 }), 4.0 + 3.0 - 5.0 + 1.0);
  // a1 = 0 is not rejected: IEEE arithmetic
  EXPECT_TRUE(std::isnan(lib(F::BlendUni, { 0.0, 1.0, 1.0, 0.0, 1.0 })));
}

TEST(LibraryTransformations, InPlaceEffects)
{
  V x{ 2, 4, 6 };
  EXPECT_EQ(lib(F::Scale3D, { &x, 2.0, 4.0, 3.0 }), 1.0);
  EXPECT_EQ(x, (V{ 1, 1, 2 }));
  EXPECT_EQ(lib(F::Shift3D, { &x, 1.0, -1.0, 0.5 }), 1.0);
  EXPECT_EQ(x, (V{ 0, 2, 1.5 }));

  const double pi2 = std::acos(0.0);
  V r{ 1, 0, 0 };
  lib(F::Rotate3DZ, { &r, pi2 });
  // x' = x cos + y sin, y' = -x sin + y cos
  EXPECT_EQ(r[0], std::cos(pi2));
  EXPECT_EQ(r[1], -1.0);
  EXPECT_EQ(r[2], 0.0);
  V ry{ 0, 5, 1 };
  lib(F::Rotate3DY, { &ry, pi2 }); // z' = z cos + x sin ; x' = -z sin + x cos
  EXPECT_EQ(ry, (V{ -1.0, 5.0, std::cos(pi2) }));
  V rx{ 7, 1, 0 };
  lib(F::Rotate3DX, { &rx, pi2 }); // y' = y cos + z sin ; z' = -y sin + z cos
  EXPECT_EQ(rx, (V{ 7.0, std::cos(pi2), -1.0 }));

  // twist about z from angle 0 at z = 0 to pi/2 at z = 2: at z = 1 the angle is pi/4
  V t{ 1, 0, 1 };
  lib(F::TwistZ, { &t, 0.0, 2.0, 0.0, 2.0 * pi2 });
  const double th = (1 - 0.5) * 0.0 + 0.5 * (2.0 * pi2);
  EXPECT_EQ(t, (V{ std::cos(th), -std::sin(th), 1.0 }));

  V st{ 3, 3, 3 };
  V origin{ 1, 1, 1 };
  lib(F::Stretch3D, { &st, &origin, 2.0, 4.0, 0.5 });
  EXPECT_EQ(st, (V{ 2.0, 1.5, 5.0 }));
  // the same array as point and origin: element by element, like the original
  V same{ 3, 3, 3 };
  lib(F::Stretch3D, { &same, &same, 2.0, 2.0, 2.0 });
  EXPECT_EQ(same, (V{ 3.0, 3.0, 3.0 }));

  // taper along z: below z1 the scale is s1, above z2 s2, linear between, |scale|<EPS -> 1
  V tp{ 2, 4, -1 };
  lib(F::TaperZ, { &tp, 0.0, 1.0, 2.0, 4.0 });
  EXPECT_EQ(tp, (V{ 1.0, 2.0, -1.0 }));
  V tp2{ 2, 4, 0.5 };
  lib(F::TaperZ, { &tp2, 0.0, 1.0, 2.0, 4.0 });
  EXPECT_EQ(tp2, (V{ 2.0 / 3.0, 4.0 / 3.0, 0.5 }));
  V tp3{ 2, 4, 9 };
  lib(F::TaperX, { &tp3, 0.0, 1.0, 2.0, 0.0 });
  EXPECT_EQ(tp3, (V{ 2.0, 4.0, 9.0 }));
  V tp4{ 0, 4, 9 };
  lib(F::TaperY, { &tp4, 0.0, 1.0, 2.0, 3.0 });
  EXPECT_EQ(tp4, (V{ 0.0, 4.0, 3.0 }));
}

TEST(LibraryTransformations, SpaceMaps)
{
  // one key point moving source (0,0,0) to target (1,0,0), b = 1: at the target u = 0, r = 0,
  // weight 1, so the point maps back onto the source
  V src{ 0, 0, 0 };
  V dst{ 1, 0, 0 };
  V b{ 1, 1, 1 };
  V p{ 1, 0, 0 };
  EXPECT_EQ(lib(F::SpaceMapCubic, { &p, &src, &dst, &b }), 1.0);
  EXPECT_EQ(p, (V{ 0, 0, 0 }));
  V far{ 10, 0, 0 };
  lib(F::SpaceMapCubic, { &far, &src, &dst, &b });
  EXPECT_EQ(far, (V{ 10, 0, 0 })); // r > 1: untouched
  V pe{ 1, 0, 0 };
  lib(F::SpaceMapExp, { &pe, &src, &dst, &b });
  EXPECT_EQ(pe, (V{ 0, 0, 0 }));
  V fe{ 1, 4, 0 };
  lib(F::SpaceMapExp, { &fe, &src, &dst, &b });
  EXPECT_EQ(fe, (V{ 1.0 - std::exp(-16.0), 4.0, 0.0 }));
}

TEST(LibraryTransformations, ShortArraysDoNotCrash)
{
  V x{ 2 };
  EXPECT_EQ(lib(F::Scale3D, { &x, 2.0, 2.0, 2.0 }), 1.0);
  EXPECT_EQ(x, (V{ 1.0 }));
  V empty;
  EXPECT_EQ(lib(F::Rotate3DX, { &empty, 1.0 }), 1.0);
}

TEST(LibraryConvolution, ValuesOfTheOriginal)
{
  V b{ 0, 0, 0, 0, 0, 0 }, e{ 1, 0, 0, 0, 1, 1 }, sc{ 1, 2 };
  V x{ 0.5, 0.2, -0.3 };
  EXPECT_BITS(0.47003419695041776, lib(F::ConvLine, { &x, &b, &e, &sc, 0.3 }));
  V y{ 1.5, 1, 0.5 };
  EXPECT_BITS(-0.19094639293515708, lib(F::ConvLine, { &y, &b, &e, &sc, 0.3 }));
  EXPECT_BITS(0.26253219715681936, lib(F::ConvLineR, { &x, &b, &e, 0.5 }));
  V origin{ 0, 0, 0 };
  EXPECT_BITS(0.95457666747909276, lib(F::ConvLineR, { &origin, &b, &e, 2.0 }));

  V vect{ 0, 0, 0, 1, 0, 0, 1, 1, 0.5 }, sc2{ 1, 1.5 };
  EXPECT_BITS(0.63007011999418228, lib(F::ConvCurve, { &x, &vect, &sc2, 0.25 }));

  V tri{ 0, 0, 0, 2, 0, 0, 0.5, 1.5, 0 }, one{ 1 };
  V xt{ 1, 0.2, -0.5 };
  EXPECT_BITS(0.29752386085605292, lib(F::ConvTriangle, { &xt, &tri, &one, 0.3 }));

  V mv{ 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 }, mi{ 1, 2, 3, 1, 2, 4 }, ms{ 1, 1 };
  V xm{ 0.5, -0.5, 0.5 };
  EXPECT_BITS(0.083047509397726094, lib(F::ConvMesh, { &xm, &mv, &mi, &ms, 0.3 }));
}

TEST(LibraryConvolution, ZeroLengthSegmentAborts)
{
  V b{ 1, 1, 1 }, e{ 1, 1, 1 }, s{ 1 };
  V x{ 0, 0, 0 };
  DoubleContext context;
  lib(F::ConvLine, { &x, &b, &e, &s, 0.3 }, context);
  ASSERT_TRUE(context.abort_message.has_value());
  EXPECT_EQ(*context.abort_message, "ERROR:Tips of the segment take same coordinate!");
  V v{ 1, 1, 1, 1, 1, 1 };
  DoubleContext curve;
  lib(F::ConvCurve, { &x, &v, &s, 0.3 }, curve);
  ASSERT_TRUE(curve.abort_message.has_value());
  EXPECT_EQ(*curve.abort_message, "Tips of the segment take same coordinate!");
  DoubleContext fine;
  V e2{ 2, 1, 1 };
  lib(F::ConvLine, { &x, &b, &e2, &s, 0.3 }, fine);
  EXPECT_FALSE(fine.abort_message.has_value());
}

TEST(LibraryConvolution, ArcValuesAndSideEffects)
{
  V cc{ 0, 0, 0 }, rr{ 1 }, th{ 90 }, ax{ 0, 0, 1 }, an{ 0 }, sc{ 1.5 };
  V x{ 0.7, 0.3, 0.1 };
  EXPECT_BITS(0.31495092107663836, lib(F::ConvArc, { &x, &cc, &rr, &th, &ax, &an, &sc, 0.4 }));
  EXPECT_EQ(an[0], 1e-6); // angle += EPS in the caller's array
  EXPECT_EQ(th[0], 90.0);
  V x2{ -0.5, 0.8, -0.3 };
  an = { 0 };
  EXPECT_BITS(-0.27480449213345259, lib(F::ConvArc, { &x2, &cc, &rr, &th, &ax, &an, &sc, 0.4 }));

  // theta 270 is split at 180 (and written back as 180); 400 is clamped to 360 first
  V c2{ 0.1, 0, 0 }, r2{ 1.2 }, ax2{ 1, 0, 1 }, an2{ 30 }, s2{ 1.5 }, th2{ 270 };
  V p{ -0.9, -0.2, 0.3 };
  EXPECT_BITS(0.2921845202946175, lib(F::ConvArc, { &p, &c2, &r2, &th2, &ax2, &an2, &s2, 0.4 }));
  EXPECT_EQ(th2[0], 180.0);
  EXPECT_EQ(an2[0], 30.0 + 1e-6);
  th2 = { 400 };
  an2 = { 30 };
  V q{ 0.2, -1, 0.5 };
  EXPECT_BITS(-0.16809922355838591, lib(F::ConvArc, { &q, &c2, &r2, &th2, &ax2, &an2, &s2, 0.4 }));
  EXPECT_EQ(th2[0], 180.0);
}

TEST(LibraryBezier, ValuesOfTheOriginal)
{
  V bb{ -1, -1, -1, 1, 1, 1 }, w{ 1, -1, 0.5, 2, -0.5, 1.5, 0.25, -2 };
  V x{ 0.5, -0.5, 0.25 };
  EXPECT_BITS(0.035099040036000895, lib(F::BezierVolume, { &x, 2.0, 2.0, 2.0, &bb, &w }));
  V y{ -0.9, 0.9, -0.9 };
  EXPECT_BITS(-1.2419333618604229, lib(F::BezierVolume, { &y, 2.0, 2.0, 2.0, &bb, &w }));
  V z{ 1.5, 0, 0 };
  EXPECT_BITS(-6.3252211471846271, lib(F::BezierVolume, { &z, 2.0, 2.0, 2.0, &bb, &w }));
  // degree beyond the original's table
  EXPECT_TRUE(std::isnan(lib(F::BezierVolume, { &x, 30.0, 2.0, 2.0, &bb, &w })));
}

TEST(LibrarySardf, DistancePrimitives)
{
  V c{ 0.5, -1, 2 };
  V o{ 0, 0, 0 };
  EXPECT_BITS(0.044902879379189249, lib(F::DEllipsoid, { &o, &c, 1.0, 2.0, 3.0 }));
  EXPECT_BITS(-1.6516208931570251, lib(F::DEllipsoid, { &o, &c, 3.0, 1.0, 0.5 }));
  EXPECT_BITS(0.0, lib(F::DEllipsoid, { &c, &c, 1.0, 2.0, 3.0 }));
  V p{ 1.25, 1.5, 0.75 };
  EXPECT_BITS(-0.87621848121271051, lib(F::DEllipsoid, { &p, &c, 1.0, 2.0, 3.0 }));
  V q{ -2, 0.5, 1 };
  EXPECT_BITS(-1.265834470128024, lib(F::DEllipsoid, { &q, &c, 3.0, 1.0, 0.5 }));

  V u{ 1, 1, 0 };
  EXPECT_BITS(-1.2638462845343543, lib(F::DCylinder, { &o, &c, &u, 1.0 }));
  EXPECT_BITS(-0.75890590993378604, lib(F::DCylinder, { &p, &c, &u, 1.0 }));

  // torus Z through the tube centre (3,4,0), R = 5: distance 0 -> r0
  V t{ 3, 4, 0 };
  EXPECT_EQ(lib(F::DTorusZ, { &t, &o, 5.0, 0.5 }), 0.5);
  V tx{ 1, 0, 5 };
  EXPECT_EQ(lib(F::DTorusX, { &tx, &o, 5.0, 0.5 }), -0.5);
  V ty{ 0, 2, 5 };
  EXPECT_EQ(lib(F::DTorusY, { &ty, &o, 5.0, 3.0 }), 1.0);
  // cone with R = 1 (45 degrees): on the axis at height h the distance is h sin(pi/4)
  V ax{ 2, 0, 0 };
  EXPECT_EQ(lib(F::DConeX, { &ax, &o, 1.0 }),
    -(0.0 * std::cos(std::atan(1.0)) - 2.0 * std::sin(std::atan(1.0))));
  V ay{ 0, -2, 0 };
  EXPECT_EQ(lib(F::DConeY, { &ay, &o, 1.0 }), 2.0 * std::sin(std::atan(1.0)));
  V az{ 3, 4, 0 };
  EXPECT_EQ(lib(F::DConeZ, { &az, &o, 1.0 }), -(5.0 * std::cos(std::atan(1.0))));
}

TEST(LibrarySardf, OperationsValuesOfTheOriginal)
{
  EXPECT_BITS(2.0, lib(F::DUni, { 1.0, 2.0, 1.0, 0.5 }));
  EXPECT_BITS(0.99999999999999778, lib(F::DInt, { 1.0, 2.0, 1.0, 0.5 }));
  EXPECT_BITS(-2.0, lib(F::DSub, { 1.0, 2.0, 1.0, 0.5 }));
  EXPECT_BITS(2.1014029908038654, lib(F::DUni, { 1.0, 2.0, 0.5, 0.2 }));
  EXPECT_BITS(0.99999999999999778, lib(F::DSub, { 2.0, -1.0, 1.0, 0.5 }));
  EXPECT_BITS(-0.99999999999999778, lib(F::DUni, { -1.0, -2.0, 1.0, 0.5 }));
  EXPECT_BITS(-2.1014029908038654, lib(F::DInt, { -1.0, -2.0, 0.5, 0.2 }));
  EXPECT_BITS(0.30420569207358167, lib(F::DUni, { 0.3, 0.2, 1.0, 0.5 }));
  EXPECT_BITS(0.094311204834142986, lib(F::DInt, { 0.3, 0.2, 1.0, 0.5 }));
  EXPECT_BITS(0.33495969362187761, lib(F::DUni, { 0.3, 0.2, 0.5, 0.2 }));
  EXPECT_BITS(0.13318675250908885, lib(F::DInt, { 0.3, 0.2, 0.5, 0.2 }));
  EXPECT_BITS(0.0, lib(F::DInt, { 0.0, 1.0, 1.0, 0.5 }));

  EXPECT_BITS(2.0, lib(F::DBlendUni, { 1.0, 2.0, 1.0 }));
  EXPECT_BITS(1.0, lib(F::DBlendInt, { 1.0, 2.0, 1.0 }));
  EXPECT_BITS(1.5885621722338523, lib(F::DBlendUni, { 1.0, 1.5, 1.0 }));
  EXPECT_BITS(0.0, lib(F::DBlendUni, { std::nan(""), 1.0, 1.0 }));
}

TEST(LibrarySardf, Sawtooth)
{
  EXPECT_BITS(0.31830988618379069, lib(F::Sawtooth, { 0.0, 5.0, 1.0, 1.0 }));
  EXPECT_BITS(0.15915494309189535, lib(F::Sawtooth, { 0.0, 20.0, 2.0, 0.5 }));
  EXPECT_EQ(lib(F::Sawtooth, { 0.3, 1.0, 1.0, 1.0 }), 0.0);
  EXPECT_EQ(lib(F::Sawtooth, { 0.3, std::nan(""), 1.0, 1.0 }), 0.0); // (int)NaN = INT_MIN
}

TEST(LibraryAttributes, SimpleFunctions)
{
  EXPECT_EQ(lib(F::A_Clamp, { 5.0, 0.0, 2.0 }), 2.0);
  EXPECT_EQ(lib(F::A_Clamp, { -1.0, 0.0, 2.0 }), 0.0);
  EXPECT_EQ(lib(F::A_Clamp, { 1.5, 0.0, 2.0 }), 1.5);
  EXPECT_BITS(0.0, lib(F::A_Floor, { -0.5 })); // (int) gives +0, not trunc's -0
  EXPECT_EQ(lib(F::A_Floor, { -2.7 }), -2.0);
  EXPECT_EQ(lib(F::A_Floor, { 1e300 }), -2147483648.0);
  // pulse is 1 iff b <= f <= a
  EXPECT_EQ(lib(F::A_Pulse, { 0.5, 1.0, 0.0 }), 1.0);
  EXPECT_EQ(lib(F::A_Pulse, { 0.5, 0.0, 1.0 }), 0.0);
  EXPECT_EQ(lib(F::A_Step, { 0.5, 1.0 }), 0.0);
  EXPECT_EQ(lib(F::A_Step, { 1.0, 1.0 }), 1.0);
  // smoothstep reads only its last three arguments
  EXPECT_EQ(lib(F::A_SmoothStep, { 9.0, 9.0, 9.0, 0.5, 0.0, 1.0 }), 0.5);
  EXPECT_EQ(lib(F::A_SmoothStep, { 9.0, 9.0, 9.0, 2.0, 0.0, 1.0 }), 1.0);
  EXPECT_EQ(lib(F::A_SmoothStep, { 9.0, 9.0, 9.0, -2.0, 0.0, 1.0 }), 0.0);
  EXPECT_EQ(lib(F::A_Modulo, { 7.0, 3.0 }), 1.0);
  EXPECT_EQ(lib(F::A_Modulo, { -7.0, 3.0 }), 2.0);
  // wave: (1 + sin 0) / 2 = 0.5 rescaled into [2, 4]
  EXPECT_EQ(lib(F::A_Wave, { 0.0, 4.0, 2.0, 1.0 }), 3.0);
  EXPECT_EQ(lib(F::A_Wave, { 0.0, 2.0, 4.0, 1.0 }), 3.0);
  V x{ 0, 0, 0 };
  EXPECT_EQ(lib(F::A_NoiseG, { &x, 1.0, 1.0 }), 0.5);
}

TEST(LibraryAttributes, ColourArrays)
{
  V s{ 9, 9, 9, 9 };
  EXPECT_EQ(lib(F::A_SetColor, { -1.0, &s, 1.0, 2.0, 3.0 }), 1.0);
  EXPECT_EQ(s, (V{ 9, 9, 9, 9 }));
  lib(F::A_SetColor, { 0.0, &s, 1.0, 2.0, 3.0 });
  EXPECT_EQ(s, (V{ 1, 2, 3, 9 }));
  V s1{ 5, 6 };
  lib(F::A_SetAttributes, { 1.0, &s, &s1 });
  EXPECT_EQ(s, (V{ 5, 6, 3, 9 }));

  V out{ 0, 0 }, a{ 0, 10 }, b{ 10, 20 };
  EXPECT_EQ(lib(F::A_Lerp, { &out, &a, &b, 2.5, 0.0, 10.0 }), 0.25);
  EXPECT_EQ(out, (V{ 2.5, 12.5 }));
  EXPECT_EQ(lib(F::A_Cerp, { &out, &a, &b, 20.0, 0.0, 10.0 }), 2.0);
  EXPECT_EQ(out, (V{ 10, 20 }));
  lib(F::A_Lerp, { &out, &a, &b, -1.0, 0.0, 10.0 });
  EXPECT_EQ(out, (V{ 0, 10 }));

  V hsv{ 0, 0, 0 }, rgb{ 0.2, 0.6, 0.4 };
  lib(F::A_RGBToHSV, { &rgb, &hsv });
  EXPECT_BITS(150.0, hsv[0]);
  EXPECT_BITS(0.66666666666666663, hsv[1]);
  EXPECT_BITS(0.59999999999999998, hsv[2]);
  V back{ 0, 0, 0 };
  lib(F::A_HSVToRGB, { &hsv, &back });
  EXPECT_BITS(0.20000000000000001, back[0]);
  EXPECT_BITS(0.59999999999999998, back[1]);
  EXPECT_BITS(0.40000000000000002, back[2]);
  V wrap{ 725, 0.5, 0.8 };
  lib(F::A_HSVToRGB, { &wrap, &back });
  EXPECT_BITS(0.80000000000000004, back[0]);
  EXPECT_BITS(0.43333333333333335, back[1]);
  EXPECT_BITS(0.40000000000000002, back[2]);
  V huge{ -std::numeric_limits<double>::infinity(), 1, 1 };
  lib(F::A_HSVToRGB, { &huge, &back }); // the original never returns; here it terminates
}

TEST(LibraryAttributes, UnionOperators)
{
  V c1{ 1, 0.2, 0.5 }, c2{ 0, 0.7, 0.5 };
  const double u = 1.0 + 2.0 + std::sqrt(5.0);
  const V expected[5] = {
    { 1, 0.2, 0.5 }, { 0, 0.7, 0.5 }, { 1, 0.2 + 0.7, 1 }, { 0, 0.2, 0.5 }, { 1, 0.7, 0.5 }
  };
  for (int op = 0; op < 5; ++op)
  {
    V s{ -1, -1, -1 };
    EXPECT_EQ(lib(F::A_Union, { 1.0, 2.0, &s, &c1, &c2, double(op) }), u);
    EXPECT_EQ(s, expected[op]) << "operator " << op;
  }
  V s{ -1, -1, -1 };
  lib(F::A_Union, { 1.0, 2.0, &s, &c1, &c2, 7.0 });
  EXPECT_EQ(s, (V{ -1, -1, -1 }));
  lib(F::A_Union, { 1.0, -2.0, &s, &c1, &c2, 7.0 });
  EXPECT_EQ(s, c1);
  V t{ -1, -1, -1 };
  lib(F::A_Union, { -5.0, -6.0, &t, &c1, &c2, 0.0 }); // union < -EPS: untouched
  EXPECT_EQ(t, (V{ -1, -1, -1 }));
}

TEST(LibraryAttributes, TablesAndPatterns)
{
  V attr{ 0, 0, 10, 20, 30, 40 }, map{ 0, 1, 3 };
  V s{ 0, 0 };
  lib(F::A_LookUpTable, { -1.0, &s, &attr, &map });
  EXPECT_EQ(s, (V{ 30, 40 })); // below the first entry: the LAST row
  lib(F::A_LookUpTable, { 1.0, &s, &attr, &map });
  EXPECT_EQ(s, (V{ 10, 20 }));
  lib(F::A_SmoothLookUpTable, { 2.0, &s, &attr, &map });
  EXPECT_EQ(s, (V{ 20, 30 }));

  V knots{ 0, 0, 1, 2, 3, 1, 2, 4, 0, 0, 5, 5 };
  V sp{ 0, 0 };
  lib(F::A_Spline, { &sp, &knots, 2.5, 0.0, 10.0 });
  EXPECT_EQ(sp, (V{ 2.6875, 1.0390625 }));
  lib(F::A_Spline, { &sp, &knots, 5.0, 0.0, 10.0 });
  EXPECT_EQ(sp, (V{ 2.75, 2.6875 }));

  V cattr{ 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9 }, cmap{ 0, 0.5, 1 };
  // rows are size(output) = 4 wide, so row 1 is attr[5..8] (1-based)
  V out{ -1, -1, -1, -1 };
  V x{ 0.8, 0, 0 };
  EXPECT_EQ(lib(F::A_Circles, { &x, &out, &cattr, &cmap }), 1.0);
  EXPECT_EQ(out, (V{ 0.5, 0.6, 0.7, 0.8 }));
  EXPECT_EQ(cattr[3], 1.0 + 0.1); // written into input_attr[n_map + 1]
  V x0{ 0.3, 0, 0 };
  lib(F::A_Circles, { &x0, &out, &cattr, &cmap });
  EXPECT_EQ(out, (V{ 0.1, 0.2, 0.3, 1.1 })); // row 0 reads the 1.1 just written
  V cattr2{ 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9 };
  V y{ 0.3, 0, 0 };
  out = { -1, -1, -1, -1 };
  lib(F::A_Crackles, { &y, &out, 3.0, &cattr2, &cmap });
  EXPECT_EQ(out, (V{ 0.5, 0.6, 0.7, 0.8 }));
  EXPECT_EQ(cattr2[3], 1.1);
  V z{ 0.8, 0.1, 0.2 };
  lib(F::A_Crackles, { &z, &out, 3.0, &cattr2, &cmap });
  EXPECT_EQ(out, (V{ 0.1, 0.2, 0.3, 1.1 }));

  V bs{ 1, 1, 1 }, gs{ 0.5, 0.5, 0.5 }, cb{ 1, 0, 0 }, cg{ 0, 0, 1 };
  V cs{ 9, 9, 9 };
  V p1{ 1.2, 0.5, 0.5 };
  EXPECT_EQ(lib(F::A_CheckerBoard, { &p1, &bs, &gs, &cs, &cb, &cg }), 1.0);
  EXPECT_EQ(cs, cg);
  V p2{ -0.6, -0.6, -0.6 };
  lib(F::A_CheckerBoard, { &p2, &bs, &gs, &cs, &cb, &cg });
  EXPECT_EQ(cs, cb);
}

TEST(LibraryAttributes, PerlinNoiseIsDeterministic)
{
  V x{ 0.3, 1.7, -2.2 };
  const double n1 = lib(F::A_NoiseP, { &x });
  EXPECT_EQ(n1, lib(F::A_NoiseP, { &x }));
  EXPECT_TRUE(std::isfinite(n1));
  EXPECT_LT(std::fabs(n1), 1.5);
  V lattice{ 1, 2, 3 };
  EXPECT_EQ(lib(F::A_NoiseP, { &lattice }), 0.0); // gradient noise vanishes on the lattice
  const double t = lib(F::A_Turbulence, { &x, 8.0 });
  EXPECT_TRUE(std::isfinite(t));
  EXPECT_GT(t, 0.0);
  EXPECT_EQ(lib(F::A_Turbulence, { &x, 0.5 }), 0.0);
  EXPECT_TRUE(std::isnan(lib(F::A_Turbulence, { &x, std::numeric_limits<double>::infinity() })));
}

TEST(LibraryCall, BadCallsDoNotCrash)
{
  DoubleContext context;
  std::vector<Arg<double>> none;
  EXPECT_TRUE(std::isnan(call(F::Sphere, none, context)));
  EXPECT_TRUE(context.abort_message.has_value());
  DoubleContext builtin;
  std::vector<Arg<double>> one(1);
  EXPECT_TRUE(std::isnan(call(F::Sqrt, one, builtin)));
  // every library function with empty arrays and zero reals
  for (const FunctionInfo& info : function_table())
  {
    if (info.builtin)
    {
      continue;
    }
    std::vector<Arg<double>> args(info.arity);
    DoubleContext ctx;
    (void)call(info.id, args, ctx);
  }
}

TEST(LibraryCall, GenericClassification)
{
  EXPECT_TRUE(is_generic(F::Sphere));
  EXPECT_TRUE(is_generic(F::SpaceMapCubic));
  EXPECT_TRUE(is_generic(F::A_Union));
  EXPECT_TRUE(is_generic(F::DBlendInt));
  EXPECT_FALSE(is_generic(F::DEllipsoid));
  EXPECT_FALSE(is_generic(F::ConvArc));
  EXPECT_FALSE(is_generic(F::BezierVolume));
  EXPECT_FALSE(is_generic(F::Sawtooth));
  EXPECT_FALSE(is_generic(F::Sqrt));
}

} // namespace
} // namespace frep::library::test
