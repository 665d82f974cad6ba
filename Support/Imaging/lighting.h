// The look of a shaded picture, shared by both renderers (the mesh renderer of Multimedia/Render
// and the ray caster of FRep/Raycast), so that a section drawn either way is lit the same: a
// small kit of lights fixed to the camera and the Blinn-Phong parameters.
#pragma once

#include <array>
#include <vector>

namespace frep::imaging
{

/// A directional light fixed to the camera (it turns with the view, like a studio kit).
struct Light
{
  /// Towards the light, in camera coordinates: x right, y up, z from the scene towards the
  /// camera. Need not be unit length.
  std::array<double, 3> direction{ 0.0, 0.0, 1.0 };
  double intensity = 1.0;
  double specular = 1.0; ///< scales RenderStyle::specular for this light
};

/// The default kit: a key light from the camera's upper left (intensity 0.7), a fill light from
/// the lower right (0.3, little specular) and a faint rim from behind the top (0.15).
std::vector<Light> default_lights();

struct RenderStyle
{
  /// Samples per pixel along each axis (1 = none; 2 or 3 for anti-aliasing; clamped to 1..4).
  int supersample = 2;
  /// Worker threads, 0 = all cores. The picture does not depend on it.
  int threads = 0;
  std::vector<Light> lights = default_lights();
  double ambient = 0.25;   ///< light reaching every surface, times its colour
  double specular = 0.25;  ///< white highlight strength (Blinn-Phong)
  double shininess = 40.0; ///< Blinn-Phong exponent
  /// Diffuse factor for back faces (shaded with the flipped normal), so the inside of an open
  /// surface is told apart from the outside without looking wrong.
  double back_face_factor = 0.8;
};

} // namespace frep::imaging
