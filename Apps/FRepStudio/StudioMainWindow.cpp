#include "StudioMainWindow.h"

#include "AnimationExport.h"
#include "DurableSave.h"
#include "shape_files.h"

#include "CoordinatePanel.h"
#include "ExamplesDirectory.h"
#include "ErrorListWidget.h"
#include "MappingEditor.h"
#include "PathPanel.h"
#include "SectionView.h"
#include "SpreadsheetPanel.h"

#include <QAction>

#include <algorithm>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QtConcurrent/QtConcurrentRun>

namespace frepstudio
{

namespace
{
constexpr int kMaxRecentFiles = 8;
const char* const kRecentKey = "recentFiles";
}

QList<QPair<QString, QString>> StudioMainWindow::examples()
{
  const QString root = examplesDirectory();
  return {
    { "Cat", root + "/homotopic/cat.hf" },
    { "Robot", root + "/homotopic/robot.hf" },
    { "NiHon", root + "/homotopic/nihon.hf" },
    { "Rob_let", root + "/homotopic/roblet.hf" },
    { "Meta5D", root + "/homotopic/meta5d.hf" },
    { "Morph4D", root + "/mapping/morph4d.hf" },
    { "homotopy5d", root + "/homotopy5d.hf" },
  };
}

StudioMainWindow::StudioMainWindow(QWidget* parent)
  : QMainWindow(parent)
{
  editor_ = new HyperFunEditor(this);
  editor_->setObjectName("editor");
  view_ = new SectionView(this);
  spreadsheet_ = new SpreadsheetPanel(this);
  spreadsheet_->setObjectName("spreadsheet");
  // The spreadsheet costs a mesh per cell: it is a tab beside the 3-D section, laid out only
  // while it is shown (View > Spreadsheet).
  tabs_ = new QTabWidget(this);
  tabs_->addTab(view_, tr("Section"));
  tabs_->addTab(spreadsheet_, tr("Spreadsheet"));
  mapping_ = new MappingEditor(this);
  mapping_->setObjectName("mappingEditor");
  tabs_->addTab(mapping_, tr("Mapping"));
  // A mapping with a path through two coordinates gives the path panel its path.
  connect(mapping_, &MappingEditor::specChanged, this, [this] {
    if (mapping_->spec().animation.path)
      path_->setPath(*mapping_->spec().animation.path);
  });
  auto* splitter = new QSplitter(Qt::Horizontal, this);
  splitter->addWidget(editor_);
  splitter->addWidget(tabs_);
  // The OpenGL widget has no size hint of its own: without a minimum and initial sizes the
  // splitter would give it no width at all.
  view_->setMinimumSize(320, 240);
  splitter->setStretchFactor(0, 2);
  splitter->setStretchFactor(1, 3);
  splitter->setSizes({ 440, 660 });
  setCentralWidget(splitter);

  panel_ = new CoordinatePanel(this);
  auto* panel_dock = new QDockWidget(tr("Model"), this);
  panel_dock->setObjectName("modelDock");
  panel_dock->setWidget(panel_);
  addDockWidget(Qt::RightDockWidgetArea, panel_dock);

  // The path animates the section: a dock beside the view, not a tab that would hide it.
  path_ = new PathPanel(this);
  path_->setObjectName("pathPanel");
  auto* path_dock = new QDockWidget(tr("Path"), this);
  path_dock->setObjectName("pathDock");
  path_dock->setWidget(path_);
  addDockWidget(Qt::RightDockWidgetArea, path_dock);
  connect(path_, &PathPanel::positionChanged, this,
    [this](const std::map<std::string, double>& values) {
      for (const auto& [name, value] : values)
        panel_->setValue(name, value);
    });

  errors_ = new ErrorListWidget(this);
  errors_->setObjectName("errorList");
  auto* error_dock = new QDockWidget(tr("Errors"), this);
  error_dock->setObjectName("errorDock");
  error_dock->setWidget(errors_);
  addDockWidget(Qt::BottomDockWidgetArea, error_dock);
  resizeDocks({ error_dock }, { 90 }, Qt::Vertical);

  // A cell moves the sliders to its values and shows that section.
  connect(spreadsheet_, &SpreadsheetPanel::cellActivated, this,
    [this](const std::map<std::string, double>& values) {
      for (const auto& [name, value] : values)
        panel_->setValue(name, value);
      showSpreadsheet(false);
    });

  status_ = new QLabel(this);
  statusBar()->addPermanentWidget(status_, 1);

  worker_ = new MeshWorker(this);
  pictures_ = new PictureWorker(this);
  picture_timer_.setSingleShot(true);
  picture_timer_.setInterval(kPictureRestMs);
  connect(&picture_timer_, &QTimer::timeout, this, &StudioMainWindow::requestPicture);

  parse_timer_.setSingleShot(true);
  parse_timer_.setInterval(kParseDebounceMs);
  refine_timer_.setSingleShot(true);
  refine_timer_.setInterval(kRefineRestMs);

  connect(editor_, &QPlainTextEdit::textChanged, this, [this] { parse_timer_.start(); });
  connect(editor_->document(), &QTextDocument::modificationChanged, this,
    [this] { updateTitle(); });
  connect(&parse_timer_, &QTimer::timeout, this, &StudioMainWindow::startAnalysis);
  connect(&refine_timer_, &QTimer::timeout, this, [this] {
    // The values have rested, but the coarse section of these values may still be meshing (a
    // loaded machine): a new request would cancel it and leave the view empty for longer. Let it
    // finish, then refine.
    if (worker_->busy())
    {
      refine_timer_.start();
      return;
    }
    requestSection({ kRefinedResolution });
  });
  connect(errors_, &ErrorListWidget::locationActivated, editor_, &HyperFunEditor::goToLocation);
  connect(panel_, &CoordinatePanel::valuesChanged, this, &StudioMainWindow::onValuesChanged);
  connect(panel_, &CoordinatePanel::objectChanged, this, [this] {
    reset_camera_ = true;
    showCurrentObject();
  });
  connect(worker_, &MeshWorker::sectionReady, this, &StudioMainWindow::onSectionReady);
  connect(worker_, &MeshWorker::sectionFailed, this, [this](quint64, const QString& message) {
    section_failed_ = true;
    status_->setText(tr("Section: %1").arg(message));
  });
  connect(view_, &SectionView::frameRendered, this, &StudioMainWindow::onFrameRendered);
  // High quality: the mesh while the camera moves, the ray-cast picture once it rests.
  connect(view_, &SectionView::interactionStarted, this, [this] {
    picture_timer_.stop();
    pictures_->cancel();
    view_->showMesh();
  });
  auto picture_later = [this] {
    if (highQuality())
      picture_timer_.start();
  };
  connect(view_, &SectionView::interactionEnded, this, picture_later);
  connect(view_, &SectionView::resized, this, [this, picture_later] {
    if (view_->showingPicture())
      view_->showMesh();
    picture_later();
  });
  connect(pictures_, &PictureWorker::pictureReady, this,
    [this](quint64, const QImage& picture, double seconds) {
      if (!highQuality() || picture.isNull())
        return;
      view_->showPicture(picture);
      status_->setText(tr("high quality: ray-cast %1 x %2 pixels in %3 ms")
                         .arg(picture.width())
                         .arg(picture.height())
                         .arg(seconds * 1000, 0, 'f', 0));
    });

  buildMenus();
  resize(1280, 800);
  updateTitle();
}

StudioMainWindow::~StudioMainWindow()
{
  // Stop the mesher and the ray caster before the widgets they report to go away.
  worker_->cancel();
  pictures_->cancel();
}

void StudioMainWindow::buildMenus()
{
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&New"), this, [this] {
    if (maybeSave())
      setModelText("my_model(x[3], a[1])\n{\n  array c[3];\n  c = [0, 0, 0];\n"
                   "  my_model = hfSphere(x, c, 5);\n}\n");
  }, QKeySequence::New);
  file->addAction(tr("&Open..."), this, &StudioMainWindow::openFile, QKeySequence::Open);
  recent_menu_ = file->addMenu(tr("Open &Recent"));
  file->addAction(tr("&Save"), this, [this] {
    if (file_.isEmpty())
    {
      const QString path =
        QFileDialog::getSaveFileName(this, tr("Save model"), {}, tr("HyperFun (*.hf)"));
      if (!path.isEmpty())
        saveTo(path);
    }
    else
    {
      saveTo(file_);
    }
  }, QKeySequence::Save);
  file->addAction(tr("Save &As..."), this, [this] {
    const QString path =
      QFileDialog::getSaveFileName(this, tr("Save model"), file_, tr("HyperFun (*.hf)"));
    if (!path.isEmpty())
      saveTo(path);
  }, QKeySequence::SaveAs);
  file->addSeparator();
  file->addAction(tr("&Export Animation..."), this, [this] {
    const QString directory = QFileDialog::getExistingDirectory(this, tr("Export the animation into"));
    if (directory.isEmpty())
      return;
    QString error;
    AnimationExport* job = exportAnimation(directory, &error);
    if (!job)
    {
      QMessageBox::warning(this, tr("Export"), error);
      return;
    }
    auto* dialog = new QProgressDialog(tr("Exporting frames, sound and movie..."), tr("Cancel"), 0,
      1000, this);
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(0);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(job, &AnimationExport::progress, dialog, [dialog](int done, int total) {
      dialog->setMaximum(total);
      dialog->setValue(std::min(done, total - 1)); // closed by finished, not by the value
    });
    connect(dialog, &QProgressDialog::canceled, job, &AnimationExport::cancel);
    connect(job, &AnimationExport::finished, this, [this, dialog](bool ok, const QString& message) {
      dialog->close();
      if (ok)
        QMessageBox::information(this, tr("Export"), message);
      else
        QMessageBox::warning(this, tr("Export"), message);
    });
  });
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  view->addAction(findChild<QDockWidget*>("modelDock")->toggleViewAction());
  view->addAction(findChild<QDockWidget*>("errorDock")->toggleViewAction());
  view->addAction(findChild<QDockWidget*>("pathDock")->toggleViewAction());
  view->addSeparator();
  view->addAction(tr("&Section"), this, [this] { showSpreadsheet(false); },
    QKeySequence(QStringLiteral("Ctrl+1")));
  view->addAction(tr("S&preadsheet"), this, [this] { showSpreadsheet(true); },
    QKeySequence(QStringLiteral("Ctrl+2")));
  view->addSeparator();
  high_quality_ = view->addAction(tr("&High Quality (Ray-Cast)"));
  high_quality_->setObjectName("highQualityAction");
  high_quality_->setCheckable(true);
  high_quality_->setShortcut(QKeySequence(QStringLiteral("Ctrl+H")));
  high_quality_->setToolTip(tr("Draw the resting section by rays from the function itself (no "
                               "facets, no detail lost below the grid)"));
  connect(high_quality_, &QAction::toggled, this, [this](bool on) {
    picture_timer_.stop();
    pictures_->cancel();
    view_->showMesh();
    if (on)
      requestPicture();
  });

  QMenu* examples_menu = menuBar()->addMenu(tr("&Examples"));
  for (const auto& [title, path] : examples())
  {
    QAction* action = examples_menu->addAction(title, this, [this, path = path] {
      if (maybeSave())
        loadFile(path);
    });
    action->setEnabled(QFileInfo::exists(path));
  }
  updateRecentMenu();
}

