// A multimedia mapping produced end to end, as files in a directory: the spreadsheet of
// cross-sections (spreadsheet.png), the shape alone when nothing varies (shape.png), the path of
// the two dynamic coordinates (path.png), the animation frames (frames/frame_NNNNN.png), the sound
// track (STEM.wav), the movie with the sound muxed in (STEM.mp4) and manifest.json, which lists
// every file with each cell's and frame's values. `frepkit map`, `frepkit demo` and FRepStudio's
// Export Animation are this one call; they differ only in how they load the model and show the
// progress.
//
//   frep::mapping::ProductionInputs in;
//   in.spec = frep::mapping::load_mapping(text).spec;
//   in.model = frep::load_model(frep::ModelSource::file("morph.hf")).model;
//   frep::mapping::ProductionOptions run;
//   run.directory = "out";
//   run.progress = [&](double f) { bar.set(f); return true; };
//   const frep::mapping::ProductionReport report = frep::mapping::produce(in, run);
//   if (!report.ok()) { ... report.error, report.diagnostics ... }
//
// Durable and resumable: every file is written under a temporary name and put in place when
// complete (Support/Durable), and frames already on disk from an interrupted run with the same
// inputs are kept (a fingerprint of the model, the mapping and the parameters). A run that is
// cancelled or fails keeps the files it finished and leaves no temporary behind.
#pragma once

#include "Mapping/mapping_spec.h"

#include "Compiler/model.h"
#include "Eval/run_control.h"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace frep::mapping
{

/// What is produced: the mapping, the model it is applied to, and what identifies them.
struct ProductionInputs
{
  /// The mapping, with any overrides already applied (frepkit map's --resolution, --frames).
  Spec spec;
  /// The model, loaded and compiled (frep::load_model). Required.
  std::shared_ptr<const Model> model;
  /// a[1], a[2], ... of the model. Default: none (the object's a[] are zero).
  std::vector<double> parameters;
  /// Everything the model's values depend on that the model object does not show: its text and
  /// the contents of the libraries and shape files it calls (user_inputs_key in the programs).
  /// Part of the frames' fingerprint: frames on disk are kept only when it is the same.
  std::string model_key;
  /// The model's and the mapping's names as the manifest records them (their paths as given).
  std::string model_label;
  std::string mapping_label;
};

/// Where the files go and which of them to make; the RunControl part says on how many threads,
/// reports the fraction done (from any worker thread, one call at a time; returning false stops
/// the run like `cancel`) and cancels. `threads` (0 = all cores) is the number of workers, each
/// drawing whole cells and frames; `pool`, when given, only frames the solids.
struct ProductionOptions : RunControl
{
  /// The output directory, created when missing. Required.
  std::filesystem::path directory;
  /// The stem of the movie and sound files. Default "animation".
  std::string stem = "animation";
  /// Make only these of what the mapping can make: "spreadsheet", "path", "frames", "audio",
  /// "movie", "shape". Default empty: everything.
  std::vector<std::string> only;
  /// Draw every frame again, even those kept from an earlier run. Default false.
  bool force = false;
  /// Write manifest.json. Default true; false: the manifest is only returned in the report (frepkit
  /// demo adds its meshes and writes it once).
  bool write_manifest = true;
};

/// One stage of the run: its line in a summary and its entry in the manifest's "seconds".
struct ProductionStage
{
  std::string name; ///< "framing", "spreadsheet", "shape", "path", "frames", "ghost", "topology", "audio", "movie"
  double seconds = 0;
  std::string detail; ///< "25 cells, 1000x1000; worker time: ..."
};

struct ProductionReport
{
  enum class Status
  {
    Done,      ///< every file asked for is written
    Invalid,   ///< the mapping does not fit the model (diagnostics say why); nothing written
    Failed,    ///< a section, a file or the movie failed (error); what finished is kept
    Cancelled, ///< stopped by `cancel` or `progress`; what finished is kept
  };
  Status status = Status::Failed;
  /// One line: why the run did not complete ("the mapping does not fit ...", "c[2,3]: ...").
  std::string error;
  /// The mapping's problems, "place: message", one per entry (status Invalid).
  std::vector<std::string> diagnostics;
  /// What was made anyway but deserves a word ("no font: pictures without labels").
  std::vector<std::string> warnings;
  std::vector<ProductionStage> stages;
  /// manifest.json's text (also when `write_manifest` is false); empty unless Done.
  std::string manifest;
  std::size_t triangles = 0;      ///< meshed in all (0 when everything was ray-cast)
  std::size_t failed_samples = 0; ///< samples whose evaluation raised a run-time error (outside)
  double seconds = 0;             ///< wall time of the whole run

  bool ok() const { return status == Status::Done; }
};

/// Plans the mapping for the model and makes the files. Never throws for bad input or a failed
/// write: the report says what happened.
ProductionReport produce(const ProductionInputs& inputs, const ProductionOptions& options);

/// The object to load for a mapping: `requested` when it is not empty, else the mapping's
/// "object" (empty: the model file's default object).
std::string mapped_object(const Spec& spec, const std::string& requested);

/// The products `produce` recognises in ProductionOptions::only.
const std::vector<std::string>& product_names();

} // namespace frep::mapping
