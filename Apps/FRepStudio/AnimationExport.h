// Exporting the animation (frames, sound track, MP4, manifest) of the editor's model along a
// mapping: the same work `frepkit map` does, run as that program in a QProcess so the UI never
// blocks, a crash cannot take the window down, and Cancel (SIGTERM) leaves exactly what frepkit
// leaves after an interrupt: the finished frames (a later export resumes), no half-written file.
// Progress is the count of frames on disk.
#pragma once

#include "Plan/mapping_spec.h"
#include "UserInputs.h"

#include <QObject>
#include <QProcess>
#include <QStringList>
#include <QString>
#include <QTimer>

namespace frepstudio
{

class AnimationExport : public QObject
{
  Q_OBJECT
public:
  explicit AnimationExport(QObject* parent = nullptr);
  ~AnimationExport() override;

  /// The frepkit program: the one built with FRepStudio, else next to it, else on PATH.
  static QString frepkitProgram();

  /// Writes the model text and the mapping into OUT/.frepstudio/ and starts
  /// `frepkit map model.hf mapping.json -O OUT --name animation`. False (and `error`) when the
  /// files cannot be written or the program not started.
  bool start(const QString& model_text,
    const QString& object,
    const frep::mapping::Spec& spec,
    const QString& output_directory,
    QString* error);
  /// User libraries passed on to frepkit map (--library), for models that call their functions.
  void setUserInputs(const UserInputs& inputs) { inputs_ = inputs; }
  /// Stops the export (SIGTERM: frepkit keeps the frames it finished and removes temporaries).
  void cancel();
  bool isRunning() const { return process_.state() != QProcess::NotRunning; }
  int expectedFrames() const { return expected_frames_; }
  QString outputDirectory() const { return output_; }

signals:
  /// Frames written so far of the expected count.
  void progress(int frames, int total);
  /// ok: every file written; otherwise `message` is frepkit's error (or "cancelled").
  void finished(bool ok, const QString& message);

private:
  UserInputs inputs_;
  void poll();
  void processFinished(int code, QProcess::ExitStatus status);

  QProcess process_;
  QTimer poll_timer_;
  QString output_;
  int expected_frames_ = 0;
  bool cancelled_ = false;
};

} // namespace frepstudio
