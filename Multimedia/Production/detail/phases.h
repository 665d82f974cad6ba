// The phases of produce (production.cpp), in the order it runs them:
//   1. plan     (setup.cpp)    the mapping planned for the model's coordinates;
//   2. products (setup.cpp)    what `only` and the plan ask for;
//   3. output   (setup.cpp)    the output directory and the worker count;
//   4. framing  (setup.cpp)    the box every picture frames: the solids' (Scene/framing.h);
//   5. pictures (pictures.cpp) the spreadsheet, the shape alone, the path;
//   6. frames   (frames.cpp)   the animation frames, resumable (fingerprint), and the ghost
//               (ghost.cpp)    the union of every shape they show, when the mapping asks,
//               (topology.cpp) the map of the topology of the cells and frames, when it asks;
//   7. media    (media.cpp)    the sound track and the movie;
//   8. manifest (manifest.cpp) manifest.json.
// The rendering phases share the Workers (workers.cpp: per-worker picture kits and mesher pools,
// the progress, the meshing counters) and report into a Record (the manifest's file entries and
// the stages). Problems are thrown as ProductionError, a stop as Stopped; produce() turns both
// into the report.
#pragma once

#include "Production/production.h"

#include "Mapping/mapping_plan.h"
#include "Scene/floor_scene.h"
#include "Scene/framing.h"
#include "Scene/pictures.h"
#include "Scene/sample_picture.h"
#include "Scene/section_mesh.h"
#include "Scene/section_raycast.h"

#include "Imaging/image.h"

#include "Eval/thread_pool.h"

