// Picture comparison for the screenshot tests: same size, and a small mean difference (llvmpipe
// is deterministic on one machine, but fonts and drivers may shift a few pixels elsewhere).
#pragma once

#include <QImage>
#include <QString>

namespace frepstudio::testing
{

struct ImageDifference
{
  bool same_size = false;
  double mean = 0;          ///< mean |a - b| per channel, 0..255
  double changed_pixels = 0; ///< fraction of pixels with a channel differing by more than 32
};

ImageDifference compare_images(const QImage& a, const QImage& b);

} // namespace frepstudio::testing
