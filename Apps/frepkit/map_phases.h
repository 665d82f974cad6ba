// The phases of frepkit map, in the order run_map (map_command.cpp) runs them:
//   1. inputs   (map_inputs.cpp)   the mapping file and the model, checked, and the plan;
//   2. products (map_inputs.cpp)   what --only and the plan ask for;
//   3. output   (map_inputs.cpp)   the output directory, the files' stem, the worker count;
//   4. framing  (map_inputs.cpp)   the box every picture frames: the solids' (Scene/framing.h);
//   5. pictures (map_pictures.cpp) the spreadsheet, the shape alone, the path;
//   6. frames   (map_frames.cpp)   the animation frames, resumable (fingerprint);
//   7. media    (map_media.cpp)    the sound track and the movie;
//   8. manifest (map_manifest.cpp) manifest.json and the summary on standard error.
// The rendering phases share a MapWorkers (map_workers.cpp: per-worker picture kits and pools,
// the progress bar, the meshing counters) and report into a MapRecord (the manifest's file
// entries and the stages' times). Problems are thrown as UserError.
#pragma once

#include "map_command.h"
#include "progress_bar.h"

#include "Plan/mapping_plan.h"
#include "Plan/mapping_spec.h"
#include "Imaging/image.h"
#include "Scene/floor_scene.h"
#include "Scene/framing.h"
#include "Scene/pictures.h"
#include "Scene/section_mesh.h"
#include "Scene/section_raycast.h"

#include "Compiler/model.h"
#include "Eval/thread_pool.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace frepkit::map_run
{

namespace fs = std::filesystem;
namespace mapping = frep::mapping;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start);

/// The whole file as bytes; a UserError "cannot read the <what> <path>" when it cannot be read.
std::string read_file(const std::string& path, const char* what);

/// Written under a temporary name, renamed when complete (AtomicOutput, Support/Durable).
void write_png_file(const fs::path& path, const frep::imaging::Image& image);
void write_text_file(const fs::path& path, const std::string& text);

/// A sample's label and its values by coordinate name (NaN values left out), for the manifest.
nlohmann::json sample_json(const mapping::Sample& s, const std::vector<std::string>& names);

// --- 1-4: inputs, products, output, framing ------------------------------------------------

struct MapInputs
{
  std::string mapping_text; ///< the mapping file as read (part of the frames' fingerprint)
  mapping::Spec spec;       ///< with --resolution and --frames applied
  std::shared_ptr<const frep::Model> model;
  std::vector<double> parameters; ///< --parameters, else the mapping's
  mapping::ModelCoordinates coordinates;
  mapping::Plan plan;
  /// What the one camera of the cells and frames frames (phase 4); empty: the plan's box.
  mapping::Framing framing;
};

/// Every problem of the mapping, the model and the plan is reported before anything is written.
MapInputs load_inputs(const MapOptions& options);

struct MapProducts
{
  bool spreadsheet = false;
  bool path = false;
  bool frames = false;
  bool audio = false;
  bool movie = false;
  bool shape = false; ///< nothing varies (world and fixed coordinates only)
};

/// What --only asks for among what the plan can make; a UserError when that is nothing.
MapProducts choose_products(const MapOptions& options, const mapping::Plan& plan);

struct MapOutput
{
  fs::path directory; ///< created
  std::string stem;   ///< of the movie and sound files
  int workers = 1;
};

MapOutput prepare_output(const MapOptions& options);

struct MapRecord;

/// When the products draw sections (spreadsheet, shape, frames) and the mapping gives no
/// render.view_box: the framing of the solids of every cell and frame (mapping::frame_solids,
/// on `workers` threads), so one camera frames the shapes, not the model box; its time is the
/// record's "framing" stage.
void frame_solids(MapInputs& in, const MapProducts& products, int workers, MapRecord& record);

// --- what the rendering phases share -------------------------------------------------------

/// A stage's line in the summary and its entry in the manifest's "seconds".
struct MapStage
{
  std::string name;
  double seconds = 0;
  std::string detail;
};

/// What the phases produced: the manifest's "files" and the stages, in order.
struct MapRecord
{
  nlohmann::json files = nlohmann::json::array();
  std::vector<MapStage> stages;
};

/// Where a stage's time goes, summed over the workers (thread seconds, not wall time).
struct Ledger
{
  std::mutex mutex;
  double meshing = 0, rendering = 0, writing = 0;
  void add(double mesh, double render, double write);
  std::string text();
};

