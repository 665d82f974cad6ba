// The table of callable functions: the 23 math builtins and the hf*/hfA_* library, with the
// arity and argument kinds the original interpreter registers (int_global.c functions_info[]).
// The parser checks calls against it; the library and the compiler dispatch on FunctionId.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace frep
{

/// Kind of one argument: any real expression, a bare array name, or a string constant.
enum class ArgKind : std::uint8_t
{
  Real,
  Array,
  String
};

/// Stable identifiers; the first 23 are the builtins in the original's order.
enum class FunctionId : std::uint16_t
{
  // builtins (int_global.c 0..22)
  Sqrt, Exp, Log, Logd, Sin, Cos, Tan, Asin, Acos, Atan, Abs, Sinh, Cosh, Tanh, Sign,
  Mod, Max, Min, Atan2, Ceil, Floor, Int, Frac,
  // 1. primitives
  Sphere, Ellipsoid, TorusZ, TorusX, TorusY, EllCylX, EllCylY, EllCylZ,
  CylinderX, CylinderY, CylinderZ, Block, Blobby, MetaBall, Soft,
  // 2b. transformations
  Scale3D, Shift3D, Rotate3DZ, Rotate3DY, Rotate3DX,
  // 2a. blends
  BlendUni, BlendInt,
  // 2b. more transformations
  TwistZ, TwistY, TwistX, Stretch3D, TaperZ, TaperY, TaperX,
  // 1. convolution, Bezier, noise, superellipsoid, cones
  ConvPoint, ConvLine, ConvArc, ConvTriangle, BezierVolume, ConvLineR, ConvCurve, ConvMesh,
  NoiseG, Superell, ConeX, ConeY, ConeZ, EllConeX, EllConeY, EllConeZ,
  // 2b. space maps
  SpaceMapCubic, SpaceMapExp,
  // 4. attributes
  A_Wave, A_CheckerBoard, A_Union, A_Crackles, A_Circles, A_NoiseG, A_NoiseP, A_Turbulence,
  A_SetColor, A_SetAttributes, A_Lerp, A_Cerp, A_Clamp, A_Floor, A_Pulse, A_LookUpTable,
  A_SmoothLookUpTable, A_Step, A_SmoothStep, A_Modulo, A_Spline, A_RGBToHSV, A_HSVToRGB,
  // 3. SARDF family
  DConeX, DConeY, DConeZ, DCylinder, DEllipsoid, DTorusX, DTorusY, DTorusZ,
  DUni, DInt, DSub, DBlendUni, DBlendInt, Sawtooth,
  Count
};

inline constexpr int kMaxFunctionArity = 10;

struct FunctionInfo
{
  FunctionId id;
  std::string_view name;  ///< lower-case; lookup is case-insensitive
  std::string_view spelling; ///< documented spelling (hfSphere, hfA_Lerp, ...)
  int arity;
  std::array<ArgKind, kMaxFunctionArity> kinds; ///< kinds[0..arity-1]
  bool builtin;           ///< one of the 23 math builtins (not a library function)
};

/// All functions, indexed by FunctionId.
std::span<const FunctionInfo> function_table();

/// The entry for an id.
const FunctionInfo& function_info(FunctionId id);

/// Case-insensitive lookup by name; nullopt when the name is not a function.
std::optional<FunctionId> find_function(std::string_view name);

} // namespace frep
