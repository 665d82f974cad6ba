// The PNG writer of a build without libpng.
#include "Imaging/png_writer.h"

namespace frep::imaging
{

void write_png(std::ostream&, std::int64_t, std::int64_t, const std::vector<std::uint8_t>&)
{
  throw PngError(".png is not available in this build (it was built without libpng)");
}

void write_png(std::ostream& out, const Image&)
{
  write_png(out, 0, 0, {});
}

} // namespace frep::imaging
