// frepkit demo homotopic -O DIR: the main job, "Homotopic Fun in 5D Space" end to end: Meta5D
// written from the four key files by the metamorphosis component (meta5d.hf, keys aligned by
// size unless --align says otherwise), the mapping Examples/homotopic/homotopic.json of it
// through `frepkit map` (spreadsheet.png, path.png, frames/, homotopic.wav, homotopic.mp4), the
// four key shapes as binary STL meshes (cat.stl, robot.stl, nihon.stl, roblet.stl), and one
// manifest.json listing all of it (with the model's file and how it was blended).
#pragma once

#include "morph_command.h"

#include <optional>
#include <string>

namespace CLI
{
class App;
}

namespace frepkit
{

struct DemoOptions
{
  std::string name = "homotopic";
  std::string output_directory;
  std::string examples; ///< the Examples folder; default: the source tree's, else next to the tool
  std::optional<int> frames;
  std::optional<int> resolution;
  std::optional<int> ghost; ///< the ghost's resolution (default: the mapping's 32), 0: none
  std::optional<int> topology; ///< the topology map's resolution (the mapping's 96), 0: none
  std::optional<std::string> method; ///< overrides the mapping's render.method (mesh | raycast)
  int mesh_grid = 256;               ///< grid of the key shapes' meshes
  std::string align = "size";        ///< Meta5D's keys aligned: none (the paper), centroid or size
  std::string normalise = "none";    ///< Meta5D's keys' values: none or distance
  BlendOptions blend;                ///< Meta5D's timing and key weights
  bool force = false;
  int threads = 0;
  bool quiet = false;
};

CLI::App* add_demo_command(CLI::App& app, DemoOptions& options);

/// Returns the process exit code; user errors are thrown as UserError.
int run_demo(const DemoOptions& options);

} // namespace frepkit
