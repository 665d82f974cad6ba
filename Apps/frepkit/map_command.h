// frepkit map MODEL.hf MAPPING.json -O OUTDIR: a multimedia mapping end to end — the spreadsheet
// of cross-sections (spreadsheet.png), the path of the dynamic coordinates (path.png), the
// animation frames (frames/frame_NNNNN.png), the sound track (NAME.wav), the movie with the
// sound muxed in (NAME.mp4), the shape alone when nothing varies (shape.png) and manifest.json
// listing everything with each frame's values. The run is the Production library's
// (frep::mapping::produce, as FRepStudio's export); this command reads the files, applies the
// overrides, shows the progress bar and the summary. Resumable: frames already written by an
// interrupted run with the same model and mapping are kept; every file is written under a
// temporary name and renamed when complete.
#pragma once

#include "user_inputs.h"
#include <optional>
#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace frepkit
{

struct MapOptions
{
  UserInputs user; ///< --library, --shape
  std::string model;
  std::string mapping;
  std::string output_directory;
  std::optional<std::string> object;
  std::vector<double> parameters;
  std::optional<int> resolution; ///< overrides world.resolution
  std::optional<int> frames;     ///< overrides the frame count (duration * fps)
  /// animation.ghost's resolution (the ghost added with its default tolerance if the mapping has
  /// none); 0: no ghost. Applied after `resolution`.
  std::optional<int> ghost;
  /// topology.resolution (the map of the topology added with its defaults if the mapping has
  /// none); 0: no topology map. Applied after `resolution`.
  std::optional<int> topology;
  /// Overrides render.method for cells and frames alike: "mesh" (quick drafts) or "raycast".
  std::optional<std::string> method;
  std::vector<std::string> only; ///< spreadsheet, path, frames, audio, movie, shape, ghost, topology
  std::string name;              ///< output stem; default: the mapping file's stem
  bool force = false;            ///< re-render frames that exist
  /// When set, the manifest's text is given here instead of written to manifest.json: frepkit
  /// demo adds the meshes and writes manifest.json itself, once, so that an interruption leaves
  /// either the old manifest or the complete new one, and no intermediate file.
  std::string* manifest_out = nullptr;
  int threads = 0;
  bool quiet = false;
};

CLI::App* add_map_command(CLI::App& app, MapOptions& options);

/// Returns the process exit code; user errors are thrown as UserError.
int run_map(const MapOptions& options);

} // namespace frepkit