bool StudioMainWindow::loadFile(const QString& path)
{
  QFile in(path);
  if (!in.open(QIODevice::ReadOnly))
  {
    status_->setText(tr("Cannot open %1: %2").arg(path, in.errorString()));
    return false;
  }
  const QString text = QString::fromUtf8(in.readAll());
  file_ = QFileInfo(path).absoluteFilePath();
  reset_camera_ = true;
  {
    // Loading is not an edit: analyse at once instead of after the typing debounce.
    QSignalBlocker block(editor_);
    editor_->setPlainText(text);
  }
  editor_->document()->setModified(false);
  addRecentFile(file_);
  updateTitle();
  startAnalysis();
  return true;
}

void StudioMainWindow::setModelText(const QString& text, const QString& name)
{
  file_ = name;
  reset_camera_ = true;
  {
    QSignalBlocker block(editor_);
    editor_->setPlainText(text);
  }
  editor_->document()->setModified(false);
  updateTitle();
  startAnalysis();
}

void StudioMainWindow::selectObject(const QString& name)
{
  pending_object_ = name;
  if (analysis_ && panel_->selectObject(name.toStdString()))
    pending_object_.clear();
}

bool StudioMainWindow::setValue(const QString& name, double value)
{
  return panel_->setValue(name.toStdString(), value);
}

