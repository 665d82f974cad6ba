// The library functions that exist only for double: their control flow depends on values
// (iterative solvers, table searches, value-dependent loop counts), so the compiler calls them
// as opaque nodes. Each takes its arguments in declaration order, like library::call, and may
// modify array arguments in place exactly as the original does.
#pragma once

#include "Library/library.h"

#include <span>

namespace frep::library
{

using DoubleArgs = std::span<Arg<double>>;

// convolution.cpp
double conv_line(DoubleArgs args, DoubleContext& ctx);
double conv_curve(DoubleArgs args, DoubleContext& ctx);
double conv_line_r(DoubleArgs args, DoubleContext& ctx);
double conv_triangle(DoubleArgs args, DoubleContext& ctx);
double conv_mesh(DoubleArgs args, DoubleContext& ctx);
// conv_arc.cpp
double conv_arc(DoubleArgs args, DoubleContext& ctx);
// bezier_volume.cpp
double bezier_volume(DoubleArgs args, DoubleContext& ctx);
// distance_ellipsoid.cpp
double distance_ellipsoid(DoubleArgs args, DoubleContext& ctx);
// sardf_operations.cpp
double distance_union(DoubleArgs args, DoubleContext& ctx);
double distance_intersection(DoubleArgs args, DoubleContext& ctx);
double distance_subtraction(DoubleArgs args, DoubleContext& ctx);
// sawtooth.cpp
double sawtooth(DoubleArgs args, DoubleContext& ctx);
// attribute_patterns.cpp
double a_crackles(DoubleArgs args, DoubleContext& ctx);
double a_circles(DoubleArgs args, DoubleContext& ctx);
// attribute_tables.cpp
double a_lookup_table(DoubleArgs args, DoubleContext& ctx);
double a_smooth_lookup_table(DoubleArgs args, DoubleContext& ctx);
double a_spline(DoubleArgs args, DoubleContext& ctx);
// attribute_colour.cpp
double a_hsv_to_rgb(DoubleArgs args, DoubleContext& ctx);
// perlin_noise.cpp
double a_noise_p(DoubleArgs args, DoubleContext& ctx);
double a_turbulence(DoubleArgs args, DoubleContext& ctx);

} // namespace frep::library
