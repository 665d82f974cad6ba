// Dispatch to the generic (scalar-type templated) library implementations.
//
// call_generic<T, Ctx>(id, args, ctx) evaluates a library function written once for any scalar
// type T that provides the vocabulary of scalar_ops.h (found by argument-dependent lookup):
// +, -, *, / (also mixed with double), unary -, ordered comparisons giving a condition type,
// select/logical_and/logical_or/logical_not on conditions, and the C math functions. Ctx needs
// abort_if(condition, message). The templates never branch on a T value, so a symbolic T
// records the whole computation; array sizes are plain integers and may be branched on.
//
// Returns nullopt for the functions that exist only for double (is_generic(id) == false) and
// for an argument list that does not match the function's arity.
#pragma once

#include "Library/detail/attributes_generic.h"
#include "Library/detail/blends.h"
#include "Library/detail/distance_primitives.h"
#include "Library/library.h"
#include "Library/detail/primitives.h"
#include "Library/detail/transformations.h"

#include <optional>
#include <span>

namespace frep::library
{

// The primitives of call_generic (section 1 of the library); nullopt for any other id.
template<class T, class Ctx>
std::optional<T> call_primitive(FunctionId id, std::span<Arg<T>> args, Ctx& ctx)
{
  switch (id)
  {
    // 1. primitives
    case FunctionId::Sphere:
      return sphere<T>(args, ctx);
    case FunctionId::Ellipsoid:
      return ellipsoid<T>(args, ctx);
    case FunctionId::TorusX:
      return torus<0, T>(args, ctx);
    case FunctionId::TorusY:
      return torus<1, T>(args, ctx);
    case FunctionId::TorusZ:
      return torus<2, T>(args, ctx);
    case FunctionId::EllCylX:
      return ell_cylinder<0, T>(args, ctx);
    case FunctionId::EllCylY:
      return ell_cylinder<1, T>(args, ctx);
    case FunctionId::EllCylZ:
      return ell_cylinder<2, T>(args, ctx);
    case FunctionId::CylinderX:
      return cylinder<0, T>(args, ctx);
    case FunctionId::CylinderY:
      return cylinder<1, T>(args, ctx);
    case FunctionId::CylinderZ:
      return cylinder<2, T>(args, ctx);
    case FunctionId::Block:
      return block<T>(args, ctx);
    case FunctionId::Blobby:
      return blobby<T>(args, ctx);
    case FunctionId::MetaBall:
      return metaball<T>(args, ctx);
    case FunctionId::Soft:
      return soft<T>(args, ctx);
    case FunctionId::ConvPoint:
      return conv_point<T>(args, ctx);
    case FunctionId::NoiseG:
      return noise_g<T>(args, ctx);
    case FunctionId::Superell:
      return superellipsoid<T>(args, ctx);
    case FunctionId::ConeX:
      return cone<0, T>(args, ctx);
    case FunctionId::ConeY:
      return cone<1, T>(args, ctx);
    case FunctionId::ConeZ:
      return cone<2, T>(args, ctx);
    case FunctionId::EllConeX:
      return ell_cone<0, T>(args, ctx);
    case FunctionId::EllConeY:
      return ell_cone<1, T>(args, ctx);
    case FunctionId::EllConeZ:
      return ell_cone<2, T>(args, ctx);

    default:
      return std::nullopt;
  }
}

template<class T, class Ctx>
std::optional<T> call_generic(FunctionId id, std::span<Arg<T>> args, Ctx& ctx)
{
  if (id >= FunctionId::Count || id < FunctionId::Sphere ||
      static_cast<int>(args.size()) != function_info(id).arity)
  {
    return std::nullopt;
  }
  switch (id)
  {
    // 2a. blends
    case FunctionId::BlendUni:
      return blend<true, T>(args, ctx);
    case FunctionId::BlendInt:
      return blend<false, T>(args, ctx);

    // 2b. transformations
    case FunctionId::Scale3D:
      return scale3d<T>(args, ctx);
    case FunctionId::Shift3D:
      return shift3d<T>(args, ctx);
    case FunctionId::Rotate3DX:
      return rotate3d<0, T>(args, ctx);
    case FunctionId::Rotate3DY:
      return rotate3d<1, T>(args, ctx);
    case FunctionId::Rotate3DZ:
      return rotate3d<2, T>(args, ctx);
    case FunctionId::TwistX:
      return twist<0, T>(args, ctx);
    case FunctionId::TwistY:
      return twist<1, T>(args, ctx);
    case FunctionId::TwistZ:
      return twist<2, T>(args, ctx);
    case FunctionId::Stretch3D:
      return stretch3d<T>(args, ctx);
    case FunctionId::TaperX:
      return taper<0, T>(args, ctx);
    case FunctionId::TaperY:
      return taper<1, T>(args, ctx);
    case FunctionId::TaperZ:
      return taper<2, T>(args, ctx);
    case FunctionId::SpaceMapCubic:
      return space_map<true, T>(args, ctx);
    case FunctionId::SpaceMapExp:
      return space_map<false, T>(args, ctx);

    // 3. SARDF family (closed-form members)
    case FunctionId::DConeX:
      return distance_cone<0, T>(args, ctx);
    case FunctionId::DConeY:
      return distance_cone<1, T>(args, ctx);
    case FunctionId::DConeZ:
      return distance_cone<2, T>(args, ctx);
    case FunctionId::DCylinder:
      return distance_cylinder<T>(args, ctx);
    case FunctionId::DTorusX:
      return distance_torus<0, T>(args, ctx);
    case FunctionId::DTorusY:
      return distance_torus<1, T>(args, ctx);
    case FunctionId::DTorusZ:
      return distance_torus<2, T>(args, ctx);
    case FunctionId::DBlendUni:
      return distance_blend<true, T>(args, ctx);
    case FunctionId::DBlendInt:
      return distance_blend<false, T>(args, ctx);

    // 4. attributes
    case FunctionId::A_Wave:
      return a_wave<T>(args, ctx);
    case FunctionId::A_CheckerBoard:
      return a_checkerboard<T>(args, ctx);
    case FunctionId::A_Union:
      return a_union<T>(args, ctx);
    case FunctionId::A_NoiseG:
      return a_noise_g<T>(args, ctx);
    case FunctionId::A_SetColor:
      return a_set_color<T>(args, ctx);
    case FunctionId::A_SetAttributes:
      return a_set_attributes<T>(args, ctx);
    case FunctionId::A_Lerp:
    case FunctionId::A_Cerp:
      return a_lerp<T>(args, ctx);
    case FunctionId::A_Clamp:
      return a_clamp<T>(args, ctx);
    case FunctionId::A_Floor:
      return a_floor<T>(args, ctx);
    case FunctionId::A_Pulse:
      return a_pulse<T>(args, ctx);
    case FunctionId::A_Step:
      return a_step<T>(args, ctx);
    case FunctionId::A_SmoothStep:
      return a_smooth_step<T>(args, ctx);
    case FunctionId::A_Modulo:
      return a_modulo<T>(args, ctx);
    case FunctionId::A_RGBToHSV:
      return a_rgb_to_hsv<T>(args, ctx);

    default:
      return call_primitive<T>(id, args, ctx);
  }
}

} // namespace frep::library
