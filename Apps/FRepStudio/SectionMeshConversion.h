// The engine's mesh (frep::mesh::Surface) as vtkPolyData for display: points, triangles (or the
// segments of a 2-D contour), the mesher's normals, and colours from the model's s[] attributes.
#pragma once

#include "Compiler/tape.h"
#include "Mesh/surface.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace frepstudio
{

/// How the section is coloured.
enum class SectionColouring
{
  Plain,     ///< the actor's colour
  Rgb,       ///< s[1..3] are red, green, blue in [0, 1] (hfp -ct): array "Colors", direct
  Attribute  ///< s[1] only: array "s1", mapped through the lookup table
};

/// Which colouring a tape's attributes call for: Rgb when the object has s[3] or more and sets
/// one of them (frepkit's rule), Attribute when it sets s[1], else Plain.
SectionColouring colouring_for(const frep::Tape& tape, int s_dim);

/// Converts a surface (3-D triangles or 2-D segments) to vtkPolyData. Runs on any thread: the
/// result is not shared until it is handed to the view.
vtkSmartPointer<vtkPolyData> to_poly_data(const frep::mesh::Surface& surface,
  SectionColouring colouring);

} // namespace frepstudio
