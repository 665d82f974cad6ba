#include "ImageComparison.h"

#include <cstdlib>

namespace frepstudio::testing
{

ImageDifference compare_images(const QImage& a, const QImage& b)
{
  ImageDifference difference;
  difference.same_size = !a.isNull() && a.size() == b.size();
  if (!difference.same_size)
    return difference;
  const QImage x = a.convertToFormat(QImage::Format_RGB32);
  const QImage y = b.convertToFormat(QImage::Format_RGB32);
  double sum = 0;
  long long changed = 0;
  for (int row = 0; row < x.height(); ++row)
  {
    const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(row));
    const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(row));
    for (int column = 0; column < x.width(); ++column)
    {
      const int dr = std::abs(qRed(p[column]) - qRed(q[column]));
      const int dg = std::abs(qGreen(p[column]) - qGreen(q[column]));
      const int db = std::abs(qBlue(p[column]) - qBlue(q[column]));
      sum += dr + dg + db;
      changed += (dr > 32 || dg > 32 || db > 32) ? 1 : 0;
    }
  }
  const double pixels = static_cast<double>(x.width()) * x.height();
  difference.mean = sum / (3 * pixels);
  difference.changed_pixels = changed / pixels;
  return difference;
}

} // namespace frepstudio::testing
