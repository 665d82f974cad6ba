#include "SpreadsheetPanel.h"

#include "Eval/thread_pool.h"

#include <algorithm>

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QResizeEvent>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace frepstudio
{

SpreadsheetPanel::SpreadsheetPanel(QWidget* parent)
  : QWidget(parent)
  , engine_pool_(std::make_shared<frep::ThreadPool>(0))
{
  jobs_.setMaxThreadCount(1);
  auto* layout = new QVBoxLayout(this);
  auto* controls = new QHBoxLayout;
  controls->addWidget(new QLabel(tr("Rows:"), this));
  rows_ = new QComboBox(this);
  rows_->setObjectName("spreadsheetRows");
  controls->addWidget(rows_);
  controls->addWidget(new QLabel(tr("Columns:"), this));
  columns_ = new QComboBox(this);
  columns_->setObjectName("spreadsheetColumns");
  controls->addWidget(columns_);
  controls->addWidget(new QLabel(tr("Steps:"), this));
  steps_ = new QSpinBox(this);
  steps_->setObjectName("spreadsheetSteps");
  steps_->setRange(2, 9);
  steps_->setValue(5); // the paper's 5 x 5: x4, x5 in 0, 0.25 ... 1
  controls->addWidget(steps_);
  controls->addStretch(1);
  layout->addLayout(controls);
  // On the status line, not beside the combo boxes: a wider row would widen the tab widget
  // (its minimum is its widest page's) and move the window's splitter.
  auto* status_row = new QHBoxLayout;
  status_ = new QLabel(this);
  status_row->addWidget(status_, 1);
  raycast_ = new QCheckBox(tr("Ray-cast"), this);
  raycast_->setObjectName("spreadsheetRaycast");
  raycast_->setToolTip(tr("Draw the cells by rays from the function itself (no facets, no "
                          "detail lost below the grid) instead of meshing them"));
  status_row->addWidget(raycast_);
  layout->addLayout(status_row);

  scroll_ = new QScrollArea(this);
  grid_widget_ = new QWidget(scroll_);
  grid_ = new QGridLayout(grid_widget_);
  grid_->setSpacing(2);
  scroll_->setWidget(grid_widget_);
  scroll_->setWidgetResizable(true);
  layout->addWidget(scroll_, 1);

  connect(rows_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] { rebuild(); });
  connect(columns_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] { rebuild(); });
  connect(steps_, qOverload<int>(&QSpinBox::valueChanged), this, [this] { rebuild(); });
  connect(raycast_, &QCheckBox::toggled, this, [this] { rebuild(); });
}

SpreadsheetPanel::~SpreadsheetPanel()
{
  generation_.fetch_add(1);
  jobs_.waitForDone();
}

int SpreadsheetPanel::steps() const
{
  return steps_->value();
}

void SpreadsheetPanel::setSteps(int steps)
{
  steps_->setValue(steps);
}

bool SpreadsheetPanel::raycast() const
{
  return raycast_->isChecked();
}

void SpreadsheetPanel::setRaycast(bool raycast)
{
  raycast_->setChecked(raycast);
}

int SpreadsheetPanel::rowCoordinate() const
{
  return rows_->currentData().isValid() ? rows_->currentData().toInt() : -1;
}

int SpreadsheetPanel::columnCoordinate() const
{
  return columns_->currentData().isValid() ? columns_->currentData().toInt() : -1;
}

QToolButton* SpreadsheetPanel::cell(int row, int column) const
{
  const int columns = columnCoordinate() >= 0 ? steps() : 1;
  const int index = row * columns + column;
  return index >= 0 && index < static_cast<int>(cells_.size()) ? cells_[index] : nullptr;
}

