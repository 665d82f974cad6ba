// library::call and library::is_generic: the double entry point of the HyperFun library.
// Generic functions run their template with T = double (so the interpreter and the compiler's
// symbolic expansion share one implementation); the rest go to their double-only code.
#include "Library/library.h"

#include "Library/detail/library_double.h"
#include "Library/detail/library_generic.h"

#include <limits>

namespace frep::library
{
namespace
{

using DoubleFunction = double (*)(DoubleArgs, DoubleContext&);

/// The double-only implementation of `id`, or null when `id` is generic (or not a library
/// function).
DoubleFunction double_only(FunctionId id)
{
  switch (id)
  {
    case FunctionId::ConvLine:
      return conv_line;
    case FunctionId::ConvArc:
      return conv_arc;
    case FunctionId::ConvTriangle:
      return conv_triangle;
    case FunctionId::BezierVolume:
      return bezier_volume;
    case FunctionId::ConvLineR:
      return conv_line_r;
    case FunctionId::ConvCurve:
      return conv_curve;
    case FunctionId::ConvMesh:
      return conv_mesh;
    case FunctionId::A_Crackles:
      return a_crackles;
    case FunctionId::A_Circles:
      return a_circles;
    case FunctionId::A_NoiseP:
      return a_noise_p;
    case FunctionId::A_Turbulence:
      return a_turbulence;
    case FunctionId::A_LookUpTable:
      return a_lookup_table;
    case FunctionId::A_SmoothLookUpTable:
      return a_smooth_lookup_table;
    case FunctionId::A_Spline:
      return a_spline;
    case FunctionId::A_HSVToRGB:
      return a_hsv_to_rgb;
    case FunctionId::DEllipsoid:
      return distance_ellipsoid;
    case FunctionId::DUni:
      return distance_union;
    case FunctionId::DInt:
      return distance_intersection;
    case FunctionId::DSub:
      return distance_subtraction;
    case FunctionId::Sawtooth:
      return sawtooth;
    default:
      return nullptr;
  }
}

bool is_library_function(FunctionId id)
{
  return id >= FunctionId::Sphere && id < FunctionId::Count;
}

} // namespace

bool is_generic(FunctionId id)
{
  return is_library_function(id) && double_only(id) == nullptr;
}

double call(FunctionId id, std::span<Arg<double>> args, DoubleContext& context)
{
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (!is_library_function(id))
  {
    context.abort_if(true, "internal error: not a library function");
    return kNaN;
  }
  if (static_cast<int>(args.size()) != function_info(id).arity)
  {
    context.abort_if(true, "internal error: wrong number of arguments for a library function");
    return kNaN;
  }
  if (DoubleFunction f = double_only(id))
  {
    return f(args, context);
  }
  return *call_generic<double, DoubleContext>(id, args, context);
}

} // namespace frep::library
