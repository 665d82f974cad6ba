// Headless-safe screenshots: wait until the window has settled (text analysed, refined section
// on screen), grab it, and composite the VTK view's own read-back over the view's area.
#pragma once

#include <QImage>
#include <QString>

namespace frepstudio
{

class StudioMainWindow;

/// Processes events until `window` is settled or `timeout_ms` passes; false on timeout.
bool wait_until_settled(StudioMainWindow& window, int timeout_ms);

/// The whole window as it is on screen, the 3-D view included.
QImage capture_window(StudioMainWindow& window);

/// Fraction of the pixels that are not black. The view's background is a grey-blue gradient, so
/// a proper frame is close to 1; a failed read-back or composition is black (close to 0).
double non_black_fraction(const QImage& picture);

/// Settles, captures and writes `path`. Returns an empty string or why it failed.
QString write_screenshot(StudioMainWindow& window, const QString& path, int timeout_ms);

} // namespace frepstudio
