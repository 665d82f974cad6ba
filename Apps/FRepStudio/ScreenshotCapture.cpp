#include "ScreenshotCapture.h"

#include "DurableSave.h"
#include "SectionView.h"
#include "StudioMainWindow.h"

#include <QApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <QPainter>
#include <QThread>
#include <QVTKOpenGLNativeWidget.h>

namespace frepstudio
{

bool wait_until_settled(StudioMainWindow& window, int timeout_ms)
{
  QElapsedTimer clock;
  clock.start();
  // Settled must hold twice in a row, a few ms apart: an analysis that just finished may post
  // the request that makes the window busy again.
  int settled_in_a_row = 0;
  while (clock.elapsed() < timeout_ms)
  {
    QApplication::processEvents(QEventLoop::AllEvents, 20);
    settled_in_a_row = window.isSettled() ? settled_in_a_row + 1 : 0;
    if (settled_in_a_row >= 3)
      return true;
    QThread::msleep(5);
  }
  return false;
}

QImage capture_window(StudioMainWindow& window)
{
  QImage picture = window.grab().toImage().convertToFormat(QImage::Format_RGB888);
  // QWidget::grab() paints the QOpenGLWidget from its last frame, which is black on some
  // platforms (no composition of GL widgets); VTK's read-back of its framebuffer always holds
  // the frame. Paint it over the view's rectangle.
  SectionView* view = window.sectionView();
  const QImage frame = view->isVisible() ? view->renderToImage() : QImage();
  if (!frame.isNull())
  {
    const QPoint origin = view->vtkWidget()->mapTo(&window, QPoint(0, 0));
    const qreal ratio = picture.devicePixelRatio();
    QPainter painter(&picture);
    painter.drawImage(QRectF(origin * ratio, QSizeF(view->vtkWidget()->size()) * ratio), frame);
  }
  return picture;
}

double non_black_fraction(const QImage& picture)
{
  if (picture.isNull())
    return 0;
  const QImage image = picture.convertToFormat(QImage::Format_RGB32);
  long long lit = 0;
  for (int y = 0; y < image.height(); ++y)
  {
    const auto* row = reinterpret_cast<const QRgb*>(image.constScanLine(y));
    for (int x = 0; x < image.width(); ++x)
      lit += std::max({ qRed(row[x]), qGreen(row[x]), qBlue(row[x]) }) > 8 ? 1 : 0;
  }
  return static_cast<double>(lit) / (static_cast<double>(image.width()) * image.height());
}

QString write_screenshot(StudioMainWindow& window, const QString& path, int timeout_ms)
{
  if (!wait_until_settled(window, timeout_ms))
    return QStringLiteral("the refined section was not ready within %1 s").arg(timeout_ms / 1000);
  const bool view_shown = window.sectionView()->isVisible();
  const QImage frame = view_shown ? window.sectionView()->renderToImage() : QImage();
  if (view_shown && non_black_fraction(frame) < 0.5)
    return QStringLiteral("the 3-D view rendered black (no OpenGL frame to read back)");
  const QImage picture = capture_window(window);
  if (non_black_fraction(picture) < 0.5)
    return QStringLiteral("the window grab is black");
  if (const QString problem = saveImageDurably(path, picture); !problem.isEmpty())
    return QStringLiteral("cannot write %1: %2").arg(path, problem);
  return {};
}

} // namespace frepstudio
