#include "PathPanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace frepstudio
{

namespace
{
constexpr int kScrubSteps = 1000;
constexpr int kFrameMs = 40; // 25 frames per second while playing
}

PathPanel::PathPanel(QWidget* parent)
  : QWidget(parent)
{
  auto* layout = new QVBoxLayout(this);
  auto* axes = new QHBoxLayout;
  first_ = new QComboBox(this);
  second_ = new QComboBox(this);
  axes->addWidget(new QLabel(tr("Across:"), this));
  axes->addWidget(first_);
  axes->addWidget(new QLabel(tr("Up:"), this));
  axes->addWidget(second_);
  axes->addStretch(1);
  layout->addLayout(axes);

  canvas_ = new PathCanvas(this);
  canvas_->setObjectName("pathCanvas");
  layout->addWidget(canvas_, 1);

  auto* options = new QHBoxLayout;
  closed_ = new QCheckBox(tr("Closed"), this);
  closed_->setChecked(true);
  smooth_ = new QCheckBox(tr("Smooth"), this);
  smooth_->setToolTip(tr("Centripetal Catmull-Rom through the control points; off: a polyline"));
  smooth_->setChecked(true);
  duration_ = new QDoubleSpinBox(this);
  duration_->setRange(0.5, 600);
  duration_->setValue(10);
  duration_->setSuffix(tr(" s"));
  duration_->setToolTip(tr("Time for the whole path"));
  options->addWidget(closed_);
  options->addWidget(smooth_);
    options->addWidget(duration_);
  options->addStretch(1);
  layout->addLayout(options);

  auto* transport = new QHBoxLayout;
  play_ = new QPushButton(tr("Play"), this);
  play_->setObjectName("pathPlay");
  scrub_ = new QSlider(Qt::Horizontal, this);
  scrub_->setObjectName("pathScrub");
  scrub_->setRange(0, kScrubSteps);
  transport->addWidget(play_);
  transport->addWidget(scrub_, 1);
  layout->addLayout(transport);
  status_ = new QLabel(this);
  layout->addWidget(status_);

  // The paper's path in the (x4, x5) unit square (Examples/homotopic/homotopic.json).
  points_ = { { 0.1, 0.1 }, { 0.5, 0.5 }, { 0.9, 0.1 }, { 0.9, 0.9 }, { 0.5, 0.5 }, { 0.1, 0.9 } };

  connect(play_, &QPushButton::clicked, this, [this] { isPlaying() ? pause() : play(); });
  connect(scrub_, &QSlider::valueChanged, this, [this] {
    emitPosition();
    canvas_->update();
  });
  connect(&timer_, &QTimer::timeout, this, [this] {
    const double step = kFrameMs / 1000.0 / duration_->value();
    double s = position() + step;
    if (s > 1)
      s = closed_->isChecked() ? s - 1 : 1;
    setPosition(s);
    if (!closed_->isChecked() && s >= 1)
      pause();
  });
  for (QCheckBox* box : { closed_, smooth_ })
    connect(box, &QCheckBox::toggled, this, [this] { resample(); });
  for (QComboBox* box : { first_, second_ })
    connect(box, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] {
      resample();
      emitPosition();
    });
  setCoordinates({});
}

void PathPanel::setCoordinates(const std::vector<std::array<double, 2>>& extra_ranges)
{
  const bool same = extra_ranges == extra_ranges_;
  extra_ranges_ = extra_ranges;
  if (!same)
  {
    QSignalBlocker block_first(first_);
    QSignalBlocker block_second(second_);
    first_->clear();
    second_->clear();
    for (std::size_t k = 0; k < extra_ranges.size(); ++k)
    {
      first_->addItem(QString("x%1").arg(k + 4), static_cast<int>(k));
      second_->addItem(QString("x%1").arg(k + 4), static_cast<int>(k));
    }
    if (extra_ranges.size() >= 2)
    {
      first_->setCurrentIndex(0);
      second_->setCurrentIndex(1);
    }
  }
  const bool usable = extra_ranges.size() >= 2;
  setEnabled(usable);
  if (!usable)
    pause();
  resample();
}

