// VTK XML ImageData (.vti) of a sampled section through vtkXMLImageDataWriter: point arrays "F"
// (double, the active scalars; NaN where the model failed) and "s1".."sN" when sampled. The
// image's axes are the free coordinates in order; a 2-D section has one slice (z extent 0).
#pragma once

#include "section_image.h"

#include <ostream>

namespace frepkit
{

void write_vti(std::ostream& out, const SampledSection& section);

} // namespace frepkit
