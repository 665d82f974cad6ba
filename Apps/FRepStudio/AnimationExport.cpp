#include "AnimationExport.h"

#include "DurableSave.h"

#include "Mapping/mapping_json.h"
#include "Production/production.h"
#include "shape_files.h"

#include <QDir>

#include <algorithm>
#include <cmath>

namespace frepstudio
{
namespace
{

std::vector<std::string> strings(const QStringList& list)
{
  std::vector<std::string> out;
  for (const QString& item : list)
    out.push_back(item.toStdString());
  return out;
}

} // namespace

AnimationExport::AnimationExport(QObject* parent)
  : QObject(parent)
{
}

AnimationExport::~AnimationExport()
{
  cancelled_ = true;
  if (thread_.joinable())
    thread_.join();
}

void AnimationExport::setUserInputs(const UserInputs& inputs, const frep::LoadOptions& options)
{
  inputs_ = inputs;
  load_options_ = options;
}

bool AnimationExport::start(const QString& model_text,
  const QString& model_name,
  const QString& object,
  const frep::mapping::Spec& spec,
  const QString& output_directory,
  QString* error)
{
  if (running_ || thread_.joinable())
  {
    *error = tr("an export is already running");
    return false;
  }
  output_ = output_directory;
  const QString work = QDir(output_directory).filePath(".frepstudio");
  if (!QDir().mkpath(work))
  {
    *error = tr("cannot create %1").arg(work);
    return false;
  }
  auto save = [&](const QString& name, const QByteArray& bytes)
  {
    const QString path = QDir(work).filePath(name);
    if (const QString problem = saveDurably(path, bytes); !problem.isEmpty())
    {
      *error = tr("cannot write %1: %2").arg(path, problem);
      return false;
    }
    return true;
  };
  if (!save("model.hf", model_text.toUtf8()) ||
      !save("mapping.json", QByteArray::fromStdString(frep::mapping::save_mapping(spec))))
  {
    return false;
  }
  expected_frames_ =
    std::max(1, static_cast<int>(std::lround(spec.animation.duration * spec.animation.fps)));
  cancelled_ = false;
  shown_permille_ = -1;
  running_ = true;
  emit progress(0, 1000);
  thread_ = std::thread(&AnimationExport::run,
    this,
    model_text.toStdString(),
    model_name.toStdString(),
    object.toStdString(),
    spec);
  return true;
}

void AnimationExport::cancel()
{
  cancelled_ = true;
}

void AnimationExport::run(std::string model_text,
  std::string model_name,
  std::string object,
  frep::mapping::Spec spec)
{
  frep::LoadOptions options = load_options_;
  options.object = frep::mapping::mapped_object(spec, object);
  frep::mapping::ProductionInputs in;
  in.model_key = model_text + frepkit::user_inputs_key(strings(inputs_.libraries),
                                strings(inputs_.shapes), inputs_.unsignedDistance);
  const frep::LoadedModel loaded =
    frep::load_model(frep::ModelSource::from_text(std::move(model_text), model_name), options);
  if (!loaded.ok())
  {
    complete(false, QString::fromStdString(loaded.message()).trimmed());
    return;
  }
  in.model = loaded.model;
  in.parameters = spec.parameters;
  in.spec = std::move(spec);
  in.model_label = QDir(output_).filePath(".frepstudio/model.hf").toStdString();
  in.mapping_label = QDir(output_).filePath(".frepstudio/mapping.json").toStdString();
  frep::mapping::ProductionOptions run;
  run.directory = output_.toStdString();
  run.stem = "animation";
  run.cancel = [this] { return cancelled_.load(); };
  run.progress = [this](double fraction)
  {
    reportProgress(fraction);
    return true;
  };
  const frep::mapping::ProductionReport report = frep::mapping::produce(in, run);
  if (report.status == frep::mapping::ProductionReport::Status::Cancelled)
  {
    complete(false, tr("cancelled; the frames written so far are kept"));
    return;
  }
  if (!report.ok())
  {
    QStringList lines;
    for (const std::string& d : report.diagnostics)
      lines << QString::fromStdString(d);
    lines << QString::fromStdString(report.error);
    complete(false, lines.join('\n'));
    return;
  }
  complete(true,
    tr("animation.mp4, animation.wav, the frames and manifest.json are in %1").arg(output_));
}

void AnimationExport::reportProgress(double fraction)
{
  // Called by produce() one call at a time, from its workers: only a new per-mille value is
  // sent to the window's thread.
  const int permille = static_cast<int>(std::floor(std::clamp(fraction, 0.0, 1.0) * 1000.0));
  if (shown_permille_.exchange(permille) == permille)
    return;
  QMetaObject::invokeMethod(
    this, [this, permille] { emit progress(permille, 1000); }, Qt::QueuedConnection);
}

void AnimationExport::complete(bool ok, const QString& message)
{
  // On the window's thread: the export's thread has ended (or is ending) by then.
  QMetaObject::invokeMethod(
    this,
    [this, ok, message]
    {
      if (thread_.joinable())
        thread_.join();
      running_ = false;
      emit finished(ok, message);
    },
    Qt::QueuedConnection);
}

} // namespace frepstudio
