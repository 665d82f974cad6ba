// Reads the pictures frepkit map writes (OpenImageIO) and prints what the tests check:
//   image_file_check cells SPREADSHEET.png MANIFEST.json
//       -> "cells N nonempty K min_coverage C" : per cell of the manifest (its "rect"), the
//          share of pixels that differ from the cell's corner (background) colour
//   image_file_check compare IMAGE.png BASELINE.png
//       -> "width W height H mean_difference M differing_fraction F" (channels 0..1; a pixel
//          differs when a channel is off by more than 0.1)
// Exit code 1 with a message when a file cannot be read or the sizes differ.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace
{

bool read_rgb(const std::string& path, OIIO::ImageBuf& out)
{
  OIIO::ImageBuf in(path);
  if (!in.read(0, 0, true, OIIO::TypeDesc::FLOAT))
  {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), in.geterror().c_str());
    return false;
  }
  out = std::move(in);
  return true;
}

float channel(const OIIO::ImageBuf& image, int x, int y, int c)
{
  float pixel[4] = { 0, 0, 0, 0 };
  image.getpixel(x, y, pixel, 4);
  return pixel[c];
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 4)
  {
    std::fprintf(stderr, "usage: %s cells PNG MANIFEST | compare PNG BASELINE\n", argv[0]);
    return 2;
  }
  const std::string kind = argv[1];
  OIIO::ImageBuf image;
  if (!read_rgb(argv[2], image))
  {
    return 1;
  }
  if (kind == "cells")
  {
    std::ifstream in(argv[3]);
    const nlohmann::json manifest = nlohmann::json::parse(in, nullptr, false);
    if (manifest.is_discarded())
    {
      std::fprintf(stderr, "%s: not JSON\n", argv[3]);
      return 1;
    }
    int cells = 0, nonempty = 0;
    double min_coverage = 1.0;
    for (const auto& file : manifest["files"])
    {
      if (file.value("kind", "") != "spreadsheet")
      {
        continue;
      }
      for (const auto& cell : file["cells"])
      {
        const auto r = cell["rect"];
        const int x0 = r[0], y0 = r[1], w = r[2], h = r[3];
        const float bg[3] = { channel(image, x0 + 1, y0 + 1, 0),
          channel(image, x0 + 1, y0 + 1, 1),
          channel(image, x0 + 1, y0 + 1, 2) };
        long covered = 0;
        for (int y = y0; y < y0 + h; ++y)
        {
          for (int x = x0; x < x0 + w; ++x)
          {
            float p[4];
            image.getpixel(x, y, p, 4);
            covered +=
              std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 0.05;
          }
        }
        const double coverage = static_cast<double>(covered) / (static_cast<double>(w) * h);
        ++cells;
        nonempty += coverage > 0.005;
        min_coverage = std::min(min_coverage, coverage);
      }
    }
    std::printf("cells %d nonempty %d min_coverage %.4f\n", cells, nonempty, min_coverage);
    return 0;
  }
  if (kind == "compare")
  {
    OIIO::ImageBuf baseline;
    if (!read_rgb(argv[3], baseline))
    {
      return 1;
    }
    const auto& a = image.spec();
    const auto& b = baseline.spec();
    if (a.width != b.width || a.height != b.height)
    {
      std::fprintf(stderr, "sizes differ: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
      return 1;
    }
    double sum = 0;
    long differing = 0;
    const int channels = std::min({ a.nchannels, b.nchannels, 3 });
    for (int y = 0; y < a.height; ++y)
    {
      for (int x = 0; x < a.width; ++x)
      {
        float p[4], q[4];
        image.getpixel(x, y, p, 4);
        baseline.getpixel(x, y, q, 4);
        float worst = 0;
        for (int c = 0; c < channels; ++c)
        {
          const float d = std::abs(p[c] - q[c]);
          sum += d;
          worst = std::max(worst, d);
        }
        differing += worst > 0.1f;
      }
    }
    const double n = static_cast<double>(a.width) * a.height;
    std::printf("width %d height %d mean_difference %.6f differing_fraction %.6f\n",
      a.width,
      a.height,
      sum / (n * channels),
      differing / n);
    return 0;
  }
  std::fprintf(stderr, "unknown kind %s\n", kind.c_str());
  return 2;
}