void SpreadsheetPanel::updateAxisChoices()
{
  const int extra = static_cast<int>(sheet_.extra_ranges.size());
  if (rows_->count() == std::max(extra, 0) && columns_->count() == extra + 1)
    return; // same coordinates: keep the user's choice
  QSignalBlocker block_rows(rows_);
  QSignalBlocker block_columns(columns_);
  rows_->clear();
  columns_->clear();
  columns_->addItem(tr("(none)"));
  for (int k = 0; k < extra; ++k)
  {
    const QString name = QString("x%1").arg(k + 4);
    rows_->addItem(name, k);
    columns_->addItem(name, k);
  }
  // Default: rows x5, columns x4 when there are two (the paper's layout), else rows x4.
  rows_->setCurrentIndex(extra >= 2 ? 1 : 0);
  columns_->setCurrentIndex(extra >= 2 ? 1 : 0);
}

bool SpreadsheetPanel::sameGrid(const Sheet& sheet) const
{
  if (!has_sheet_ || sheet.base.model != sheet_.base.model ||
    sheet.base.parameters != sheet_.base.parameters || sheet.base.lo != sheet_.base.lo ||
    sheet.base.hi != sheet_.base.hi || sheet.extra_ranges != sheet_.extra_ranges ||
    sheet.base.fixed_values.size() != sheet_.base.fixed_values.size())
    return false;
  for (int k = 0; k < static_cast<int>(sheet.base.fixed_values.size()); ++k)
    if (k != rowCoordinate() && k != columnCoordinate() &&
      sheet.base.fixed_values[k] != sheet_.base.fixed_values[k])
      return false;
  return true;
}

void SpreadsheetPanel::setSheet(const Sheet& sheet)
{
  const bool same = sameGrid(sheet);
  sheet_ = sheet;
  has_sheet_ = true;
  updateAxisChoices();
  if (same)
    return;
  cells_empty_pending_ = true;
  if (isVisible())
    rebuild();
}

void SpreadsheetPanel::showEvent(QShowEvent* event)
{
  QWidget::showEvent(event);
  if (has_sheet_ && (cells_.empty() || cells_empty_pending_))
    rebuild();
}

void SpreadsheetPanel::resizeEvent(QResizeEvent* event)
{
  QWidget::resizeEvent(event);
  fitCells();
}

void SpreadsheetPanel::fitCells()
{
  constexpr int kMinimumCellPixels = 32;
  constexpr int kFrame = 8; // the button around its picture
  if (cells_.empty() || cell_columns_ < 1)
    return;
  int header = 0;
  for (int r = 1; r < grid_->rowCount(); ++r)
  {
    if (QLayoutItem* item = grid_->itemAtPosition(r, 0); item && item->widget())
      header = std::max(header, item->widget()->sizeHint().width());
  }
  const QMargins margins = grid_->contentsMargins();
  const int available = scroll_->viewport()->width() - margins.left() - margins.right() - header -
    grid_->horizontalSpacing() * cell_columns_;
  const int pixels = std::clamp(available / cell_columns_ - kFrame, kMinimumCellPixels,
    sheet_.base.pixels);
  for (QToolButton* button : cells_)
  {
    button->setFixedSize(pixels + kFrame, pixels + kFrame);
    button->setIconSize(QSize(pixels, pixels));
  }
}

