// The .vti writer of a build without VTK (FREPKIT_ENABLE_VTK off).
#include "vti_writer.h"

#include "user_error.h"

namespace frepkit
{

void write_vti(std::ostream&, const SampledSection&)
{
  throw UserError(
    ".vti (VTK XML ImageData) is not available in this build (FREPKIT_ENABLE_VTK is off)");
}

} // namespace frepkit
