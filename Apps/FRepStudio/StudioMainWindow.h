// FRepStudio's main window: the HyperFun editor beside the live 3-D cross-section, the model
// panel (object, x4.. sliders, a[]), the error list, and the file menus. The text is analysed
// (parsed, compiled, and the shown object's box found from the solid's bounds: CoordinateRanges)
// on a short debounce off the UI thread; the section is meshed off the UI thread, coarse first
// and refined when the values rest (MeshWorker); in "High quality" mode the refined section is
// then ray-cast at the view's camera (PictureWorker) and shown in place of the mesh until the
// camera moves.
#pragma once

#include "HyperFunEditor.h"
#include "MeshWorker.h"
#include "ModelAnalysis.h"
#include "PictureWorker.h"
#include "ProjectedModel.h"
#include "UserInputs.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QTimer>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>

class QTabWidget;
class QAction;
class QLabel;
class QMenu;

namespace frepstudio
{

class CoordinatePanel;
class ErrorListWidget;
class SectionView;
class SpreadsheetPanel;
class MappingEditor;
class PathPanel;
class AnimationExport;

class StudioMainWindow : public QMainWindow
{
  Q_OBJECT
public:
  /// Samples per axis of the coarse and the refined section.
  static constexpr int kCoarseResolution = 32;
  static constexpr int kRefinedResolution = 128;
  /// Quiet time before a text change is analysed / before a value change is refined.
  static constexpr int kParseDebounceMs = 300;
  static constexpr int kRefineRestMs = 150;
  /// Quiet time after the camera or the window moved before the "High quality" picture.
  static constexpr int kPictureRestMs = 200;

  explicit StudioMainWindow(QWidget* parent = nullptr);
  ~StudioMainWindow() override;

  /// Opens a model file (no unsaved-changes prompt: see openFile()). False when unreadable.
  bool loadFile(const QString& path);
  /// Loads user libraries (frepkit_user.h) and shape files (name=FILE) whose functions models
  /// may call; they are also passed to the animation export. False and `error` (naming the
  /// library and the function, or the shape and what is wrong with its file) when one cannot be
  /// loaded; nothing changes then.
  bool setUserInputs(const UserInputs& inputs, QString* error);
  /// Replaces the text as an unnamed model.
  void setModelText(const QString& text, const QString& name = QString());
  /// Selects an object now, or when the next analysis lists it.
  void selectObject(const QString& name);
  /// Sets x4.. or a[i] by name ("x4", "a1"), now or when the model has it.
  bool setValue(const QString& name, double value);

  /// True when nothing is pending: the text is analysed, and the refined section of the current
  /// values is on screen (or the model has no section to show), its High quality picture too
  /// when that mode is on, and a visible spreadsheet has all its cells.
  bool isSettled() const;
  /// The current file ("" for an unnamed model).
  QString currentFile() const { return file_; }
  const ModelAnalysis* analysis() const { return analysis_ ? &*analysis_ : nullptr; }
  /// The object shown (null when none); its `ranges` are the box and the sliders' ranges.
  const ObjectSummary* currentObjectSummary() const;

  HyperFunEditor* editor() const { return editor_; }
  ErrorListWidget* errorList() const { return errors_; }
  SectionView* sectionView() const { return view_; }
  CoordinatePanel* coordinatePanel() const { return panel_; }
  SpreadsheetPanel* spreadsheetPanel() const { return spreadsheet_; }
  MappingEditor* mappingEditor() const { return mapping_; }
  PathPanel* pathPanel() const { return path_; }
  /// Shows the spreadsheet tab (true) or the 3-D section tab (View > Spreadsheet / Section).
  void showSpreadsheet(bool show);
  /// View > High Quality: the resting section ray-cast (no facets) instead of its mesh.
  void setHighQuality(bool on);
  bool highQuality() const;

  /// Opens a mapping file in the Mapping tab and shows it; false when it cannot be read.
  bool showMapping(const QString& path);

  /// Starts exporting the animation of the Mapping tab's mapping (the path panel's path when
  /// the mapping has none) into `directory` through `frepkit map`; returns the running export
  /// (owned by the window) or null with `error`. File > Export Animation... shows its progress
  /// in a dialog whose Cancel stops it.
  AnimationExport* exportAnimation(const QString& directory, QString* error);

  /// The examples of the Examples menu: title and path.
  static QList<QPair<QString, QString>> examples();

signals:
  /// An analysis was applied (errors listed, panel rebuilt).
  void analysisApplied();
  /// A section is on screen: its resolution, cells, and ms from the request to the frame.
  void sectionShown(int resolution, long long cells, double milliseconds);

protected:
  void closeEvent(QCloseEvent* event) override;

private:
  frep::LoadOptions loadOptions_; // --library and --shape, as the engine loads them
  UserInputs userInputs_; // absolute paths: their files key the export's frames
  void buildMenus();
  void startAnalysis();
  void applyAnalysis(ModelAnalysis analysis);
  /// Meshes the current state: the given resolutions, in order.
  void requestSection(std::vector<int> resolutions);
  void onValuesChanged();
  void onSectionReady(const SectionMesh& mesh);
  void onFrameRendered();
  /// Ray-casts the shown refined section at the view's camera (High quality mode).
  void requestPicture();
  bool maybeSave();
  bool saveTo(const QString& path);
  void openFile();
  void addRecentFile(const QString& path);
  void updateRecentMenu();
  void updateTitle();
  /// The panel's sliders and a[] fields for the current object, then its section once its box
  /// is known (searchBounds when the analysis did not search it).
  void showCurrentObject();
  /// The object's ranges note (a solid without bounds keeps hfp's box) as the error list's warning.
  void showRangesNote(const ObjectSummary& object);
  /// Searches `object`'s box off the UI thread (CoordinateRanges::with_solid_bounds); then shows
  /// its section if it is still the current object of the current analysis.
  void searchBounds(const ObjectSummary& object);

  HyperFunEditor* editor_ = nullptr;
  SectionView* view_ = nullptr;
  CoordinatePanel* panel_ = nullptr;
  ErrorListWidget* errors_ = nullptr;
  SpreadsheetPanel* spreadsheet_ = nullptr;
  MappingEditor* mapping_ = nullptr;
  PathPanel* path_ = nullptr;
  QTabWidget* tabs_ = nullptr; ///< the 3-D section and the spreadsheet
  QLabel* status_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  MeshWorker* worker_ = nullptr;
  PictureWorker* pictures_ = nullptr;
  QAction* high_quality_ = nullptr;
  QTimer picture_timer_;
  std::optional<SectionRequest> last_request_; ///< the newest section request (its values)
  ProjectedModel projected_; ///< the current object projected along the ticked coordinates

  QString file_;
  QTimer parse_timer_;
  QTimer refine_timer_;
  std::uint64_t analysis_generation_ = 0;
  int analyses_running_ = 0; ///< analyses and searchBounds jobs
  /// searchBounds jobs under way: the analysis's generation and the object's name.
  std::set<std::pair<std::uint64_t, std::string>> searching_;
  std::optional<ModelAnalysis> analysis_;
  QString pending_object_;
  bool reset_camera_ = true;
  std::uint64_t shown_generation_ = 0;
  bool refined_shown_ = false;
  bool section_failed_ = false;
  /// The section waiting for its frame (set when handed to the view, cleared when rendered).
  std::optional<SectionMesh> awaiting_frame_;
};

} // namespace frepstudio
