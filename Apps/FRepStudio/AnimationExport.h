// Exporting the animation (frames, sound track, MP4, manifest) of the editor's model along a
// mapping: the Production library's run (frep::mapping::produce, the same call as `frepkit map`)
// on a thread of its own, so the UI never blocks. Cancel stops it between samples (and stops
// ffmpeg) and leaves exactly what an interrupted `frepkit map` leaves: the finished frames (a
// later export resumes), no half-written file. The model text and the mapping are also saved in
// OUT/.frepstudio/ (model.hf, mapping.json), so `frepkit map` can repeat the export.
#pragma once

#include "Mapping/mapping_spec.h"
#include "UserInputs.h"

#include "Compiler/load_model.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <thread>

namespace frepstudio
{

class AnimationExport : public QObject
{
  Q_OBJECT
public:
  explicit AnimationExport(QObject* parent = nullptr);
  /// Cancels a running export and waits for it to stop.
  ~AnimationExport() override;

  /// What the model may call besides the library (the window's --library and --shape): the
  /// engine's load options, and the same inputs as files (their contents key the frames).
  void setUserInputs(const UserInputs& inputs, const frep::LoadOptions& options);

  /// Saves the model text and the mapping into OUT/.frepstudio/ and starts the export into
  /// `output_directory` (files named animation.*). `model_name` is the name diagnostics use
  /// (its extension chooses the language: ".vm" is a tape). False (and `error`) when an export
  /// is running or the files cannot be written; a model that does not load ends the export with
  /// finished(false, its diagnostics).
  bool start(const QString& model_text,
    const QString& model_name,
    const QString& object,
    const frep::mapping::Spec& spec,
    const QString& output_directory,
    QString* error);
  /// Asks the export to stop; finished(false, "cancelled; ...") follows.
  void cancel();
  bool isRunning() const { return running_; }
  /// The frames the mapping asks for.
  int expectedFrames() const { return expected_frames_; }
  QString outputDirectory() const { return output_; }

signals:
  /// Per mille of the whole export (cells, frames, the movie) done: `done` of `total` (1000).
  void progress(int done, int total);
  /// ok: every file written; otherwise `message` says why (or that it was cancelled).
  void finished(bool ok, const QString& message);

private:
  void run(std::string model_text, std::string model_name, std::string object,
    frep::mapping::Spec spec);
  void reportProgress(double fraction);
  void complete(bool ok, const QString& message);

  UserInputs inputs_;
  frep::LoadOptions load_options_;
  std::thread thread_;
  std::atomic<bool> running_{ false };
  std::atomic<bool> cancelled_{ false };
  std::atomic<int> shown_permille_{ -1 };
  QString output_;
  int expected_frames_ = 0;
};

} // namespace frepstudio
