// One cell of the spreadsheet of cross-sections: the section of a model at given fixed values,
// meshed by the engine and drawn by the headless software renderer (Multimedia/Render), or drawn
// by rays from the function itself (FRep/Raycast: no facets, no detail lost below the
// grid), so cells are made on a worker thread without touching OpenGL.
#pragma once

#include "SectionSpec.h"
#include "Compiler/model.h"

#include <QImage>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace frep
{
class ThreadPool;
}

namespace frepstudio
{

struct CellRequest : SectionSpec // fixed_values: x4..xn for this cell
{
  int resolution = 40; ///< samples per axis
  int pixels = 160;    ///< the picture is pixels x pixels
  bool raycast = false; ///< draw by rays instead of meshing at `resolution`
};

/// Meshes and draws (or ray-casts) one cell; an empty picture when cancelled (`keep_going` returned false) or
/// when the model cannot be cut (x_dim < 3). The camera matches the 3-D view's default one
/// (y up, looking from +x +y +z), fitted to the box, so every cell is framed alike.
QImage render_cell(const CellRequest& request, const std::shared_ptr<frep::ThreadPool>& pool,
  const std::function<bool()>& keep_going);

} // namespace frepstudio