void StudioMainWindow::startAnalysis()
{
  parse_timer_.stop();
  const std::uint64_t generation = ++analysis_generation_;
  const std::string text = editor_->toPlainText().toStdString();
  const std::string name = file_.isEmpty() ? std::string("<editor>")
                                           : QFileInfo(file_).fileName().toStdString();
  // The object applyAnalysis will show (a pending choice, else the current one if the text still
  // has it, else the default): the one whose box the analysis searches.
  const std::string shown =
    pending_object_.isEmpty() ? panel_->currentObject() : pending_object_.toStdString();
  ++analyses_running_;
  // The watcher belongs to the window: if the window closes first, the result is dropped.
  auto* watcher = new QFutureWatcher<ModelAnalysis>(this);
  connect(watcher, &QFutureWatcher<ModelAnalysis>::finished, this, [this, watcher] {
    --analyses_running_;
    ModelAnalysis result = watcher->result();
    watcher->deleteLater();
    // Only the newest text counts; an older analysis finishing late is dropped.
    if (result.generation == analysis_generation_)
      applyAnalysis(std::move(result));
  });
  watcher->setFuture(QtConcurrent::run([text, name, generation, options = loadOptions_, shown]
    { return analyse_model(text, name, generation, options, shown); }));
}

void StudioMainWindow::applyAnalysis(ModelAnalysis analysis)
{
  errors_->setDiagnostics(analysis.diagnostics);
  std::vector<TextLocation> locations;
  for (const auto& diagnostic : analysis.diagnostics)
    locations.push_back({ diagnostic.location.line, diagnostic.location.column });
  editor_->setErrorLocations(locations);

  if (!analysis.ok())
  {
    // Keep the last good model and its section on screen: a typo must not blank the view.
    status_->setText(tr("%n error(s)", nullptr, static_cast<int>(analysis.diagnostics.size())));
    emit analysisApplied();
    return;
  }
  analysis_ = std::move(analysis);
  std::vector<std::string> names;
  for (const auto& object : analysis_->objects)
    names.push_back(object.name);
  panel_->setObjects(names, analysis_->default_object);
  if (!pending_object_.isEmpty() && panel_->selectObject(pending_object_.toStdString()))
    pending_object_.clear();
  showCurrentObject();
  emit analysisApplied();
}