std::array<int, 2> PathPanel::axes() const
{
  return { first_->currentData().isValid() ? first_->currentData().toInt() : -1,
    second_->currentData().isValid() ? second_->currentData().toInt() : -1 };
}

std::array<double, 2> PathPanel::range(int which) const
{
  const int axis = axes()[which];
  return axis >= 0 && axis < static_cast<int>(extra_ranges_.size()) ? extra_ranges_[axis]
                                                                    : std::array{ 0.0, 1.0 };
}

void PathPanel::setControlPoints(const std::vector<std::array<double, 2>>& points)
{
  points_ = points;
  resample();
}

void PathPanel::setPath(const frep::mapping::Path& path)
{
  if (path.coordinates.size() != 2 || path.points.size() < 2)
    return;
  for (int which = 0; which < 2; ++which)
  {
    QComboBox* box = which == 0 ? first_ : second_;
    const int index = box->findText(QString::fromStdString(path.coordinates[which]));
    if (index < 0)
      return;
    QSignalBlocker block(box);
    box->setCurrentIndex(index);
  }
  std::vector<std::array<double, 2>> points;
  for (const auto& p : path.points)
    if (p.size() == 2)
      points.push_back({ p[0], p[1] });
  QSignalBlocker block_closed(closed_);
  QSignalBlocker block_smooth(smooth_);
  closed_->setChecked(path.closed);
  smooth_->setChecked(path.interpolation == frep::mapping::Path::Interpolation::CatmullRom);
  setControlPoints(points);
}

frep::mapping::Path PathPanel::path() const
{
  frep::mapping::Path path;
  const auto a = axes();
  if (a[0] >= 0 && a[1] >= 0)
    path.coordinates = { "x" + std::to_string(a[0] + 4), "x" + std::to_string(a[1] + 4) };
  for (const auto& p : points_)
    path.points.push_back({ p[0], p[1] });
  path.closed = closed_->isChecked();
  path.interpolation = smooth_->isChecked() ? frep::mapping::Path::Interpolation::CatmullRom
                                            : frep::mapping::Path::Interpolation::Polyline;
  return path;
}

void PathPanel::resample()
{
  auto result = frep::mapping::SampledPath::make(path());
  sampled_ok_ = result.ok() && axes()[0] >= 0 && axes()[1] >= 0 && axes()[0] != axes()[1];
  if (result.ok())
    sampled_ = std::move(result.path);
  status_->setText(!sampled_ok_ && !result.errors.empty()
      ? QString::fromStdString("path " + result.errors.front().place + ": " +
          result.errors.front().message)
      : (axes()[0] == axes()[1] && axes()[0] >= 0 ? tr("Choose two different coordinates.")
                                                   : tr("%n control point(s)", nullptr,
                                                       static_cast<int>(points_.size()))));
  canvas_->update();
}

double PathPanel::position() const
{
  return static_cast<double>(scrub_->value()) / kScrubSteps;
}

void PathPanel::setPosition(double s)
{
  scrub_->setValue(static_cast<int>(std::lround(std::clamp(s, 0.0, 1.0) * kScrubSteps)));
}

void PathPanel::play()
{
  if (!sampled_ok_)
    return;
  timer_.start(kFrameMs);
  play_->setText(tr("Pause"));
}

void PathPanel::pause()
{
  timer_.stop();
  play_->setText(tr("Play"));
}

void PathPanel::emitPosition()
{
  if (!sampled_ok_ || !isEnabled())
    return;
  const std::vector<double> point = sampled_.point_at(position());
  const auto a = axes();
  emit positionChanged({ { "x" + std::to_string(a[0] + 4), point[0] },
    { "x" + std::to_string(a[1] + 4), point[1] } });
}

// --- the canvas -------------------------------------------------------------------------------

PathCanvas::PathCanvas(PathPanel* panel)
  : QWidget(panel)
  , panel_(panel)
{
  setMinimumSize(180, 180);
  setMouseTracking(false);
}

QRectF PathCanvas::plot() const
{
  const double side = std::min(width(), height()) - 24.0;
  return { (width() - side) / 2, (height() - side) / 2, side, side };
}