void SpreadsheetPanel::rebuild()
{
  const std::uint64_t generation = generation_.fetch_add(1) + 1;
  cells_empty_pending_ = false;
  cells_.clear(); // the buttons are the grid's: deleted with its items below
  finished_ = 0;
  while (QLayoutItem* item = grid_->takeAt(0))
  {
    delete item->widget();
    delete item;
  }
  const int row_axis = rowCoordinate();
  const int column_axis = columnCoordinate();
  if (!has_sheet_ || !sheet_.base.model || row_axis < 0)
  {
    status_->setText(tr("The spreadsheet needs a model with a coordinate beyond x1..x3."));
    return;
  }
  const int n = steps();
  const int columns = column_axis >= 0 ? n : 1;
  auto value_of = [this](int axis, int step, int n) {
    const auto range = sheet_.extra_ranges[axis];
    return range[0] + (range[1] - range[0]) * step / (n - 1);
  };
  // Column headers along the top, row headers on the left.
  for (int c = 0; c < columns && column_axis >= 0; ++c)
    grid_->addWidget(new QLabel(QString("x%1 = %2").arg(column_axis + 4).arg(
                                  value_of(column_axis, c, n)), grid_widget_),
      0, c + 1, Qt::AlignCenter);
  SheetRequest request;
  request.base = sheet_.base;
  request.base.raycast = raycast();
  request.row_coordinate = row_axis;
  request.column_coordinate = column_axis;
  for (int step = 0; step < n; ++step)
  {
    request.row_values.push_back(value_of(row_axis, step, n));
    if (column_axis >= 0)
      request.column_values.push_back(value_of(column_axis, step, n));
  }
  for (int r = 0; r < n; ++r)
  {
    grid_->addWidget(
      new QLabel(QString("x%1 = %2").arg(row_axis + 4).arg(request.row_values[r]), grid_widget_),
      r + 1,
      0,
      Qt::AlignRight | Qt::AlignVCenter);
    for (int c = 0; c < columns; ++c)
    {
      std::map<std::string, double> values;
      values["x" + std::to_string(row_axis + 4)] = request.row_values[r];
      if (column_axis >= 0)
        values["x" + std::to_string(column_axis + 4)] = request.column_values[c];
      auto* button = new QToolButton(grid_widget_);
      button->setFixedSize(request.base.pixels + 8, request.base.pixels + 8);
      button->setIconSize(QSize(request.base.pixels, request.base.pixels));
      button->setToolTip(tr("Click: move the sliders here"));
      connect(button, &QToolButton::clicked, this, [this, values] { emit cellActivated(values); });
      grid_->addWidget(button, r + 1, c + 1);
      cells_.push_back(button);
    }
  }
  cell_columns_ = columns;
  fitCells();
  status_->setText(tr("Framing %1 cells...").arg(cells_.size()));

  // One job for the whole grid: the sheet's plan and framing (one camera for every cell), then
  // cell by cell in reading order; each finished cell is posted to the UI thread, where it is
  // dropped if a newer grid has replaced this one meanwhile.
  jobs_.start(
    [this, generation, request = std::move(request), previous = last_framing_]
    {
      auto keep_going = [this, generation] { return generation_.load() == generation; };
      auto post_error = [this, generation](const std::string& error)
      {
        QMetaObject::invokeMethod(
          this,
          [this, generation, error]
          {
            if (generation_.load() == generation)
              status_->setText(
                tr("The spreadsheet cannot be drawn: %1").arg(QString::fromStdString(error)));
          },
          Qt::QueuedConnection);
      };
      auto framing_progress = [this, generation, cells = request.row_values.size() *
                                          std::max<std::size_t>(1, request.column_values.size())](
                                double fraction)
      {
        QMetaObject::invokeMethod(
          this,
          [this, generation, cells, fraction]
          {
            if (generation_.load() == generation && finished_ == 0)
              status_->setText(tr("Framing %1 cells: %2%").arg(cells).arg(
                static_cast<int>(100.0 * fraction)));
          },
          Qt::QueuedConnection);
      };
      std::string error;
      const std::unique_ptr<SheetRenderer> renderer = SheetRenderer::prepare(
        request, engine_pool_, keep_going, &error, previous, framing_progress);
      if (!renderer)
      {
        if (!error.empty())
          post_error(error);
        return;
      }
      QMetaObject::invokeMethod(
        this,
        [this, framing = renderer->framing()] { last_framing_ = framing; },
        Qt::QueuedConnection);
      for (std::size_t i = 0; i < renderer->cellCount() && keep_going(); ++i)
      {
        QImage picture = renderer->cell(i, keep_going, &error);
        if (!error.empty())
          return post_error(error);
        QMetaObject::invokeMethod(
          this,
          [this, generation, i, picture]
          {
            if (generation_.load() != generation || i >= cells_.size())
              return;
            cells_[i]->setIcon(QPixmap::fromImage(picture));
            ++finished_;
            status_->setText(finished_ == static_cast<int>(cells_.size())
                               ? tr("%1 cells. Click one to move the sliders there.").arg(finished_)
                               : tr("Computing: %1 of %2 cells").arg(finished_).arg(cells_.size()));
          },
          Qt::QueuedConnection);
      }
    });
}

} // namespace frepstudio