/// One picture kit and one single-thread mesher pool per worker, the progress bar over all the
/// products' work units, and the counters of the meshing. Made once the InterruptGuard is up.
class MapWorkers
{
public:
  MapWorkers(const MapInputs& inputs, const MapProducts& products, int workers, bool quiet);

  int count() const { return static_cast<int>(kits_.size()); }
  mapping::PictureKit* kit(int worker) { return kits_[static_cast<std::size_t>(worker)].get(); }

  /// The section of `sample` meshed on `worker`'s pool; a UserError when interrupted or failed.
  mapping::Section section(const mapping::Sample& sample, int worker);

  /// The sample's picture by the mapping's render method: its section meshed on `worker`'s
  /// pool and rasterised, or drawn by rays on `threads` threads (with `floor`, if given: the
  /// floor scene's board, on which the section is stood by its lowest point,
  /// mapping::stand_on_floor). A UserError when interrupted or failed.
  struct Picture
  {
    frep::imaging::Image image;
    double mesh_seconds = 0.0;   ///< meshing (0 when ray-cast)
    double render_seconds = 0.0; ///< rasterising or ray casting
    std::size_t triangles = 0;
  };
  Picture picture(mapping::RenderSettings::Method method,
    const mapping::Sample& sample,
    const frep::imaging::Camera& camera,
    int width,
    int height,
    int worker,
    int threads = 1,
    const frep::raycast::Floor* floor = nullptr);

  /// Runs body(i, worker) for i in [0, count) on the workers; the first exception (or an
  /// interrupt) stops the others and is rethrown.
  void parallel(std::size_t count, const std::function<void(std::size_t, int)>& body);

  /// One work unit done (a cell or a frame).
  void advance();
  /// The bar at `units` work units done (the movie's progress, between whole units).
  void show_units(double units);
  std::size_t units_done() const { return units_done_; }
  void finish_bar() { bar_.finish(); }

  std::size_t failed_samples() const { return failed_samples_; }
  std::size_t triangles() const { return triangles_; }

private:
  const MapInputs& inputs_;
  std::vector<std::unique_ptr<mapping::PictureKit>> kits_;
  std::vector<std::shared_ptr<frep::ThreadPool>> pools_;
  ProgressBar bar_;
  double total_units_ = 1.0;
  std::atomic<std::size_t> units_done_{ 0 };
  std::mutex bar_mutex_;
  std::atomic<std::size_t> failed_samples_{ 0 };
  std::atomic<std::size_t> triangles_{ 0 };
};

// --- 5-8: the products ----------------------------------------------------------------------

/// spreadsheet.png: every cell with one camera, composed with labels.
void render_spreadsheet(const MapInputs& in,
  MapWorkers& workers,
  const fs::path& out_dir,
  MapRecord& record);

/// shape.png: the shape alone, when nothing varies.
void render_shape(const MapInputs& in,
  MapWorkers& workers,
  const fs::path& out_dir,
  MapRecord& record);

/// path.png: the path of the two dynamic coordinates.
void draw_path(const MapInputs& in,
  MapWorkers& workers,
  const fs::path& out_dir,
  MapRecord& record);

/// Where the frames go: frames/frame_%05d.png under the output directory.
struct FrameFiles
{
  fs::path directory;
  std::string pattern = "frame_%05d.png";
  fs::path file(std::size_t k) const;
  std::string name(std::size_t k) const;
};

/// The frames, resumable: a frame on disk is kept when the fingerprint of the model, the
/// mapping and the overrides is the one it was rendered with (and --force is not given).
void render_frames(const MapOptions& options,
  const MapInputs& in,
  MapWorkers& workers,
  const FrameFiles& frames,
  MapRecord& record);

/// The sound track (WAV) of the frames' voices.
void write_sound(const MapInputs& in, const fs::path& wav, MapRecord& record);

/// The movie from the frames, with the sound track when there is one.
void encode_movie(const MapInputs& in,
  MapWorkers& workers,
  const FrameFiles& frames,
  const fs::path* audio,
  const fs::path& movie,
  MapRecord& record);

/// manifest.json: the inputs, every file written, the stages' times.
void write_manifest(const MapOptions& options,
  const MapInputs& in,
  const fs::path& out_dir,
  const MapRecord& record);

/// The summary on standard error (unless --quiet) and the warning about failed samples.
void print_summary(const MapOptions& options,
  const MapInputs& in,
  const fs::path& out_dir,
  const MapRecord& record,
  const MapWorkers& workers,
  Clock::time_point start);

} // namespace frepkit::map_run