void StudioMainWindow::showCurrentObject()
{
  const ObjectSummary* object = currentObjectSummary();
  if (!object)
    return;
  {
    // x4..'s ranges do not wait for the search: they are the file's or [0, 1] either way.
    QSignalBlocker block(panel_);
    panel_->setModelShape(object->x_dim, object->a_dim, object->ranges);
  }
  if (!object->searched)
  {
    errors_->setWarning({});
    searchBounds(*object); // the section follows the box
    return;
  }
  showRangesNote(*object);
  requestSection({ kCoarseResolution, kRefinedResolution });
}

void StudioMainWindow::showRangesNote(const ObjectSummary& object)
{
  // Said once, beside the model's errors, for as long as this object of this text is shown.
  const std::string& note = object.ranges.note();
  errors_->setWarning(note.empty() ? QString()
                                   : tr("%1: warning: %2: %3")
                                       .arg(QString::fromStdString(analysis_->file_name),
                                         QString::fromStdString(object.name),
                                         QString::fromStdString(note)));
}

void StudioMainWindow::searchBounds(const ObjectSummary& object)
{
  // The analysis searched the object it was to show; another one picked since is searched here,
  // off the UI thread, in the analysis's model (a later edit's analysis makes this one moot).
  if (!searching_.insert({ analysis_->generation, object.name }).second)
    return; // already under way
  ++analyses_running_;
  auto* watcher = new QFutureWatcher<CoordinateRanges>(this);
  connect(watcher, &QFutureWatcher<CoordinateRanges>::finished, this,
    [this, watcher, generation = analysis_->generation, name = object.name] {
      --analyses_running_;
      searching_.erase({ generation, name });
      const CoordinateRanges ranges = watcher->result();
      watcher->deleteLater();
      if (!analysis_ || analysis_->generation != generation)
        return;
      for (ObjectSummary& o : analysis_->objects)
        if (o.name == name && !o.searched)
        {
          o.ranges = ranges;
          o.searched = true;
          if (panel_->currentObject() == name)
          {
            showRangesNote(o);
            requestSection({ kCoarseResolution, kRefinedResolution });
          }
        }
    });
  watcher->setFuture(QtConcurrent::run([model = object.model, file = analysis_->file_ranges]
    { return file.with_solid_bounds(*model); }));
}

