// The path panel: a path through two coordinates beyond x1..x3 (default x4, x5), drawn and
// edited on their plane, and its animation: play / pause and a scrub slider that move the
// sliders along it (constant speed, Mapping/Core's SampledPath: polyline or centripetal
// Catmull-Rom, open or closed). Left click adds a control point at the end, dragging moves one,
// right click removes one. While playing only coarse sections are made; the refined one follows
// when the animation pauses (the main window's rest timer).
#pragma once

#include "Mapping/path.h"

#include <QTimer>
#include <QWidget>

#include <array>
#include <map>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;

namespace frepstudio
{

class PathCanvas;

class PathPanel : public QWidget
{
  Q_OBJECT
public:
  explicit PathPanel(QWidget* parent = nullptr);

  /// The coordinates beyond x1..x3 of the current object (x4.. with their ranges). With fewer
  /// than two the panel is disabled.
  void setCoordinates(const std::vector<std::array<double, 2>>& extra_ranges);
  /// Control points in model units of the two chosen coordinates.
  void setControlPoints(const std::vector<std::array<double, 2>>& points);
  const std::vector<std::array<double, 2>>& controlPoints() const { return points_; }
  /// Takes a mapping's path when it runs through two coordinates (e.g. "x4", "x5").
  void setPath(const frep::mapping::Path& path);
  /// The path as the Mapping module describes it (coordinates, points, interpolation, closed).
  frep::mapping::Path path() const;

  /// Position along the path, 0..1 (arc-length fraction).
  double position() const;
  void setPosition(double s);
  void play();
  void pause();
  bool isPlaying() const { return timer_.isActive(); }
  QSlider* scrubSlider() const { return scrub_; }
  PathCanvas* canvas() const { return canvas_; }
  /// The two coordinates (indices into x4..: 0 = x4).
  std::array<int, 2> axes() const;
  std::array<double, 2> range(int which) const;

signals:
  /// Move the sliders: coordinate name -> value.
  void positionChanged(const std::map<std::string, double>& values);

private:
  void resample();
  void emitPosition();

  friend class PathCanvas;
  std::vector<std::array<double, 2>> extra_ranges_;
  std::vector<std::array<double, 2>> points_;
  frep::mapping::SampledPath sampled_;
  bool sampled_ok_ = false;
  QComboBox* first_ = nullptr;
  QComboBox* second_ = nullptr;
  QCheckBox* closed_ = nullptr;
  QCheckBox* smooth_ = nullptr;
  QDoubleSpinBox* duration_ = nullptr;
  QPushButton* play_ = nullptr;
  QSlider* scrub_ = nullptr;
  QLabel* status_ = nullptr;
  PathCanvas* canvas_ = nullptr;
  QTimer timer_;
};

/// The plane of the two coordinates: control points, the curve, the current position.
class PathCanvas : public QWidget
{
  Q_OBJECT
public:
  explicit PathCanvas(PathPanel* panel);
  /// Model units <-> widget pixels.
  QPointF toPixels(const std::array<double, 2>& point) const;
  std::array<double, 2> toModel(const QPointF& pixel) const;

protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  QSize sizeHint() const override { return { 260, 260 }; }

private:
  int pointNear(const QPointF& pixel) const;
  QRectF plot() const;
  PathPanel* panel_;
  int dragging_ = -1;
};

} // namespace frepstudio
