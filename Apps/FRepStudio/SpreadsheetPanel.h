// The spreadsheet: a grid of cross-sections over two chosen coordinates beyond x1..x3 (rows and
// columns), `steps` values each spread over their ranges, the other coordinates at the sliders'
// values. Cells are made on a worker thread (SpreadsheetRenderer) and appear as they finish; a
// newer layout cancels the older. Clicking a cell moves the sliders to its values.
#pragma once

#include "SpreadsheetRenderer.h"

#include <QThreadPool>
#include <QWidget>

#include <atomic>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QGridLayout;
class QLabel;
class QScrollArea;
class QSpinBox;
class QToolButton;

namespace frepstudio
{

class SpreadsheetPanel : public QWidget
{
  Q_OBJECT
public:
  explicit SpreadsheetPanel(QWidget* parent = nullptr);
  ~SpreadsheetPanel() override;

  /// What to lay out: the model, its coordinates beyond x1..x3 with their ranges, and the
  /// current values of all of them (the coordinates that are not rows or columns keep these).
  struct Sheet
  {
    CellRequest base;                                 ///< fixed_values = the sliders' values
    std::vector<std::array<double, 2>> extra_ranges;  ///< x4..xn
  };
  /// Lays the grid out again (cancelling what runs) when the panel is visible and the sheet
  /// differs from the current one in more than the row and column coordinates' values (moving
  /// those sliders does not change the grid); a hidden panel keeps it for when it is shown.
  void setSheet(const Sheet& sheet);

  /// Cells per axis; the row and column coordinates (indices into x4..: 0 = x4; -1 = none).
  int steps() const;
  void setSteps(int steps);
  /// Cells drawn by rays (the "Ray-cast" box) instead of meshed; default off.
  bool raycast() const;
  void setRaycast(bool raycast);
  int rowCoordinate() const;
  int columnCoordinate() const;
  /// Finished cells and all cells of the current grid (for tests and the status line).
  int finishedCells() const { return finished_; }
  int cellCount() const { return static_cast<int>(cells_.size()); }
  /// The button of cell (row, column), or null.
  QToolButton* cell(int row, int column) const;
  bool isComputing() const { return finished_ < static_cast<int>(cells_.size()); }

signals:
  /// A cell was clicked: set these coordinates ("x4", "x5") to these values.
  void cellActivated(const std::map<std::string, double>& values);

protected:
  void showEvent(QShowEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

private:
  void rebuild();
  /// Cells as large as their pictures (CellRequest::pixels) when the width allows, else shrunk
  /// (down to kMinimumCellPixels) so that every column fits the visible width: the pictures are
  /// scaled down, not recomputed.
  void fitCells();
  void updateAxisChoices();

  QComboBox* rows_ = nullptr;
  QComboBox* columns_ = nullptr;
  QSpinBox* steps_ = nullptr;
  QCheckBox* raycast_ = nullptr;
  QLabel* status_ = nullptr;
  QWidget* grid_widget_ = nullptr;
  QGridLayout* grid_ = nullptr;
  QScrollArea* scroll_ = nullptr;
  std::vector<QToolButton*> cells_;
  int cell_columns_ = 0; ///< columns of the current grid
  int finished_ = 0;
  bool sameGrid(const Sheet& sheet) const;

  Sheet sheet_;
  bool has_sheet_ = false;
  bool cells_empty_pending_ = false; ///< the grid is out of date (rebuild when shown)
  std::atomic<std::uint64_t> generation_{ 0 };
  QThreadPool jobs_;
  std::shared_ptr<frep::ThreadPool> engine_pool_;
  /// The last sheet's framing (UI thread): a sheet drawn another way reuses it.
  std::shared_ptr<const SheetFraming> last_framing_;
};

} // namespace frepstudio