const ObjectSummary* StudioMainWindow::currentObjectSummary() const
{
  if (!analysis_)
    return nullptr;
  const std::string name = panel_->currentObject();
  for (const auto& object : analysis_->objects)
    if (object.name == name)
      return &object;
  return nullptr;
}

void StudioMainWindow::requestSection(std::vector<int> resolutions)
{
  refine_timer_.stop();
  const ObjectSummary* object = currentObjectSummary();
  if (!object || !object->model || !object->searched)
    return; // no box yet: searchBounds requests the section when it has one
  SectionRequest request;
  request.model = object->model;
  request.s_dim = object->s_dim;
  request.parameters = panel_->parameters();
  request.fixed_values = panel_->fixedValues();
  if (const auto projected = panel_->projectedRanges(); !projected.empty())
  {
    // The union over the ticked coordinates' ranges; the source's a[] are baked into it.
    std::string why;
    request.model = projected_.get(object->model, projected, request.parameters, why);
    if (!request.model)
    {
      status_->setText(tr("Cannot project: %1").arg(QString::fromStdString(why)));
      return;
    }
    request.s_dim = 1;
    request.parameters.clear();
  }
  for (int i = 0; i < 3; ++i)
  {
    const auto range = object->ranges.range(i);
    request.lo[i] = range[0];
    request.hi[i] = range[1];
  }
  request.resolutions = std::move(resolutions);
  section_failed_ = false;
  last_request_ = request;
  picture_timer_.stop();
  pictures_->cancel(); // the section changes: a picture of the old one would be stale

  SpreadsheetPanel::Sheet sheet;
  static_cast<SectionSpec&>(sheet.base) = request;
  sheet.base.pixels = 120;
  for (int i = 3; i < object->x_dim; ++i)
    sheet.extra_ranges.push_back(object->ranges.range(i));
  spreadsheet_->setSheet(sheet);
  path_->setCoordinates(sheet.extra_ranges);

  worker_->request(std::move(request));
}

void StudioMainWindow::onValuesChanged()
{
  // While the values move, only coarse sections: each is ready in a few tens of ms. The refined
  // one follows once they have rested for kRefineRestMs.
  requestSection({ kCoarseResolution });
  refine_timer_.start();
}

