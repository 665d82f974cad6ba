#include "function_table.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace frep
{
namespace
{

constexpr ArgKind R = ArgKind::Real;
constexpr ArgKind A = ArgKind::Array;

// Order = FunctionId order. Arity and kinds as registered in the original's functions_info[]
// (hfA_SmoothStep really declares six reals; hfR, an R-package callback, is not registered).
constexpr FunctionInfo kFunctions[] = {
  {FunctionId::Sqrt, "sqrt", "sqrt", 1, {R}, true},
  {FunctionId::Exp, "exp", "exp", 1, {R}, true},
  {FunctionId::Log, "log", "log", 1, {R}, true},
  {FunctionId::Logd, "logd", "logd", 1, {R}, true},
  {FunctionId::Sin, "sin", "sin", 1, {R}, true},
  {FunctionId::Cos, "cos", "cos", 1, {R}, true},
  {FunctionId::Tan, "tan", "tan", 1, {R}, true},
  {FunctionId::Asin, "asin", "asin", 1, {R}, true},
  {FunctionId::Acos, "acos", "acos", 1, {R}, true},
  {FunctionId::Atan, "atan", "atan", 1, {R}, true},
  {FunctionId::Abs, "abs", "abs", 1, {R}, true},
  {FunctionId::Sinh, "sinh", "sinh", 1, {R}, true},
  {FunctionId::Cosh, "cosh", "cosh", 1, {R}, true},
  {FunctionId::Tanh, "tanh", "tanh", 1, {R}, true},
  {FunctionId::Sign, "sign", "sign", 1, {R}, true},
  {FunctionId::Mod, "mod", "mod", 2, {R, R}, true},
  {FunctionId::Max, "max", "max", 2, {R, R}, true},
  {FunctionId::Min, "min", "min", 2, {R, R}, true},
  {FunctionId::Atan2, "atan2", "atan2", 2, {R, R}, true},
  {FunctionId::Ceil, "ceil", "ceil", 1, {R}, true},
  {FunctionId::Floor, "floor", "floor", 1, {R}, true},
  {FunctionId::Int, "int", "int", 1, {R}, true},
  {FunctionId::Frac, "frac", "frac", 1, {R}, true},
  {FunctionId::Sphere, "hfsphere", "hfSphere", 3, {A, A, R}, false},
  {FunctionId::Ellipsoid, "hfellipsoid", "hfEllipsoid", 5, {A, A, R, R, R}, false},
  {FunctionId::TorusZ, "hftorusz", "hfTorusZ", 4, {A, A, R, R}, false},
  {FunctionId::TorusX, "hftorusx", "hfTorusX", 4, {A, A, R, R}, false},
  {FunctionId::TorusY, "hftorusy", "hfTorusY", 4, {A, A, R, R}, false},
  {FunctionId::EllCylX, "hfellcylx", "hfEllCylX", 4, {A, A, R, R}, false},
  {FunctionId::EllCylY, "hfellcyly", "hfEllCylY", 4, {A, A, R, R}, false},
  {FunctionId::EllCylZ, "hfellcylz", "hfEllCylZ", 4, {A, A, R, R}, false},
  {FunctionId::CylinderX, "hfcylinderx", "hfCylinderX", 3, {A, A, R}, false},
  {FunctionId::CylinderY, "hfcylindery", "hfCylinderY", 3, {A, A, R}, false},
  {FunctionId::CylinderZ, "hfcylinderz", "hfCylinderZ", 3, {A, A, R}, false},
  {FunctionId::Block, "hfblock", "hfBlock", 5, {A, A, R, R, R}, false},
  {FunctionId::Blobby, "hfblobby", "hfBlobby", 7, {A, A, A, A, A, A, R}, false},
  {FunctionId::MetaBall, "hfmetaball", "hfMetaBall", 7, {A, A, A, A, A, A, R}, false},
  {FunctionId::Soft, "hfsoft", "hfSoft", 6, {A, A, A, A, A, R}, false},
  {FunctionId::Scale3D, "hfscale3d", "hfScale3D", 4, {A, R, R, R}, false},
  {FunctionId::Shift3D, "hfshift3d", "hfShift3D", 4, {A, R, R, R}, false},
  {FunctionId::Rotate3DZ, "hfrotate3dz", "hfRotate3DZ", 2, {A, R}, false},
  {FunctionId::Rotate3DY, "hfrotate3dy", "hfRotate3DY", 2, {A, R}, false},
  {FunctionId::Rotate3DX, "hfrotate3dx", "hfRotate3DX", 2, {A, R}, false},
  {FunctionId::BlendUni, "hfblenduni", "hfBlendUni", 5, {R, R, R, R, R}, false},
  {FunctionId::BlendInt, "hfblendint", "hfBlendInt", 5, {R, R, R, R, R}, false},
  {FunctionId::TwistZ, "hftwistz", "hfTwistZ", 5, {A, R, R, R, R}, false},
  {FunctionId::TwistY, "hftwisty", "hfTwistY", 5, {A, R, R, R, R}, false},
  {FunctionId::TwistX, "hftwistx", "hfTwistX", 5, {A, R, R, R, R}, false},
  {FunctionId::Stretch3D, "hfstretch3d", "hfStretch3D", 5, {A, A, R, R, R}, false},
  {FunctionId::TaperZ, "hftaperz", "hfTaperZ", 5, {A, R, R, R, R}, false},
  {FunctionId::TaperY, "hftapery", "hfTaperY", 5, {A, R, R, R, R}, false},
  {FunctionId::TaperX, "hftaperx", "hfTaperX", 5, {A, R, R, R, R}, false},
  {FunctionId::ConvPoint, "hfconvpoint", "hfConvPoint", 4, {A, A, A, R}, false},
  {FunctionId::ConvLine, "hfconvline", "hfConvLine", 5, {A, A, A, A, R}, false},
  {FunctionId::ConvArc, "hfconvarc", "hfConvArc", 8, {A, A, A, A, A, A, A, R}, false},
  {FunctionId::ConvTriangle, "hfconvtriangle", "hfConvTriangle", 4, {A, A, A, R}, false},
  {FunctionId::BezierVolume, "hfbeziervolume", "hfBezierVolume", 6, {A, R, R, R, A, A}, false},
  {FunctionId::ConvLineR, "hfconvliner", "hfConvLineR", 4, {A, A, A, R}, false},
  {FunctionId::ConvCurve, "hfconvcurve", "hfConvCurve", 4, {A, A, A, R}, false},
  {FunctionId::ConvMesh, "hfconvmesh", "hfConvMesh", 5, {A, A, A, A, R}, false},
  {FunctionId::NoiseG, "hfnoiseg", "hfNoiseG", 4, {A, R, R, R}, false},
  {FunctionId::Superell, "hfsuperell", "hfSuperell", 7, {A, A, R, R, R, R, R}, false},
  {FunctionId::ConeX, "hfconex", "hfConeX", 3, {A, A, R}, false},
  {FunctionId::ConeY, "hfconey", "hfConeY", 3, {A, A, R}, false},
  {FunctionId::ConeZ, "hfconez", "hfConeZ", 3, {A, A, R}, false},
  {FunctionId::EllConeX, "hfellconex", "hfEllConeX", 4, {A, A, R, R}, false},
  {FunctionId::EllConeY, "hfellconey", "hfEllConeY", 4, {A, A, R, R}, false},
  {FunctionId::EllConeZ, "hfellconez", "hfEllConeZ", 4, {A, A, R, R}, false},
  {FunctionId::SpaceMapCubic, "hfspacemapcubic", "hfSpaceMapCubic", 4, {A, A, A, A}, false},
  {FunctionId::SpaceMapExp, "hfspacemapexp", "hfSpaceMapExp", 4, {A, A, A, A}, false},
  {FunctionId::A_Wave, "hfa_wave", "hfA_Wave", 4, {R, R, R, R}, false},
  {FunctionId::A_CheckerBoard, "hfa_checkerboard", "hfA_CheckerBoard", 6, {A, A, A, A, A, A}, false},
  {FunctionId::A_Union, "hfa_union", "hfA_Union", 6, {R, R, A, A, A, R}, false},
  {FunctionId::A_Crackles, "hfa_crackles", "hfA_Crackles", 5, {A, A, R, A, A}, false},
  {FunctionId::A_Circles, "hfa_circles", "hfA_Circles", 4, {A, A, A, A}, false},
  {FunctionId::A_NoiseG, "hfa_noiseg", "hfA_NoiseG", 3, {A, R, R}, false},
  {FunctionId::A_NoiseP, "hfa_noisep", "hfA_NoiseP", 1, {A}, false},
  {FunctionId::A_Turbulence, "hfa_turbulence", "hfA_Turbulence", 2, {A, R}, false},
  {FunctionId::A_SetColor, "hfa_setcolor", "hfA_SetColor", 5, {R, A, R, R, R}, false},
  {FunctionId::A_SetAttributes, "hfa_setattributes", "hfA_SetAttributes", 3, {R, A, A}, false},
  {FunctionId::A_Lerp, "hfa_lerp", "hfA_Lerp", 6, {A, A, A, R, R, R}, false},
  {FunctionId::A_Cerp, "hfa_cerp", "hfA_Cerp", 6, {A, A, A, R, R, R}, false},
  {FunctionId::A_Clamp, "hfa_clamp", "hfA_Clamp", 3, {R, R, R}, false},
  {FunctionId::A_Floor, "hfa_floor", "hfA_Floor", 1, {R}, false},
  {FunctionId::A_Pulse, "hfa_pulse", "hfA_Pulse", 3, {R, R, R}, false},
  {FunctionId::A_LookUpTable, "hfa_lookuptable", "hfA_LookUpTable", 4, {R, A, A, A}, false},
  {FunctionId::A_SmoothLookUpTable, "hfa_smoothlookuptable", "hfA_SmoothLookUpTable", 4, {R, A, A, A}, false},
  {FunctionId::A_Step, "hfa_step", "hfA_Step", 2, {R, R}, false},
  {FunctionId::A_SmoothStep, "hfa_smoothstep", "hfA_SmoothStep", 6, {R, R, R, R, R, R}, false},
  {FunctionId::A_Modulo, "hfa_modulo", "hfA_Modulo", 2, {R, R}, false},
  {FunctionId::A_Spline, "hfa_spline", "hfA_Spline", 5, {A, A, R, R, R}, false},
  {FunctionId::A_RGBToHSV, "hfa_rgbtohsv", "hfA_RGBToHSV", 2, {A, A}, false},
  {FunctionId::A_HSVToRGB, "hfa_hsvtorgb", "hfA_HSVToRGB", 2, {A, A}, false},
  {FunctionId::DConeX, "hfdconex", "hfDConeX", 3, {A, A, R}, false},
  {FunctionId::DConeY, "hfdconey", "hfDConeY", 3, {A, A, R}, false},
  {FunctionId::DConeZ, "hfdconez", "hfDConeZ", 3, {A, A, R}, false},
  {FunctionId::DCylinder, "hfdcylinder", "hfDCylinder", 4, {A, A, A, R}, false},
  {FunctionId::DEllipsoid, "hfdellipsoid", "hfDEllipsoid", 5, {A, A, R, R, R}, false},
  {FunctionId::DTorusX, "hfdtorusx", "hfDTorusX", 4, {A, A, R, R}, false},
  {FunctionId::DTorusY, "hfdtorusy", "hfDTorusY", 4, {A, A, R, R}, false},
  {FunctionId::DTorusZ, "hfdtorusz", "hfDTorusZ", 4, {A, A, R, R}, false},
  {FunctionId::DUni, "hfduni", "hfDUni", 4, {R, R, R, R}, false},
  {FunctionId::DInt, "hfdint", "hfDInt", 4, {R, R, R, R}, false},
  {FunctionId::DSub, "hfdsub", "hfDSub", 4, {R, R, R, R}, false},
  {FunctionId::DBlendUni, "hfdblenduni", "hfDBlendUni", 3, {R, R, R}, false},
  {FunctionId::DBlendInt, "hfdblendint", "hfDBlendInt", 3, {R, R, R}, false},
  {FunctionId::Sawtooth, "hfsawtooth", "hfSawtooth", 4, {R, R, R, R}, false},
};

static_assert(std::size(kFunctions) == static_cast<std::size_t>(FunctionId::Count));

constexpr bool table_is_in_id_order()
{
  for (std::size_t i = 0; i < std::size(kFunctions); ++i)
  {
    if (static_cast<std::size_t>(kFunctions[i].id) != i)
    {
      return false;
    }
  }
  return true;
}
static_assert(table_is_in_id_order());

} // namespace

std::span<const FunctionInfo> function_table()
{
  return kFunctions;
}

const FunctionInfo& function_info(FunctionId id)
{
  return kFunctions[static_cast<std::size_t>(id)];
}

std::optional<FunctionId> find_function(std::string_view name)
{
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const FunctionInfo& f : kFunctions)
  {
    if (f.name == lower)
    {
      return f.id;
    }
  }
  return std::nullopt;
}

} // namespace frep