QPointF PathCanvas::toPixels(const std::array<double, 2>& point) const
{
  const QRectF r = plot();
  const auto h = panel_->range(0), v = panel_->range(1);
  return { r.left() + (point[0] - h[0]) / (h[1] - h[0]) * r.width(),
    r.bottom() - (point[1] - v[0]) / (v[1] - v[0]) * r.height() };
}

std::array<double, 2> PathCanvas::toModel(const QPointF& pixel) const
{
  const QRectF r = plot();
  const auto h = panel_->range(0), v = panel_->range(1);
  const double x = std::clamp((pixel.x() - r.left()) / r.width(), 0.0, 1.0);
  const double y = std::clamp((r.bottom() - pixel.y()) / r.height(), 0.0, 1.0);
  return { h[0] + x * (h[1] - h[0]), v[0] + y * (v[1] - v[0]) };
}

int PathCanvas::pointNear(const QPointF& pixel) const
{
  for (int i = 0; i < static_cast<int>(panel_->points_.size()); ++i)
    if (QLineF(toPixels(panel_->points_[i]), pixel).length() <= 7)
      return i;
  return -1;
}

void PathCanvas::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.fillRect(rect(), palette().window());
  const QRectF r = plot();
  // A checkerboard, like the paper's inset: where on the plane the animation is.
  const int squares = 8;
  for (int i = 0; i < squares; ++i)
    for (int j = 0; j < squares; ++j)
      painter.fillRect(QRectF(r.left() + i * r.width() / squares, r.top() + j * r.height() / squares,
                         r.width() / squares, r.height() / squares),
        (i + j) % 2 ? QColor(0xe8, 0xe8, 0xe8) : QColor(0xd0, 0xd0, 0xd0));
  painter.setPen(QPen(Qt::darkGray, 1));
  painter.drawRect(r);
  const auto a = panel_->axes();
  if (a[0] >= 0 && a[1] >= 0)
  {
    painter.setPen(Qt::black);
    painter.drawText(QRectF(r.left(), r.bottom(), r.width(), 12), Qt::AlignCenter,
      QString("x%1").arg(a[0] + 4));
    painter.drawText(QRectF(0, r.top(), r.left() - 2, r.height()), Qt::AlignCenter,
      QString("x%1").arg(a[1] + 4));
  }
  if (panel_->sampled_ok_)
  {
    QPainterPath curve;
    const auto line = panel_->sampled_.polyline(200);
    for (std::size_t i = 0; i < line.size(); ++i)
    {
      const QPointF p = toPixels({ line[i][0], line[i][1] });
      i == 0 ? curve.moveTo(p) : curve.lineTo(p);
    }
    painter.setPen(QPen(QColor(0x20, 0x60, 0xc0), 2));
    painter.drawPath(curve);
    const auto now = panel_->sampled_.point_at(panel_->position());
    painter.setBrush(Qt::red);
    painter.setPen(Qt::NoPen);
    painter.drawEllipse(toPixels({ now[0], now[1] }), 6, 6);
  }
  painter.setBrush(Qt::white);
  painter.setPen(QPen(Qt::black, 1.5));
  for (const auto& point : panel_->points_)
    painter.drawEllipse(toPixels(point), 4.5, 4.5);
}

void PathCanvas::mousePressEvent(QMouseEvent* event)
{
  int near = pointNear(event->pos());
  if (event->button() == Qt::RightButton && near >= 0)
  {
    panel_->points_.erase(panel_->points_.begin() + near);
    panel_->resample();
  }
  else if (event->button() == Qt::LeftButton)
  {
    if (near < 0)
    {
      panel_->points_.push_back(toModel(event->pos()));
      near = static_cast<int>(panel_->points_.size()) - 1;
      panel_->resample();
    }
    dragging_ = near;
  }
}

void PathCanvas::mouseMoveEvent(QMouseEvent* event)
{
  if (dragging_ < 0 || dragging_ >= static_cast<int>(panel_->points_.size()))
    return;
  panel_->points_[dragging_] = toModel(event->pos());
  panel_->resample();
}

void PathCanvas::mouseReleaseEvent(QMouseEvent*)
{
  if (dragging_ >= 0)
    panel_->emitPosition(); // the path moved under the current position
  dragging_ = -1;
}

} // namespace frepstudio