void StudioMainWindow::onSectionReady(const SectionMesh& mesh)
{
  view_->setSection(mesh.poly_data, mesh.lo, mesh.hi, reset_camera_);
  reset_camera_ = false;
  shown_generation_ = mesh.generation;
  refined_shown_ = mesh.resolution >= kRefinedResolution;
  if (refined_shown_ && highQuality())
    picture_timer_.start();
  // A hidden view (the spreadsheet tab is in front) draws no frame until it is shown again.
  if (view_->isVisible())
    awaiting_frame_ = mesh;
  const bool surface = mesh.poly_data && mesh.poly_data->GetNumberOfPolys() > 0;
  status_->setText(tr("%1 %2^%3: %4 %5 in %6 ms")
                     .arg(mesh.resolution >= kRefinedResolution ? tr("refined") : tr("coarse"))
                     .arg(mesh.resolution)
                     .arg(surface ? 3 : 2)
                     .arg(mesh.cells)
                     .arg(surface ? tr("triangles") : tr("segments"))
                     .arg(mesh.seconds * 1000, 0, 'f', 0));
}

void StudioMainWindow::setHighQuality(bool on)
{
  high_quality_->setChecked(on);
}

bool StudioMainWindow::highQuality() const
{
  return high_quality_ && high_quality_->isChecked();
}

void StudioMainWindow::requestPicture()
{
  if (!highQuality() || !refined_shown_ || section_failed_ || !last_request_ ||
    !view_->section() || shown_generation_ != worker_->latestGeneration())
    return;
  SectionPictureRequest request;
  static_cast<SectionSpec&>(request) = *last_request_;
  request.camera = view_->camera();
  const QSize size = view_->pixelSize();
  request.width = size.width();
  request.height = size.height();
  request.background_bottom = view_->backgroundBottom();
  request.background_top = view_->backgroundTop();
  pictures_->request(std::move(request));
}

void StudioMainWindow::onFrameRendered()
{
  if (!awaiting_frame_)
    return;
  const SectionMesh mesh = *awaiting_frame_;
  awaiting_frame_.reset();
  const double ms = std::chrono::duration<double, std::milli>(
    std::chrono::steady_clock::now() - mesh.requested_at).count();
  emit sectionShown(mesh.resolution, static_cast<long long>(mesh.cells), ms);
}

bool StudioMainWindow::isSettled() const
{
  return !parse_timer_.isActive() && analyses_running_ == 0 && !refine_timer_.isActive() &&
    !worker_->busy() && !awaiting_frame_ && !picture_timer_.isActive() && !pictures_->busy() &&
    !(spreadsheet_->isVisible() && spreadsheet_->isComputing());
}

bool StudioMainWindow::showMapping(const QString& path)
{
  tabs_->setCurrentWidget(mapping_);
  return mapping_->loadFile(path);
}

void StudioMainWindow::showSpreadsheet(bool show)
{
  tabs_->setCurrentWidget(show ? static_cast<QWidget*>(spreadsheet_) : view_);
}

bool StudioMainWindow::maybeSave()
{
  if (!editor_->document()->isModified())
    return true;
  const auto answer = QMessageBox::warning(this, tr("FRepStudio"),
    tr("The model has unsaved changes. Save them?"),
    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Cancel)
    return false;
  if (answer == QMessageBox::Discard)
    return true;
  QString path = file_;
  if (path.isEmpty())
    path = QFileDialog::getSaveFileName(this, tr("Save model"), {}, tr("HyperFun (*.hf)"));
  return !path.isEmpty() && saveTo(path);
}

bool StudioMainWindow::saveTo(const QString& path)
{
  // Written beside the target and renamed when complete and synced: a failed save never
  // truncates the model on disk, a crash after "saved" does not lose it.
  if (const QString problem = saveDurably(path, editor_->toPlainText().toUtf8()); !problem.isEmpty())
  {
    QMessageBox::critical(this, tr("FRepStudio"), tr("Cannot save %1: %2").arg(path, problem));
    return false;
  }
  file_ = QFileInfo(path).absoluteFilePath();
  editor_->document()->setModified(false);
  addRecentFile(file_);
  updateTitle();
  return true;
}

