// The .vtp writer of a build without VTK (FREPKIT_ENABLE_VTK off).
#include "vtp_writer.h"

#include "user_error.h"

namespace frepkit
{

void write_vtp(const MeshDocument&, std::ostream&)
{
  throw UserError(
    ".vtp (VTK XML PolyData) is not available in this build (FREPKIT_ENABLE_VTK is off)");
}

} // namespace frepkit
