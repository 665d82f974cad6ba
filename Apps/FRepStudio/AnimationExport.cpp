#include "AnimationExport.h"

#include "DurableSave.h"

#include "Plan/mapping_json.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>
#include <cmath>

namespace frepstudio
{

AnimationExport::AnimationExport(QObject* parent)
  : QObject(parent)
{
  poll_timer_.setInterval(200);
  connect(&poll_timer_, &QTimer::timeout, this, &AnimationExport::poll);
  connect(&process_,
    qOverload<int, QProcess::ExitStatus>(&QProcess::finished),
    this,
    &AnimationExport::processFinished);
  process_.setProcessChannelMode(QProcess::SeparateChannels);
}

AnimationExport::~AnimationExport()
{
  if (isRunning())
  {
    process_.terminate();
    process_.waitForFinished(10000);
  }
}

QString AnimationExport::frepkitProgram()
{
  // The frepkit beside FRepStudio (<prefix>/bin, or build/bin in the build tree), else PATH.
  const QString sibling = QCoreApplication::applicationDirPath() + "/frepkit";
  if (QFileInfo(sibling).isExecutable())
  {
    return sibling;
  }
  return QStandardPaths::findExecutable("frepkit");
}

bool AnimationExport::start(const QString& model_text,
  const QString& object,
  const frep::mapping::Spec& spec,
  const QString& output_directory,
  QString* error)
{
  if (isRunning())
  {
    *error = tr("an export is already running");
    return false;
  }
  const QString program = frepkitProgram();
  if (program.isEmpty())
  {
    *error = tr("the frepkit program was not found (it is built with FRepStudio)");
    return false;
  }
  output_ = output_directory;
  const QString work = QDir(output_directory).filePath(".frepstudio");
  if (!QDir().mkpath(work))
  {
    *error = tr("cannot create %1").arg(work);
    return false;
  }
  auto write = [&](const QString& name, const QByteArray& bytes)
  {
    const QString path = QDir(work).filePath(name);
    if (const QString problem = saveDurably(path, bytes); !problem.isEmpty())
    {
      *error = tr("cannot write %1: %2").arg(path, problem);
      return false;
    }
    return true;
  };
  if (!write("model.hf", model_text.toUtf8()) ||
      !write("mapping.json", QByteArray::fromStdString(frep::mapping::save_mapping(spec))))
  {
    return false;
  }
  expected_frames_ =
    std::max(1, static_cast<int>(std::lround(spec.animation.duration * spec.animation.fps)));
  QStringList arguments{ "map",
    QDir(work).filePath("model.hf"),
    QDir(work).filePath("mapping.json"),
    "-O",
    output_directory,
    "--name",
    "animation",
    "--quiet" };
  if (!object.isEmpty())
  {
    arguments << "--object" << object;
  }
  arguments << userInputArguments(inputs_);
  cancelled_ = false;
  process_.start(program, arguments);
  if (!process_.waitForStarted(10000))
  {
    *error = tr("cannot start %1: %2").arg(program, process_.errorString());
    return false;
  }
  poll_timer_.start();
  emit progress(0, expected_frames_);
  return true;
}

void AnimationExport::cancel()
{
  if (isRunning())
  {
    cancelled_ = true;
    process_.terminate(); // SIGTERM: frepkit's interrupt guard stops between samples
  }
}

void AnimationExport::poll()
{
  const QStringList frames =
    QDir(QDir(output_).filePath("frames")).entryList({ "frame_*.png" }, QDir::Files);
  emit progress(std::min(static_cast<int>(frames.size()), expected_frames_), expected_frames_);
}

void AnimationExport::processFinished(int code, QProcess::ExitStatus status)
{
  poll_timer_.stop();
  poll();
  const QString messages = QString::fromUtf8(process_.readAllStandardError()).trimmed();
  if (cancelled_)
  {
    emit finished(false, tr("cancelled; the frames written so far are kept"));
  }
  else if (status != QProcess::NormalExit || code != 0)
  {
    emit finished(
      false, messages.isEmpty() ? tr("frepkit map failed (exit code %1)").arg(code) : messages);
  }
  else
  {
    emit finished(true,
      tr("animation.mp4, animation.wav, the frames and manifest.json are in %1").arg(output_));
  }
}

} // namespace frepstudio