#include <nlohmann/json.hpp>

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace frep::mapping::production
{

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// A problem that ends the run (the report's error).
struct ProductionError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// The run was asked to stop (cancel, or progress returning false).
struct Stopped : std::runtime_error
{
  Stopped()
    : std::runtime_error("cancelled")
  {
  }
};

double seconds_since(Clock::time_point start);

/// Written under a temporary name, put in place when complete (AtomicOutput, Support/Durable).
void write_png_file(const fs::path& path, const imaging::Image& image);
void write_text_file(const fs::path& path, const std::string& text);

/// A sample's label and its values by coordinate name (NaN values left out), for the manifest.
nlohmann::json sample_json(const Sample& s, const std::vector<std::string>& names);

// --- 1-4: plan, products, output, framing -----------------------------------------------------

/// What the phases read: the inputs, the options and the plan made from them.
struct Job
{
  const ProductionInputs& inputs;
  const ProductionOptions& options;
  ModelCoordinates coordinates;
  Plan plan;
  /// What the sections are cut from: the model, or its projection when the plan projects
  /// coordinates (section_model, made by plan_job).
  std::shared_ptr<const Model> sectioned;
  /// What the one camera of the cells and frames frames (phase 4); empty: the plan's box.
  Framing framing;
  mutable std::atomic<bool> stop_requested{ false }; ///< progress returned false

  const Spec& spec() const { return inputs.spec; }
  const Model& model() const { return *inputs.model; }
  const Model& section_source() const { return *sectioned; }
  /// Whether to stop: `cancel` says so, or `progress` returned false.
  bool stopped() const { return stop_requested || options.cancel_requested(); }
  /// Throws Stopped when stopped(): the check between two pieces of work.
  void throw_if_stopped() const;
};

/// The plan of the mapping for the model's coordinates x1..xn (hfp's default box) and the model
/// its sections are cut from; the plan's errors go into `diagnostics` (false then).
bool plan_job(Job& job, std::vector<std::string>& diagnostics);

struct Products
{
  bool spreadsheet = false;
  bool path = false;
  bool frames = false;
  bool audio = false;
  bool movie = false;
  bool shape = false; ///< nothing varies (world and fixed coordinates only)
  bool ghost = false; ///< the mapping asks for it (animation.ghost) and something moves
  bool topology = false; ///< the mapping asks for it (topology) and there are cells or frames
};

/// What `only` asks for among what the plan can make; a ProductionError when that is nothing.
Products choose_products(const Job& job);

/// The output directory, created; a ProductionError when it cannot be.
void prepare_directory(const fs::path& directory);

/// The number of workers: the options' threads, or all cores.
int worker_count(const ProductionOptions& options);

/// A stage's line in the summary and its entry in the manifest's "seconds".
using Stage = ProductionStage;

/// What the phases produced: the manifest's "files" and the stages, in order.
struct Record
{
  nlohmann::json files = nlohmann::json::array();
  std::vector<Stage> stages;
  /// The spreadsheet as composed, and each cell picture's place in it (the topology map draws
  /// over it); empty without a spreadsheet.
  imaging::Image sheet;
  std::vector<std::array<int, 4>> sheet_rects;
  /// The manifest's "topology" (the map of the topology); null without one.
  nlohmann::json topology;
};

/// When the products draw sections and the mapping gives no render.view_box: the framing of the
/// solids of every cell and frame (frame_solids), so one camera frames the shapes, not the model
/// box; its time is the record's "framing" stage.
void frame_solids(Job& job, const Products& products, int workers, Record& record);

// --- what the rendering phases share ----------------------------------------------------------

/// Where a stage's time goes, summed over the workers (thread seconds, not wall time).
struct Ledger
{
  std::mutex mutex;
  double meshing = 0, rendering = 0, writing = 0;
  void add(double mesh, double render, double write);
  std::string text();
};

/// One picture kit and one single-thread mesher pool per worker, the progress over all the
/// products' work units, and the counters of the meshing.
class Workers
{
public:
  Workers(const Job& job, const Products& products, int workers);

  int count() const { return static_cast<int>(kits_.size()); }
  PictureKit* kit(int worker) { return kits_[static_cast<std::size_t>(worker)].get(); }

  /// The sample's picture by `method` (Scene's draw_sample): on `worker`'s single-thread pool,
  /// or on `threads` threads when more than one (with `floor`, if given: the floor scene's
  /// board, on which the section is stood by its lowest point). Counts the meshes' triangles
  /// and failed samples. Throws Stopped or ProductionError.
  using Picture = SamplePicture;
  Picture picture(RenderSettings::Method method,
    const Sample& sample,
    const imaging::Camera& camera,
    int width,
    int height,
    int worker,
    int threads = 1,
    const raycast::Floor* floor = nullptr);

  /// Runs body(i, worker) for i in [0, count) on the workers; the first exception (or a stop)
  /// stops the others and is rethrown.
  void parallel(std::size_t count, const std::function<void(std::size_t, int)>& body);

  /// One work unit done (a cell or a frame drawn, or meshed for the topology map).
  void advance();
  /// The progress at `units` work units done (the movie's progress, between whole units).
  void show_units(double units);
  std::size_t units_done() const { return units_done_; }
  /// The progress at 1: everything is done.
  void finish() { show_units(total_units_); }

  std::size_t failed_samples() const { return failed_samples_; }
  std::size_t triangles() const { return triangles_; }

private:
  const Job& job_;
  std::vector<std::unique_ptr<PictureKit>> kits_;
  std::vector<std::shared_ptr<ThreadPool>> pools_;
  double total_units_ = 1.0;
  std::atomic<std::size_t> units_done_{ 0 };
  std::mutex progress_mutex_;
  std::atomic<std::size_t> failed_samples_{ 0 };
  std::atomic<std::size_t> triangles_{ 0 };
};

// --- 5-8: the products ------------------------------------------------------------------------

/// spreadsheet.png: every cell with one camera, composed with labels.
void render_spreadsheet(const Job& job, Workers& workers, Record& record);

/// shape.png: the shape alone, when nothing varies.
void render_shape(const Job& job, Workers& workers, Record& record);

/// path.png: the path of the two dynamic coordinates.
void draw_path(const Job& job, Workers& workers, Record& record);

/// ghost.png: the union of every shape the animation shows (ghost.cpp).
void render_ghost(const Job& job, Workers& workers, Record& record);

/// The map of the topology (topology.cpp): the pieces and genus of every cell's and frame's
/// section and where they change, into the record's topology, spreadsheet-topology.png (over
/// the record's sheet) and topology.png (along the frames).
void map_topology(const Job& job, Workers& workers, Record& record);

/// Where the frames go: frames/frame_%05d.png under the output directory.
struct FrameFiles
{
  fs::path directory;
  std::string pattern = "frame_%05d.png";
  fs::path file(std::size_t k) const;
  std::string name(std::size_t k) const;
};

/// The frames, resumable: a frame on disk is kept when the fingerprint of the model, the
/// mapping and the parameters is the one it was rendered with (and `force` is not set).
void render_frames(const Job& job, Workers& workers, const FrameFiles& frames, Record& record);

/// The sound track (WAV) of the frames' voices.
void write_sound(const Job& job, const fs::path& wav, Record& record);

/// The movie from the frames, with the sound track when there is one.
void encode_movie(const Job& job,
  Workers& workers,
  const FrameFiles& frames,
  const fs::path* audio,
  const fs::path& movie,
  Record& record);

/// manifest.json's text: the inputs, every file written, the stages' times.
std::string manifest_text(const Job& job, const Record& record);

} // namespace frep::mapping::production