void StudioMainWindow::openFile()
{
  if (!maybeSave())
    return;
  const QString path = QFileDialog::getOpenFileName(this, tr("Open model"),
    file_.isEmpty() ? examplesDirectory() : QFileInfo(file_).path(),
    tr("HyperFun (*.hf);;All files (*)"));
  if (!path.isEmpty())
    loadFile(path);
}

void StudioMainWindow::addRecentFile(const QString& path)
{
  QSettings settings;
  QStringList recent = settings.value(kRecentKey).toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > kMaxRecentFiles)
    recent.removeLast();
  settings.setValue(kRecentKey, recent);
  updateRecentMenu();
}

void StudioMainWindow::updateRecentMenu()
{
  recent_menu_->clear();
  const QStringList recent = QSettings().value(kRecentKey).toStringList();
  for (const QString& path : recent)
    recent_menu_->addAction(QFileInfo(path).fileName(), this, [this, path] {
      if (maybeSave())
        loadFile(path);
    })->setToolTip(path);
  recent_menu_->setEnabled(!recent.isEmpty());
}

void StudioMainWindow::updateTitle()
{
  const QString name = file_.isEmpty() ? tr("untitled") : QFileInfo(file_).fileName();
  setWindowTitle(QStringLiteral("%1%2 — FRepStudio")
                   .arg(name, editor_->document()->isModified() ? "*" : ""));
}

void StudioMainWindow::closeEvent(QCloseEvent* event)
{
  if (maybeSave())
    event->accept();
  else
    event->ignore();
}

bool StudioMainWindow::setUserInputs(const UserInputs& inputs, QString* error)
{
  const auto strings = [](const QStringList& list)
  {
    std::vector<std::string> out;
    for (const QString& item : list)
      out.push_back(item.toStdString());
    return out;
  };
  auto shapes = std::make_shared<frep::UserFunctionRegistry>();
  const std::string e =
    frepkit::add_user_inputs({}, strings(inputs.shapes), inputs.unsignedDistance, *shapes);
  if (!e.empty())
  {
    if (error)
      *error = QString::fromStdString(e);
    return false;
  }
  frep::LoadOptions options;
  options.libraries = strings(inputs.libraries);
  options.functions = inputs.shapes.isEmpty() ? nullptr : std::move(shapes);
  // The libraries are loaded with every analysis; load them once here to refuse a bad one now.
  const frep::LoadedProgram check =
    frep::load_program(frep::ModelSource::from_text("", "<libraries>"), options);
  if (!check.ok())
  {
    if (error)
      *error = QString::fromStdString(frep::format_diagnostics(check.diagnostics));
    return false;
  }
  loadOptions_ = std::move(options);
  userInputs_ = absoluteUserInputs(inputs);
  if (!editor_->toPlainText().isEmpty())
    startAnalysis(); // a model that calls the new names parses now
  return true;
}

AnimationExport* StudioMainWindow::exportAnimation(const QString& directory, QString* error)
{
  frep::mapping::Spec spec = mapping_->spec();
  if (!spec.animation.path && path_->isEnabled() && path_->controlPoints().size() >= 2)
  {
    spec.animation.path = path_->path();
  }
  auto* job = new AnimationExport(this);
  job->setUserInputs(userInputs_, loadOptions_);
  const QString object = QString::fromStdString(panel_->currentObject());
  // The name the editor's diagnostics use (its extension chooses the language).
  const QString name = file_.isEmpty() ? QStringLiteral("<editor>") : QFileInfo(file_).fileName();
  if (!job->start(editor_->toPlainText(), name, object, spec, directory, error))
  {
    delete job;
    return nullptr;
  }
  connect(job, &AnimationExport::finished, job, &QObject::deleteLater);
  return job;
}

} // namespace frepstudio
