// The PNG writer of a build without OpenImageIO.
#include "png_writer.h"

#include "user_error.h"

namespace frepkit
{

void write_png(std::ostream&, std::int64_t, std::int64_t, const std::vector<std::uint8_t>&)
{
  throw UserError(
    ".png is not available in this build (it was built without libpng)");
}

} // namespace frepkit
