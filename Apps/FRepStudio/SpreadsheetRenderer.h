// The spreadsheet of cross-sections as a multimedia mapping (Multimedia/Mapping): x1..x3 on the
// world axes over the box, the row and column coordinates on the spreadsheet's rows and
// columns, every other coordinate fixed at its slider's value. Its cells are drawn by the scene
// code of `frepkit map` (Scene's frame_solids, plan_camera and draw_sample: one camera framing
// every cell's solid, the same colours, light and methods), headless, on a worker thread.
#pragma once

#include "Compiler/model.h"
#include "Imaging/camera.h"
#include "Mapping/mapping_plan.h"
#include "Mapping/mapping_spec.h"
#include "Scene/framing.h"
#include "SectionSpec.h"

#include <QImage>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace frep
{
class ThreadPool;
}

namespace frepstudio
{

struct CellRequest : SectionSpec // fixed_values: the sliders' values of x4..xn
{
  int resolution = 40; ///< samples per axis
  int pixels = 160;    ///< a cell's picture is pixels x pixels
  bool raycast = false; ///< draw by rays instead of meshing at `resolution`
};

struct SheetRequest
{
  CellRequest base;
  int row_coordinate = 0;     ///< index into x4..: 0 = x4
  int column_coordinate = -1; ///< index into x4..; -1 = a single column
  std::vector<double> row_values;
  std::vector<double> column_values;
};

/// The sheet's mapping: world x1..x3 over the box, rows and columns (their listed values),
/// fixed coordinates; the cells' size, FRepStudio's dark background and hfp's face colour, or
/// the model's s[1..3] colours when `model_colours`; mesh or ray-cast cells.
frep::mapping::Spec sheet_mapping(const SheetRequest& request, bool model_colours);

/// A sheet's framing and what it was found for: a sheet that differs only in how its cells are
/// drawn (mesh or rays, resolution, pixels) frames the same, so it reuses this one instead of
/// framing again (about a second for Meta5D's 25 cells on 2 cores).
struct SheetFraming
{
  std::shared_ptr<const frep::Model> model;
  std::string mapping; ///< the sheet's mapping without its drawing settings (save_mapping)
  frep::mapping::Framing framing;
};

class SheetRenderer
{
public:
  /// Plans the sheet and frames its solids (frame_solids over every cell: one camera, as
  /// `frepkit map`'s), or takes `previous`' framing when it was found for the same sheet.
  /// `progress`, when given, is called on this thread with the fraction of solids framed. Null
  /// with `error` set when the sheet cannot be planned or the model cannot be cut (fewer than 4
  /// coordinates); null with no error when `keep_going` said stop.
  static std::unique_ptr<SheetRenderer> prepare(const SheetRequest& request,
    const std::shared_ptr<frep::ThreadPool>& pool,
    const std::function<bool()>& keep_going,
    std::string* error,
    const std::shared_ptr<const SheetFraming>& previous = {},
    const std::function<void(double)>& progress = {});

  /// The framing this sheet's cells are drawn with, for the next sheet's prepare.
  const std::shared_ptr<const SheetFraming>& framing() const { return framing_; }

  /// Cells in reading order (column fastest, then row).
  std::size_t cellCount() const { return plan_.cells.size(); }

  /// Cell i's picture; a null image when cancelled, or with `error` set when it failed.
  QImage cell(std::size_t i, const std::function<bool()>& keep_going, std::string* error) const;

private:
  SheetRenderer() = default;

  CellRequest base_;
  frep::mapping::Spec spec_;
  frep::mapping::Plan plan_;
  std::shared_ptr<const SheetFraming> framing_;
  frep::imaging::Camera camera_;
  std::shared_ptr<frep::ThreadPool> pool_;
};

} // namespace frepstudio
