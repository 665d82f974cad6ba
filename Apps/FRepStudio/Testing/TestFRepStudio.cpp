// FRepStudio under QTest (run by ctest under xvfb-run, QT_QPA_PLATFORM=xcb): the box of x1..x3
// from the solid's own bounds and the pictures framing it, screenshots against a baseline, the
// error list, typing into the editor, progressive and cancelled meshing, the object picker, and
// open/close cycles.
#include "AnimationExport.h"
#include "CoordinatePanel.h"
#include "CoordinateRanges.h"
#include "ErrorListWidget.h"
#include "ImageComparison.h"
#include "Mapping/mapping_json.h"
#include "MappingEditor.h"
#include "ModelAnalysis.h"
#include "PathPanel.h"
#include "ScreenshotCapture.h"
#include "SectionView.h"
#include "SpreadsheetPanel.h"
#include "SpreadsheetRenderer.h"
#include "StudioMainWindow.h"

#include "Compiler/load_model.h"
#include "Eval/thread_pool.h"
#include "Language/parser.h"
#include "Mapping/mapping_plan.h"
#include "Mesh/solid_bounds.h"
#include "Mesh/surface.h"

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QFileInfo>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QProcess>
#include <QScrollArea>
#include <QSignalSpy>
#include <QSlider>
#include <QSurfaceFormat>
#include <QTest>
#include <QTableWidget>
#include <QTimer>
#include <QToolButton>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

#include <memory>

using namespace frepstudio;

namespace
{

const QString kMeta5D = QStringLiteral(FREPSTUDIO_EXAMPLES_DIR "/homotopic/meta5d.hf");
const QString kData = QStringLiteral(FREPSTUDIO_TEST_DATA);
const QSize kShotSize(1024, 700);
constexpr int kSettleMs = 120000;

/// Compares `image` with Data/Baseline/NAME.png; the picture is always written next to the test
/// binary (as ACTUAL.png), to inspect a failure or to become the new baseline.
void expectBaseline(const QImage& image, const QString& name, const QString& actual_name)
{
  const QString baseline = kData + "/Baseline/" + name + ".png";
  const QString actual = QStringLiteral(FREPSTUDIO_TEST_OUTPUT) + "/" + actual_name + ".png";
  QVERIFY(image.save(actual));
  const QImage expected(baseline);
  QVERIFY2(!expected.isNull(),
    qPrintable(QString("no baseline %1; this run's picture is %2").arg(baseline, actual)));
  const testing::ImageDifference difference = testing::compare_images(image, expected);
  QVERIFY2(difference.same_size, qPrintable(QString("size %1x%2, baseline %3x%4 (%5)")
                                              .arg(image.width())
                                              .arg(image.height())
                                              .arg(expected.width())
                                              .arg(expected.height())
                                              .arg(actual)));
  // Limits: two runs differ only in the status bar's timing text (mean 0.02, 0.013% of the
  // pixels); moving x4 by 0.05 gives mean 0.14 and 0.14% of the pixels.
  QVERIFY2(difference.mean < 0.06 && difference.changed_pixels < 0.0005,
    qPrintable(QString("mean difference %1 (limit 0.06), changed pixels %2 (limit 0.0005): %3")
                 .arg(difference.mean)
                 .arg(difference.changed_pixels)
                 .arg(actual)));
}

std::unique_ptr<StudioMainWindow> shownWindow()
{
  auto window = std::make_unique<StudioMainWindow>();
  window->resize(kShotSize);
  window->show();
  if (!QTest::qWaitForWindowExposed(window.get()))
    return nullptr;
  return window;
}

/// The reference: the same section meshed directly by the engine, in the box the window meshes
/// (its current object's x1..x3).
std::size_t engineTriangles(const StudioMainWindow& window,
  const QString& file,
  const char* object,
  std::vector<std::optional<double>> fixed,
  int n)
{
  const ObjectSummary* shown = window.currentObjectSummary();
  if (!shown)
    return 0;
  QFile in(file);
  if (!in.open(QIODevice::ReadOnly))
    return 0;
  const auto parsed = frep::parse_program(in.readAll().toStdString(), "m.hf");
  const int index = frep::ast::select_object(*parsed.program, object);
  const auto model = frep::Model::compile(parsed.program, index).model;
  frep::Specialisation specialisation;
  specialisation.fixed = std::move(fixed);
  frep::GridSpec grid;
  for (int i = 0; i < 3; ++i)
  {
    grid.axes.push_back({ shown->ranges.range(i)[0], shown->ranges.range(i)[1], n });
  }
  return frep::mesh::extract_surface(model->specialise(specialisation), grid)
    .surface.cell_count();
}

/// Pixels of `image` whose hue is hfp's face green rather than the grey-blue background and the
/// white lines: green above red and blue (however the shading darkens it).
int greenPixels(const QImage& image)
{
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
    {
      const QColor c = image.pixelColor(x, y);
      count += c.green() > c.red() + 8 && c.green() > c.blue() + 8;
    }
  return count;
}

/// The height and the width of the smallest rectangle holding every green pixel of `image` (as
/// in greenPixels), as fractions of the image's: how much of the picture the shape spans.
std::pair<double, double> greenExtent(const QImage& image)
{
  QRect box;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
    {
      const QColor c = image.pixelColor(x, y);
      if (c.green() > c.red() + 8 && c.green() > c.blue() + 8)
        box |= QRect(x, y, 1, 1);
    }
  return { static_cast<double>(box.height()) / image.height(),
    static_cast<double>(box.width()) / image.width() };
}

/// The same for the pixels that differ from the top-left pixel (a spreadsheet cell's background).
std::pair<double, double> coveredExtent(const QImage& image)
{
  const QColor background = image.pixelColor(0, 0);
  QRect box;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
    {
      const QColor c = image.pixelColor(x, y);
      if (std::abs(c.red() - background.red()) + std::abs(c.green() - background.green()) +
            std::abs(c.blue() - background.blue()) >
          24)
        box |= QRect(x, y, 1, 1);
    }
  return { static_cast<double>(box.height()) / image.height(),
    static_cast<double>(box.width()) / image.width() };
}

const std::string kUnitBall =
  "my_model(x[3], a[1])\n{\n  my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2;\n}\n";
const std::string kHalfSpace = "my_model(x[3], a[1])\n{\n  my_model = x[1];\n}\n";

/// `range` is [-r, r] plus the 5% margin of the solid's bounds (up to the search's resolution
/// and readable()'s rounding): a unit ball gets about [-1.1, 1.1].
bool aboutBallBounds(const std::array<double, 2>& range, double r)
{
  return range[0] <= -r * 1.04 && range[0] >= -r * 1.2 && range[1] >= r * 1.04 &&
         range[1] <= r * 1.2;
}

QString rangeText(const std::array<double, 2>& range)
{
  return QString("[%1, %2]").arg(range[0]).arg(range[1]);
}

/// Pixels of `image` that differ from its top-left pixel (the cell's background).
double coveredFraction(const QImage& image)
{
  const QColor background = image.pixelColor(0, 0);
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
    {
      const QColor c = image.pixelColor(x, y);
      count += std::abs(c.red() - background.red()) + std::abs(c.green() - background.green()) +
          std::abs(c.blue() - background.blue()) > 24;
    }
  return static_cast<double>(count) / (image.width() * image.height());
}

} // namespace

class TestFRepStudio : public QObject
{
  Q_OBJECT
private slots:
  void coordinateRangesFromFile();
  void boxIsTheSolidsBounds();
  void viewFramesTheSolid();
  void screenshotCommandMatchesBaseline();
  void sliderScreenshotMatchesBaseline();
  void errorListShowsFileLineColumn();
  void typingUpdatesView();
  void coarseThenRefinedAndCancelled();
  void objectPickerAndParameters();
  void attributesColourTheSection();
  void spreadsheetCellMovesSliders();
  void spreadsheetRaycastCells();
  void spreadsheetIsTheMappingsSheet();
  void highQualityViewRayCasts();
  void mappingEditorRoundTrip();
  void pathScrubAndPlay();
  void openCloseCycles();
  void exportAnimationWritesMovie();
  void exportAnimationCancels();
  void shapeFilesAreCallable();
  void projectedCoordinateShowsTheSweep();
};

void TestFRepStudio::coordinateRangesFromFile()
{
  const CoordinateRanges ranges = CoordinateRanges::from_model_text(
    "-- frepstudio: x4 = [0, 2]\n--frepstudio: x1=[-4,4.5]\n-- frepstudio: x5 = [3, 1]\n");
  QCOMPARE(ranges.range(3)[1], 2.0);
  QCOMPARE(ranges.range(0)[0], -4.0);
  QCOMPARE(ranges.range(0)[1], 4.5);
  QVERIFY(!ranges.is_from_file(4)); // lo > hi is ignored
  QCOMPARE(ranges.range(4)[0], 0.0);
  QCOMPARE(ranges.range(4)[1], 1.0);
  QCOMPARE(ranges.range(2)[0], -10.0);

  auto window = shownWindow();
  QVERIFY(window);
  window->setModelText("-- frepstudio: x4 = [0, 2]\n-- frepstudio: x1 = [-4, 4]\n"
                       "m(x[4], a[1])\n{\n  m = 1 - x[1]^2 - x[2]^2 - x[3]^2 + x[4];\n}\n");
  QVERIFY(wait_until_settled(*window, kSettleMs));
  auto* spin = window->findChild<QDoubleSpinBox*>("x4Spin");
  QVERIFY(spin);
  QCOMPARE(spin->minimum(), 0.0);
  QCOMPARE(spin->maximum(), 2.0);
  QVERIFY(window->sectionView()->cellCount() > 0);
}

void TestFRepStudio::boxIsTheSolidsBounds()
{
  // A unit ball: x1..x3 are its own bounds with the margin, not hfp's [-10, 10].
  const ModelAnalysis ball = analyse_model(kUnitBall, "ball.hf", 1);
  QVERIFY(ball.ok());
  const CoordinateRanges& ranges = ball.objects.at(0).ranges;
  for (int i = 0; i < 3; ++i)
  {
    QVERIFY2(aboutBallBounds(ranges.range(i), 1.0), qPrintable(rangeText(ranges.range(i))));
    QVERIFY(ranges.is_from_solid(i));
  }
  QVERIFY(ranges.note().empty());

  // A line of the file wins, for its coordinate only.
  const ModelAnalysis lined =
    analyse_model("-- frepstudio: x1 = [-4, 4.5]\n" + kUnitBall, "lined.hf", 2);
  QVERIFY(lined.ok());
  const CoordinateRanges& line = lined.objects.at(0).ranges;
  QCOMPARE(line.range(0)[0], -4.0);
  QCOMPARE(line.range(0)[1], 4.5);
  QVERIFY(line.is_from_file(0) && !line.is_from_solid(0));
  QVERIFY2(aboutBallBounds(line.range(1), 1.0), qPrintable(rangeText(line.range(1))));

  // A half-space cannot be bounded: hfp's box, and a note that says so and how to choose one.
  const ModelAnalysis half = analyse_model(kHalfSpace, "half.hf", 3);
  QVERIFY(half.ok());
  const CoordinateRanges& open = half.objects.at(0).ranges;
  for (int i = 0; i < 3; ++i)
  {
    QCOMPARE(open.range(i)[0], -10.0);
    QCOMPARE(open.range(i)[1], 10.0);
    QVERIFY(!open.is_from_solid(i));
  }
  const QString note = QString::fromStdString(open.note());
  QVERIFY2(note.contains("reaches the edge of [-1000, 1000]") &&
             note.contains("x1, x2, x3 keep [-10, 10]") && note.contains("-- frepstudio: x1 ="),
    qPrintable(note));

  // Meta5D (not bounded in 5-D): x1..x3 cover its four key shapes, the sections at the corners
  // of the sliders' [0, 1]^2, each bounded here on its own (no margin); x4 and x5 keep [0, 1].
  QFile in(kMeta5D);
  QVERIFY(in.open(QIODevice::ReadOnly));
  const ModelAnalysis meta5d = analyse_model(in.readAll().toStdString(), "meta5d.hf", 4);
  QVERIFY(meta5d.ok());
  const auto object = [&](const std::string& name) -> const ObjectSummary&
  {
    return *std::find_if(meta5d.objects.begin(),
      meta5d.objects.end(),
      [&](const ObjectSummary& o) { return o.name == name; });
  };
  const CoordinateRanges& box = object("my_model").ranges;
  QVERIFY(box.note().empty());
  QCOMPARE(box.range(3), (std::array<double, 2>{ 0.0, 1.0 }));
  QCOMPARE(box.range(4), (std::array<double, 2>{ 0.0, 1.0 }));
  frep::mesh::SolidBoundsOptions tight;
  tight.margin = 0;
  for (const char* key : { "cat", "robot", "nihon", "roblet" })
  {
    const frep::mesh::SolidBounds shape =
      frep::mesh::find_solid_bounds(object(key).model->tape(), tight);
    QVERIFY2(shape.bounded(), key);
    for (int i = 0; i < 3; ++i)
    {
      QVERIFY(box.is_from_solid(i));
      QVERIFY2(box.range(i)[0] <= shape.box[i].lo && shape.box[i].hi <= box.range(i)[1],
        qPrintable(QString("%1: x%2 in [%3, %4], the box %5")
                     .arg(key)
                     .arg(i + 1)
                     .arg(shape.box[i].lo)
                     .arg(shape.box[i].hi)
                     .arg(rangeText(box.range(i)))));
    }
  }
}

void TestFRepStudio::viewFramesTheSolid()
{
  auto window = shownWindow();
  QVERIFY(window);
  // The unit ball spans at least half of the view's height or width (the issue's measure; with
  // [-10, 10] it was a twentieth). The view fits the box's corners (with the axes' labels
  // beside), from hfp's oblique direction: a ball in its box gets no more than about 0.55.
  window->setModelText(QString::fromStdString(kUnitBall));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(aboutBallBounds(window->currentObjectSummary()->ranges.range(0), 1.0));
  QCOMPARE(window->errorList()->count(), 0);
  const auto [ball_height, ball_width] = greenExtent(window->sectionView()->renderToImage());
  qInfo("the unit ball spans %.3f of the section view's height and %.3f of its width", ball_height,
    ball_width);
  QVERIFY2(std::max(ball_height, ball_width) > 0.5,
    qPrintable(QString("the ball spans %1 of the view's height, %2 of its width")
                 .arg(ball_height)
                 .arg(ball_width)));

  // A half-space is drawn in hfp's box and said so, once, in the error list (not an error).
  window->setModelText(QString::fromStdString(kHalfSpace));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(window->sectionView()->cellCount() > 0);
  ErrorListWidget* errors = window->errorList();
  QCOMPARE(errors->count(), 1);
  QCOMPARE(errors->errorCount(), 0);
  QVERIFY2(errors->item(0)->text().startsWith("<editor>: warning: my_model: the solid reaches") &&
             errors->item(0)->text().contains("keep [-10, 10]"),
    qPrintable(errors->item(0)->text()));
  // A typo lists its error beside the warning of the model still shown; mending it keeps one row.
  window->setModelText(QString::fromStdString(kHalfSpace).replace("x[1];", "x[1] +;"));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(errors->errorCount(), 1);
  QCOMPARE(errors->count(), 2);
  window->setModelText(QString::fromStdString(kHalfSpace).replace("x[1];", "x[2];"));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(errors->count(), 1);
  // A bounded solid again: the warning goes.
  window->setModelText(QString::fromStdString(kUnitBall));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(errors->count(), 0);

  // Meta5D's key shapes fill their common box [-10, 10]^3 (see its header): its box is about
  // hfp's, [-9.7, 9.7] x [-9.8, 9.7] x [-8.1, 8.1], and Cat, at x4 = x5 = 0, is framed by the
  // view's fit of the box's corners (0.36 of the height before: hfp's box, fitted by its
  // bounding sphere).
  QVERIFY(window->loadFile(kMeta5D));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  const auto [cat_height, cat_width] = greenExtent(window->sectionView()->renderToImage());
  QVERIFY2(std::max(cat_height, cat_width) > 0.4,
    qPrintable(QString("Cat spans %1 of the view's height, %2 of its width")
                 .arg(cat_height)
                 .arg(cat_width)));

  // A 5-D ball whose radius follows x4 and x5 (0.89 to 1.1 over the sliders' [0, 1]^2; not
  // bounded in 5-D): x1..x3 cover the sections at the corners, and every cell of the spreadsheet
  // frames its ball.
  window->setModelText("my_model(x[5], a[1])\n{\n  my_model = 1 + 0.2 * x[4] - 0.2 * x[5] - "
                       "x[1]^2 - x[2]^2 - x[3]^2;\n}\n");
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY2(aboutBallBounds(window->currentObjectSummary()->ranges.range(1), std::sqrt(1.2)),
    qPrintable(rangeText(window->currentObjectSummary()->ranges.range(1))));
  window->showSpreadsheet(true);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  SpreadsheetPanel* sheet = window->spreadsheetPanel();
  QCOMPARE(sheet->finishedCells(), 25);
  for (const auto& [row, column] : { std::pair{ 0, 0 }, { 0, 4 }, { 4, 0 }, { 4, 4 } })
  {
    const auto [height, width] =
      coveredExtent(sheet->cell(row, column)->icon().pixmap(120).toImage());
    QVERIFY2(std::max(height, width) > 0.5,
      qPrintable(QString("cell (%1, %2) spans %3 of its height, %4 of its width")
                   .arg(row)
                   .arg(column)
                   .arg(height)
                   .arg(width)));
  }
}

void TestFRepStudio::screenshotCommandMatchesBaseline()
{
  const QString out = QStringLiteral(FREPSTUDIO_TEST_OUTPUT "/command-meta5d.png");
  QFile::remove(out);
  QProcess studio;
  studio.setProcessChannelMode(QProcess::ForwardedChannels);
  studio.start(QStringLiteral(FREPSTUDIO_EXECUTABLE),
    { "--screenshot", out, kMeta5D, "--set", "x4=0.3", "--set", "x5=0.6", "--size",
      QString("%1x%2").arg(kShotSize.width()).arg(kShotSize.height()) });
  QVERIFY(studio.waitForFinished(kSettleMs));
  QCOMPARE(studio.exitStatus(), QProcess::NormalExit);
  QCOMPARE(studio.exitCode(), 0);
  const QImage shot(out);
  QVERIFY(!shot.isNull());
  QVERIFY(non_black_fraction(shot) > 0.9);
  expectBaseline(shot, "FRepStudioMeta5D", "command-meta5d-compared");

  // Bad arguments are refused with exit code 1, no picture.
  QProcess refused;
  refused.start(QStringLiteral(FREPSTUDIO_EXECUTABLE),
    { "--screenshot", out + ".bad.png", kMeta5D, "--set", "x4" });
  QVERIFY(refused.waitForFinished(kSettleMs));
  QCOMPARE(refused.exitCode(), 1);
  QVERIFY(!QFile::exists(out + ".bad.png"));
}

void TestFRepStudio::sliderScreenshotMatchesBaseline()
{
  // The same picture as the command line's --set, reached by moving the sliders.
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kMeta5D));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QSlider* x4 = window->coordinatePanel()->slider(3);
  QSlider* x5 = window->coordinatePanel()->slider(4);
  QVERIFY(x4 && x5);
  QCOMPARE(window->coordinatePanel()->sliderCount(), 2);
  const long long before = window->sectionView()->cellCount();
  x4->setValue(300);
  x5->setValue(600);
  QCOMPARE(window->findChild<QDoubleSpinBox*>("x4Spin")->value(), 0.3);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(window->sectionView()->cellCount() != before);
  QCOMPARE(static_cast<std::size_t>(window->sectionView()->cellCount()),
    engineTriangles(
      *window, kMeta5D, "my_model", { std::nullopt, std::nullopt, std::nullopt, 0.3, 0.6 }, 128));
  expectBaseline(capture_window(*window), "FRepStudioMeta5D", "slider-meta5d");
}

void TestFRepStudio::errorListShowsFileLineColumn()
{
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kData + "/broken.hf"));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  ErrorListWidget* errors = window->errorList();
  QVERIFY(errors->count() >= 1);
  QVERIFY2(errors->item(0)->text().startsWith("broken.hf:5:37: error: "),
    qPrintable(errors->item(0)->text()));
  QVERIFY(window->editor()->errorUnderlineCount() >= 1);
  QCOMPARE(window->sectionView()->cellCount(), 0LL);

  // Clicking the row puts the cursor on the error.
  const QRect row = errors->visualItemRect(errors->item(0));
  QTest::mouseClick(errors->viewport(), Qt::LeftButton, {}, row.center());
  QCOMPARE(window->editor()->cursorLocation().line, 5);
  QCOMPARE(window->editor()->cursorLocation().column, 37);

  // Deleting the stray "* " fixes it: the list empties, the underline goes, the ball appears.
  QTest::keyClick(window->editor(), Qt::Key_Delete);
  QTest::keyClick(window->editor(), Qt::Key_Delete);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(errors->count(), 0);
  QCOMPARE(window->editor()->errorUnderlineCount(), 0);
  QVERIFY(window->sectionView()->cellCount() > 0);
}

void TestFRepStudio::typingUpdatesView()
{
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kData + "/sphere.hf"));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  const long long radius5 = window->sectionView()->cellCount();
  QVERIFY(radius5 > 0);
  double bounds5[6];
  window->sectionView()->section()->GetBounds(bounds5);

  window->editor()->setFocus();
  QVERIFY(window->editor()->find("c, 5)"));
  QTest::keyClicks(window->editor(), "c, 2)");
  // Analysis waits for the typing to pause (the debounce), then runs in the background.
  QVERIFY(!window->isSettled());
  QVERIFY(window->editor()->document()->isModified());
  QVERIFY(window->windowTitle().contains('*'));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  const long long radius2 = window->sectionView()->cellCount();
  double bounds2[6];
  window->sectionView()->section()->GetBounds(bounds2);
  // The box follows the solid's bounds (about [-5.5, 5.5], then [-2.2, 2.2]): the mesh has about
  // as many triangles, but spans 4 instead of 10, and the view fits the new box.
  QVERIFY2(radius2 > 0 && std::abs(bounds5[1] - 5) < 0.05 && std::abs(bounds2[1] - 2) < 0.05,
    qPrintable(QString("radius 5: %1 triangles up to x1 = %2, radius 2: %3 up to %4")
                 .arg(radius5)
                 .arg(bounds5[1])
                 .arg(radius2)
                 .arg(bounds2[1])));
  const auto [height2, width2] = greenExtent(window->sectionView()->renderToImage());
  QVERIFY2(std::max(height2, width2) > 0.5,
    qPrintable(QString("the edited ball spans %1 x %2 of the view").arg(height2).arg(width2)));

  // A typo keeps the last good section on screen and lists the error.
  QTest::keyClicks(window->editor(), " +");
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(window->errorList()->count() >= 1);
  QCOMPARE(window->sectionView()->cellCount(), radius2);
}

void TestFRepStudio::coarseThenRefinedAndCancelled()
{
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kMeta5D));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QSignalSpy shown(window.get(), &StudioMainWindow::sectionShown);
  QSlider* x4 = window->coordinatePanel()->slider(3);
  QVERIFY(x4);

  // The UI keeps turning while the sections are meshed: a 10 ms timer must keep ticking.
  QElapsedTimer gap_clock;
  qint64 longest_gap = 0;
  QTimer ticker;
  ticker.setInterval(10);
  QObject::connect(&ticker, &QTimer::timeout, [&] {
    longest_gap = std::max(longest_gap, gap_clock.restart());
  });
  gap_clock.start();
  ticker.start();
  x4->setValue(500);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  ticker.stop();
  QVERIFY(shown.count() >= 2);
  QCOMPARE(shown.first().at(0).toInt(), StudioMainWindow::kCoarseResolution);
  QCOMPARE(shown.last().at(0).toInt(), StudioMainWindow::kRefinedResolution);
  QVERIFY2(longest_gap < 200, qPrintable(QString("the UI stalled %1 ms").arg(longest_gap)));

  // Ten moves in a row: every older request is cancelled or dropped; only the last value is
  // shown, coarse then refined, and it is the engine's mesh of that value.
  shown.clear();
  for (int i = 0; i < 10; ++i)
    x4->setValue(100 + 50 * i);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(shown.count(), 2);
  QCOMPARE(shown.at(0).at(0).toInt(), StudioMainWindow::kCoarseResolution);
  QCOMPARE(shown.at(1).at(0).toInt(), StudioMainWindow::kRefinedResolution);
  QCOMPARE(static_cast<std::size_t>(shown.at(1).at(1).toLongLong()),
    engineTriangles(
      *window, kMeta5D, "my_model", { std::nullopt, std::nullopt, std::nullopt, 0.55, 0.0 }, 128));
}

void TestFRepStudio::objectPickerAndParameters()
{
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kMeta5D));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  auto* picker = window->findChild<QComboBox*>("objectPicker");
  QVERIFY(picker);
  QCOMPARE(picker->count(), 6);
  QCOMPARE(picker->currentText(), QString("my_model"));
  QVERIFY(window->findChild<QDoubleSpinBox*>("a1Spin"));
  // Meta5D(x1, x2, x3, 1, 0) is Robot point by point: the section must be the engine's Robot.
  QVERIFY(window->setValue("x4", 1.0));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(static_cast<std::size_t>(window->sectionView()->cellCount()),
    engineTriangles(*window, kMeta5D, "robot", {}, 128));

  picker->setCurrentIndex(picker->findText("cat"));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(window->coordinatePanel()->sliderCount(), 0); // cat is 3-D
  // Cat's own box, searched when picked (the analysis searched my_model's only).
  const ObjectSummary* cat = window->currentObjectSummary();
  QVERIFY(cat && cat->searched && cat->ranges.is_from_solid(2));
  QVERIFY2(cat->ranges.range(2)[1] < 6.0, // Meta5D's box reaches 8.1 in x3 (NiHon)
    qPrintable(rangeText(cat->ranges.range(2))));
  QCOMPARE(static_cast<std::size_t>(window->sectionView()->cellCount()),
    engineTriangles(*window, kMeta5D, "cat", {}, 128));

  // A parameter field re-meshes like a slider (Meta5D ignores a[1]: same triangles).
  QSignalSpy shown(window.get(), &StudioMainWindow::sectionShown);
  window->findChild<QDoubleSpinBox*>("a1Spin")->setValue(2.5);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(shown.count() >= 1);
}

void TestFRepStudio::attributesColourTheSection()
{
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kData + "/coloured.hf"));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  vtkPolyData* section = window->sectionView()->section();
  QVERIFY(section && section->GetNumberOfPolys() > 0);
  QVERIFY(section->GetPointData()->GetNormals());
  auto* colours = vtkUnsignedCharArray::SafeDownCast(section->GetPointData()->GetScalars());
  QVERIFY(colours);
  QCOMPARE(QString(colours->GetName()), QString("Colors"));
  // s[1] = 0.5 + x1 / 10: red follows x1 at every point (rounded to a byte).
  double point[3];
  for (vtkIdType i = 0; i < section->GetNumberOfPoints(); i += 997)
  {
    section->GetPoint(i, point);
    const double red = std::clamp(0.5 + point[0] / 10, 0.0, 1.0) * 255;
    QVERIFY(std::abs(colours->GetTypedComponent(i, 0) - red) <= 1.0);
    QCOMPARE(int(colours->GetTypedComponent(i, 1)), 77); // s[2] = 0.3
  }
  // The file's "-- frepstudio: x1 = [-6, 6]" lines set the box.
  double bounds[6];
  section->GetBounds(bounds);
  QVERIFY(bounds[1] <= 6.0 + 1e-9 && bounds[1] > 5.9); // capped by the box at x1 = 6
}

void TestFRepStudio::spreadsheetCellMovesSliders()
{
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kMeta5D));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  SpreadsheetPanel* sheet = window->spreadsheetPanel();
  QCOMPARE(sheet->cellCount(), 0); // hidden: nothing computed
  window->showSpreadsheet(true);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  // The paper's layout: rows x5, columns x4, 5 x 5 cells.
  QCOMPARE(sheet->rowCoordinate(), 1);
  QCOMPARE(sheet->columnCoordinate(), 0);
  QCOMPARE(sheet->cellCount(), 25);
  QCOMPARE(sheet->finishedCells(), 25);
  // At 1280 px wide every column is visible: the cells shrink to fit the width (issue 32).
  window->resize(1280, 800);
  QApplication::processEvents();
  const QScrollArea* scroll = sheet->findChild<QScrollArea*>();
  QVERIFY(scroll);
  const QToolButton* last = sheet->cell(0, 4);
  const int right = last->mapTo(scroll->viewport(), QPoint(last->width(), 0)).x();
  QVERIFY2(right <= scroll->viewport()->width(),
    qPrintable(QString("the x4 = 1 column ends at %1, the view is %2 wide")
                 .arg(right).arg(scroll->viewport()->width())));
  // Corners differ (Cat, Robot, NiHon, Rob_let), and no cell is empty.
  const QImage cat = sheet->cell(0, 0)->icon().pixmap(120).toImage();
  const QImage roblet = sheet->cell(4, 4)->icon().pixmap(120).toImage();
  QVERIFY(!cat.isNull() && !roblet.isNull());
  QVERIFY(testing::compare_images(cat, roblet).changed_pixels > 0.01);

  // Moving a slider that is a row or column does not lay the sheet out again.
  window->setValue("x4", 0.9);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(sheet->cell(0, 0)->icon().pixmap(120).toImage(), cat);

  // Clicking cell (x5 = 0.5, x4 = 0.75) moves the sliders there and shows that section.
  QTest::mouseClick(sheet->cell(2, 3), Qt::LeftButton);
  QCOMPARE(window->findChild<QDoubleSpinBox*>("x4Spin")->value(), 0.75);
  QCOMPARE(window->findChild<QDoubleSpinBox*>("x5Spin")->value(), 0.5);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(window->sectionView()->isVisible());
  QCOMPARE(static_cast<std::size_t>(window->sectionView()->cellCount()),
    engineTriangles(
      *window, kMeta5D, "my_model", { std::nullopt, std::nullopt, std::nullopt, 0.75, 0.5 }, 128));
}

void TestFRepStudio::spreadsheetRaycastCells()
{
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kMeta5D));
  window->showSpreadsheet(true);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  SpreadsheetPanel* sheet = window->spreadsheetPanel();
  QCOMPARE(sheet->finishedCells(), 25);
  const QImage meshed = sheet->cell(2, 2)->icon().pixmap(120).toImage();

  // The "Ray-cast" box draws the same 25 cells by rays: the same shapes in the same places
  // (coverage within a few per cent of the meshed cells'), not the same pixels.
  sheet->setRaycast(true);
  QCOMPARE(sheet->finishedCells(), 0);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(sheet->finishedCells(), 25);
  const QImage cast = sheet->cell(2, 2)->icon().pixmap(120).toImage();
  QVERIFY(!cast.isNull());
  QVERIFY(testing::compare_images(cast, meshed).changed_pixels > 0.01);
  const double meshed_cover = coveredFraction(meshed), cast_cover = coveredFraction(cast);
  QVERIFY2(meshed_cover > 0.05 && std::abs(cast_cover - meshed_cover) < 0.03,
    qPrintable(QString("covered: meshed %1, ray-cast %2").arg(meshed_cover).arg(cast_cover)));
  for (const auto& [row, column] : { std::pair{ 0, 0 }, { 0, 4 }, { 4, 0 }, { 4, 4 } })
    QVERIFY(coveredFraction(sheet->cell(row, column)->icon().pixmap(120).toImage()) > 0.03);
}

// The panel's sheet is a multimedia mapping drawn by Scene (frepkit map's code): its plan has
// the panel's cells in reading order with the panel's values, x2 up as in the 3-D view, one
// camera for every cell; a model without a 4th coordinate is refused with a message.
void TestFRepStudio::spreadsheetIsTheMappingsSheet()
{
  const auto compile = [](const std::string& text)
  { return frep::load_model(frep::ModelSource::from_text(text)).model; };
  SheetRequest request;
  request.base.model =
    compile("m(x[5], a[1]) { m = 1 + x[4] - x[5] / 2 - x[1]^2 - x[2]^2 / 4 - x[3]^2; }");
  QVERIFY(request.base.model);
  request.base.fixed_values = { 0.3, 0.6 };
  request.base.lo = { -3, -3, -3 };
  request.base.hi = { 3, 3, 3 };
  request.base.pixels = 48;
  request.base.resolution = 24;
  request.row_coordinate = 1;    // x5
  request.column_coordinate = 0; // x4
  request.row_values = { 0, 0.5, 1 };
  request.column_values = { 0, 1 };
  const frep::mapping::PlanResult planned =
    frep::mapping::make_plan(sheet_mapping(request, false), frep::mapping::hyperfun_coordinates(5));
  QVERIFY2(planned.ok(), frep::mapping::format_errors(planned.errors).c_str());
  const frep::mapping::Plan& plan = planned.plan;
  QCOMPARE(plan.cells.size(), std::size_t(6));
  for (std::size_t i = 0; i < plan.cells.size(); ++i)
  {
    QCOMPARE(plan.cells[i].values[3], request.column_values[i % 2]);
    QCOMPARE(plan.cells[i].values[4], request.row_values[i / 2]);
  }
  // World x, y, z are driven by x1, x3, x2: x2 is up, as in the section view.
  QCOMPARE(plan.world_coordinates, (std::array<int, 3>{ 0, 2, 1 }));

  std::string error;
  const auto keep_going = [] { return true; };
  const std::unique_ptr<SheetRenderer> sheet =
    SheetRenderer::prepare(request, std::make_shared<frep::ThreadPool>(2), keep_going, &error);
  QVERIFY2(sheet, error.c_str());
  QCOMPARE(sheet->cellCount(), std::size_t(6));
  // The ball stands taller than it is wide (x2 has a quarter of the weight): up in the picture.
  const QImage cell = sheet->cell(5, keep_going, &error);
  QVERIFY2(!cell.isNull(), error.c_str());
  QCOMPARE(cell.size(), QSize(48, 48));
  const auto [height, width] = coveredExtent(cell);
  QVERIFY2(height > width * 1.3,
    qPrintable(
      QString("the ball spans %1 of the cell's height, %2 of its width").arg(height).arg(width)));
  QVERIFY(sheet
            ->cell(
              0, [] { return false; }, &error)
            .isNull()); // cancelled: nothing
  QVERIFY(error.empty());

  // Drawn by rays at another resolution, the same sheet frames the same: the framing is taken
  // over, not found again. Other row values: framed again, with progress.
  SheetRequest rays = request;
  rays.base.raycast = true;
  rays.base.resolution = 16;
  const std::unique_ptr<SheetRenderer> drawn_by_rays =
    SheetRenderer::prepare(rays, nullptr, keep_going, &error, sheet->framing());
  QVERIFY2(drawn_by_rays, error.c_str());
  QCOMPARE(drawn_by_rays->framing(), sheet->framing());
  SheetRequest moved = request;
  moved.row_values = { 0, 0.5, 0.8 };
  std::vector<double> framed;
  const std::unique_ptr<SheetRenderer> other = SheetRenderer::prepare(moved, nullptr, keep_going,
    &error, sheet->framing(), [&framed](double f) { framed.push_back(f); });
  QVERIFY2(other, error.c_str());
  QVERIFY(other->framing() != sheet->framing());
  QVERIFY(!framed.empty() && framed.back() == 1.0);

  // One coordinate beyond x1..x3: a column of rows. None: refused.
  request.base.model = compile("m(x[4], a[1]) { m = 1 + x[4] - x[1]^2 - x[2]^2 - x[3]^2; }");
  request.base.fixed_values = { 0.5 };
  request.row_coordinate = 0;
  request.column_coordinate = -1;
  request.column_values.clear();
  const std::unique_ptr<SheetRenderer> rows =
    SheetRenderer::prepare(request, nullptr, keep_going, &error);
  QVERIFY2(rows, error.c_str());
  QCOMPARE(rows->cellCount(), std::size_t(3));
  request.base.model = compile("m(x[3], a[1]) { m = 1 - x[1]^2 - x[2]^2 - x[3]^2; }");
  request.base.fixed_values.clear();
  QVERIFY(!SheetRenderer::prepare(request, nullptr, keep_going, &error));
  QVERIFY(error.find("beyond x1..x3") != std::string::npos);
}

void TestFRepStudio::highQualityViewRayCasts()
{
  auto window = shownWindow();
  QVERIFY(window);
  window->setModelText("m(x[3], a[1])\n{\n  m = 25 - x[1]^2 - x[2]^2 - x[3]^2;\n}\n");
  QVERIFY(wait_until_settled(*window, kSettleMs));
  SectionView* view = window->sectionView();
  QVERIFY(!view->showingPicture());
  const QImage meshed = view->renderToImage();

  // The resting section ray-cast at the view's camera: the same sphere, as large (13110 and
  // 13221 pixels when written), shaded differently.
  window->setHighQuality(true);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(view->showingPicture());
  const QImage cast = view->renderToImage();
  // Written next to the test binary, to look at.
  meshed.save(QStringLiteral(FREPSTUDIO_TEST_OUTPUT) + "/high-quality-mesh.png");
  cast.save(QStringLiteral(FREPSTUDIO_TEST_OUTPUT) + "/high-quality-raycast.png");
  const int meshed_green = greenPixels(meshed), cast_green = greenPixels(cast);
  QVERIFY2(meshed_green > 10000 && std::abs(cast_green - meshed_green) < 0.03 * meshed_green,
    qPrintable(QString("sphere pixels: meshed %1, ray-cast %2").arg(meshed_green).arg(cast_green)));
  QVERIFY(testing::compare_images(cast, meshed).changed_pixels > 0.01);

  // Moving the camera shows the mesh; the picture of the new view follows when it rests.
  QWidget* canvas = view->vtkWidget();
  const QPoint centre = canvas->rect().center();
  QTest::mousePress(canvas, Qt::LeftButton, {}, centre);
  QTest::mouseMove(canvas, centre + QPoint(60, 20));
  QVERIFY(!view->showingPicture());
  QTest::mouseRelease(canvas, Qt::LeftButton, {}, centre + QPoint(60, 20));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(view->showingPicture());

  window->setHighQuality(false);
  QVERIFY(!view->showingPicture());
}

void TestFRepStudio::mappingEditorRoundTrip()
{
  auto window = shownWindow();
  QVERIFY(window);
  MappingEditor* editor = window->mappingEditor();
  const QString mapping = QStringLiteral(FREPSTUDIO_EXAMPLES_DIR "/homotopic/homotopic.json");
  QVERIFY(editor->loadFile(mapping));
  QFile in(mapping);
  QVERIFY(in.open(QIODevice::ReadOnly));
  const frep::mapping::Spec original = frep::mapping::load_mapping(in.readAll().toStdString()).spec;
  QVERIFY(editor->spec() == original);
  QTableWidget* table = editor->table();
  QCOMPARE(table->rowCount(), 10); // x1..x3 one channel each, x4 three, x5 four
  QCOMPARE(table->item(3, 0)->text(), QString("x4"));
  QCOMPARE(qobject_cast<QComboBox*>(table->cellWidget(3, 1))->currentText(),
    QString("spreadsheet"));

  // Unchanged: the saved file reads back as the same spec.
  const QString same = QStringLiteral(FREPSTUDIO_TEST_OUTPUT "/mapping-same.json");
  QVERIFY(editor->saveFile(same));
  QFile same_file(same);
  QVERIFY(same_file.open(QIODevice::ReadOnly));
  QVERIFY(frep::mapping::load_mapping(same_file.readAll().toStdString()).spec == original);

  // Edited: x1's channel becomes fixed with range [-5, 5]; nothing else changes.
  qobject_cast<QComboBox*>(table->cellWidget(0, 1))->setCurrentIndex(3); // "fixed"
  table->item(0, 2)->setText("-5");
  table->item(0, 3)->setText("5");
  frep::mapping::Spec expected = original;
  expected.coordinates[0].channels[0].type = frep::mapping::Channel::Type::Fixed;
  expected.coordinates[0].channels[0].range = frep::mapping::Interval{ -5, 5 };
  QVERIFY(editor->spec() == expected);
  const QString edited = QStringLiteral(FREPSTUDIO_TEST_OUTPUT "/mapping-edited.json");
  QVERIFY(editor->saveFile(edited));
  QFile edited_file(edited);
  QVERIFY(edited_file.open(QIODevice::ReadOnly));
  const auto reread = frep::mapping::load_mapping(edited_file.readAll().toStdString());
  QVERIFY(reread.ok());
  QVERIFY(reread.spec == expected);

  // A bad file is refused with the JSON place of the problem; the editor keeps its mapping.
  const QString bad = QStringLiteral(FREPSTUDIO_TEST_OUTPUT "/mapping-bad.json");
  QFile bad_file(bad);
  QVERIFY(bad_file.open(QIODevice::WriteOnly));
  bad_file.write(R"({ "version": 1, "coordinates": { "x4": [{ "type": "nonsense" }] } })");
  bad_file.close();
  QVERIFY(!editor->loadFile(bad));
  QVERIFY(!editor->errors().isEmpty());
  QVERIFY2(editor->errors().join('\n').contains("coordinates.x4"),
    qPrintable(editor->errors().join('\n')));
  QVERIFY(editor->spec() == expected);
}

void TestFRepStudio::pathScrubAndPlay()
{
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kMeta5D));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  PathPanel* path = window->pathPanel();
  QVERIFY(path->isEnabled());
  QCOMPARE(path->axes()[0], 0); // x4 across, x5 up
  QCOMPARE(path->axes()[1], 1);
  const auto sampled = frep::mapping::SampledPath::make(path->path());
  QVERIFY(sampled.ok());

  // Scrubbing to the middle puts the sliders on the path's middle (3 decimals in the spin box).
  path->scrubSlider()->setValue(500);
  const auto middle = sampled.path.point_at(0.5);
  QVERIFY(std::abs(window->findChild<QDoubleSpinBox*>("x4Spin")->value() - middle[0]) < 6e-4);
  QVERIFY(std::abs(window->findChild<QDoubleSpinBox*>("x5Spin")->value() - middle[1]) < 6e-4);
  QVERIFY(wait_until_settled(*window, kSettleMs));

  // Playing moves along the path showing coarse sections only; pausing refines.
  QSignalSpy shown(window.get(), &StudioMainWindow::sectionShown);
  path->play();
  QTest::qWait(600);
  // Two coarse sections take ~0.1 s on an idle machine; under a parallel build they can take
  // longer than the wait (seen once), so give them time before judging.
  QTRY_VERIFY_WITH_TIMEOUT(shown.count() >= 2, 10000);
  QVERIFY(path->isPlaying());
  QVERIFY(path->position() > 0.5);
  int refined_while_playing = 0;
  for (const auto& frame : shown)
    refined_while_playing += frame.at(0).toInt() == StudioMainWindow::kRefinedResolution;
  QVERIFY(shown.count() >= 2);
  QCOMPARE(refined_while_playing, 0);
  path->pause();
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(shown.last().at(0).toInt(), StudioMainWindow::kRefinedResolution);

  // Editing: a left click adds a control point, a right click on it removes it.
  const int before = static_cast<int>(path->controlPoints().size());
  PathCanvas* canvas = path->canvas();
  const QPoint spot = canvas->toPixels({ 0.3, 0.7 }).toPoint();
  QTest::mouseClick(canvas, Qt::LeftButton, {}, spot);
  QCOMPARE(static_cast<int>(path->controlPoints().size()), before + 1);
  QVERIFY(std::abs(path->controlPoints().back()[0] - 0.3) < 0.01);
  QVERIFY(std::abs(path->controlPoints().back()[1] - 0.7) < 0.01);
  QTest::mouseClick(canvas, Qt::RightButton, {}, spot);
  QCOMPARE(static_cast<int>(path->controlPoints().size()), before);

  // A mapping file's path is taken over (homotopic.json: the same six points, closed).
  path->setControlPoints({ { 0, 0 }, { 1, 1 } });
  QVERIFY(window->mappingEditor()->loadFile(
    QStringLiteral(FREPSTUDIO_EXAMPLES_DIR "/homotopic/homotopic.json")));
  QCOMPARE(path->controlPoints().size(), std::size_t(6));
  QVERIFY(path->path() == *window->mappingEditor()->spec().animation.path);

  // A 3-D object has nothing to animate.
  window->selectObject("cat");
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(!path->isEnabled());
}

void TestFRepStudio::openCloseCycles()
{
  const int top_levels = QApplication::topLevelWidgets().size();
  const auto examples = StudioMainWindow::examples();
  for (int i = 0; i < 2 * examples.size(); ++i)
  {
    auto window = shownWindow();
    QVERIFY(window);
    QVERIFY(window->loadFile(examples[i % examples.size()].second));
    if (i % 2 == 0)
      QVERIFY(wait_until_settled(*window, kSettleMs));
    else
      QTest::qWait(40); // close while the analysis or the mesher is still running
  }
  QApplication::processEvents();
  QCOMPARE(QApplication::topLevelWidgets().size(), top_levels);

  // The application still works after the cycles.
  auto window = shownWindow();
  QVERIFY(window);
  QVERIFY(window->loadFile(kData + "/sphere.hf"));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(window->sectionView()->cellCount() > 0);
}

namespace
{
// morph4d: a ball turning into a torus as x4 goes from 0 to 1; x4 is time (and pitch).
QString morphMapping(double duration, double fps)
{
  return QString(R"({
  "coordinates": {
    "x1": [{ "type": "world", "axis": "x", "range": [-2.4, 2.4] }],
    "x2": [{ "type": "world", "axis": "y", "range": [-2.4, 2.4] }],
    "x3": [{ "type": "world", "axis": "z", "range": [-2.4, 2.4] }],
    "x4": [{ "type": "dynamic", "range": [0, 1] },
           { "type": "audio", "parameter": "pitch", "range": [0, 1], "target": [220, 440] }] },
  "animation": { "duration": %1, "fps": %2 },
  "world": { "resolution": 24 },
  "render": { "width": 160, "height": 90 } })")
    .arg(duration)
    .arg(fps);
}

int framesIn(const QString& directory)
{
  return static_cast<int>(
    QDir(directory + "/frames").entryList({ "frame_*.png" }, QDir::Files).size());
}
} // namespace

void TestFRepStudio::exportAnimationWritesMovie()
{
  auto window = shownWindow();
  QVERIFY(window->loadFile(QStringLiteral(FREPSTUDIO_EXAMPLES_DIR "/mapping/morph4d.hf")));
  const auto loaded = frep::mapping::load_mapping(morphMapping(1, 8).toStdString());
  QVERIFY(loaded.errors.empty());
  window->mappingEditor()->setSpec(loaded.spec);
  const QString out = QStringLiteral(FREPSTUDIO_TEST_OUTPUT "/export-movie");
  QDir(out).removeRecursively();
  QString error;
  AnimationExport* job = window->exportAnimation(out, &error);
  QVERIFY2(job, qPrintable(error));
  QCOMPARE(job->expectedFrames(), 8);
  QSignalSpy progress(job, &AnimationExport::progress);
  QSignalSpy finished(job, &AnimationExport::finished);
  QVERIFY(finished.wait(120000));
  QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
  QVERIFY(progress.count() >= 2); // 0 at the start, then on the way
  QCOMPARE(progress.last().at(0).toInt(), 1000);
  QCOMPARE(progress.last().at(1).toInt(), 1000);
  QCOMPARE(framesIn(out), 8);
  QVERIFY(QFileInfo(out + "/animation.mp4").size() > 1000);
  QVERIFY(QFileInfo(out + "/animation.wav").size() > 1000);
  QVERIFY(QFileInfo::exists(out + "/manifest.json"));
}

void TestFRepStudio::exportAnimationCancels()
{
  auto window = shownWindow();
  QVERIFY(window->loadFile(QStringLiteral(FREPSTUDIO_EXAMPLES_DIR "/mapping/morph4d.hf")));
  // 600 frames: long enough to be cancelled in the middle
  const auto loaded = frep::mapping::load_mapping(morphMapping(25, 24).toStdString());
  QVERIFY(loaded.errors.empty());
  window->mappingEditor()->setSpec(loaded.spec);
  const QString out = QStringLiteral(FREPSTUDIO_TEST_OUTPUT "/export-cancel");
  QDir(out).removeRecursively();
  QString error;
  AnimationExport* job = window->exportAnimation(out, &error);
  QVERIFY2(job, qPrintable(error));
  QSignalSpy finished(job, &AnimationExport::finished);
  QTRY_VERIFY_WITH_TIMEOUT(framesIn(out) >= 3, 60000);
  job->cancel();
  QVERIFY(finished.wait(30000));
  QVERIFY(!finished.at(0).at(0).toBool());
  QVERIFY(finished.at(0).at(1).toString().contains("cancelled"));
  const int kept = framesIn(out);
  QVERIFY(kept >= 3 && kept < 600);
  QVERIFY(!QFileInfo::exists(out + "/animation.mp4"));
  // nothing half-written: no temporary files next to the frames
  const QStringList leftovers =
    QDir(out + "/frames").entryList({ "*.tmp*", "*partial*" }, QDir::Files | QDir::Hidden);
  QVERIFY2(leftovers.isEmpty(), qPrintable(leftovers.join(", ")));
}

void TestFRepStudio::shapeFilesAreCallable()
{
  const QString stl = QStringLiteral(FREPSTUDIO_EXAMPLES_DIR "/metamorphosis/pebble.stl");
  const QString model = "m(x[3], a[1])\n{\n  m = pebble(x);\n}\n";
  auto window = shownWindow();
  QVERIFY(window);

  // Without the shape the call is an error of the model, and nothing is drawn.
  window->setModelText(model);
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(window->errorList()->count() >= 1);
  QCOMPARE(window->sectionView()->cellCount(), 0LL);

  // A file that cannot be read: false, the shape and the file named, nothing changes.
  QString error;
  QVERIFY(!window->setUserInputs({ {}, { "pebble=/nonexistent/pebble.stl" }, false }, &error));
  QCOMPARE(error, QStringLiteral("--shape pebble: /nonexistent/pebble.stl: cannot open the file"));
  QVERIFY(!window->setUserInputs({ {}, { "pebble" }, false }, &error));
  QVERIFY2(error.contains("expected name=FILE"), qPrintable(error));

  // With the mesh the same text analyses again by itself and the pebble is drawn.
  QVERIFY2(window->setUserInputs({ {}, { "pebble=" + stl }, false }, &error), qPrintable(error));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QCOMPARE(window->errorList()->count(), 0);
  QVERIFY(window->sectionView()->cellCount() > 0);

  // The export gets absolute paths, the volume's iso suffix kept, and the unsigned flag.
  const UserInputs relative{ { "libshapes.so" }, { "ct=scan.vti:0.5" }, true };
  const UserInputs absolute = absoluteUserInputs(relative);
  const QString cwd = QDir::currentPath();
  QCOMPARE(absolute.libraries, QStringList{ cwd + "/libshapes.so" });
  QCOMPARE(absolute.shapes, QStringList{ "ct=" + cwd + "/scan.vti:0.5" });
  QVERIFY(absolute.unsignedDistance);
}

int main(int argc, char* argv[])
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("FRepKit");
  QApplication::setApplicationName("FRepStudioTests");
  TestFRepStudio test;
  return QTest::qExec(&test, argc, argv);
}

/// The volume a closed, outward triangle mesh encloses (divergence theorem).
double enclosedVolume(vtkPolyData* poly)
{
  double volume = 0;
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  vtkCellArray* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n != 3)
      continue;
    double p[3][3];
    for (int k = 0; k < 3; ++k)
      poly->GetPoint(ids[k], p[k]);
    volume += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) / 6.0;
  }
  return volume;
}

void TestFRepStudio::projectedCoordinateShowsTheSweep()
{
  // A sphere of radius 0.5 moving from x = -1 to 1 as x4 goes 0 -> 1: at the slider's value a
  // ball, with x4 projected the capsule it sweeps (pi r^2 2 + 4/3 pi r^3).
  auto window = shownWindow();
  QVERIFY(window);
  window->setModelText("moving(x[4], a[1])\n{\n  moving = 0.25 - ((x[1] + 1 - 2*x[4])^2 + "
                       "x[2]^2 + x[3]^2);\n}\n");
  QVERIFY(wait_until_settled(*window, kSettleMs));
  const double ball = 4.0 / 3.0 * M_PI * 0.125, capsule = M_PI * 0.25 * 2 + ball;
  QVERIFY(std::abs(enclosedVolume(window->sectionView()->section()) - ball) < 0.03 * ball);
  auto* projected = window->findChild<QCheckBox*>("x4Projected");
  QVERIFY(projected);
  projected->setChecked(true);
  QVERIFY(!window->findChild<QSlider*>("x4Slider")->isEnabled());
  QVERIFY(wait_until_settled(*window, kSettleMs));
  const double swept = enclosedVolume(window->sectionView()->section());
  QVERIFY2(std::abs(swept - capsule) < 0.02 * capsule, qPrintable(QString::number(swept)));
  // Remembered when the model is edited (the panel is rebuilt), cleared by unticking.
  window->setModelText("moving(x[4], a[1])\n{\n  moving = 0.25 - ((x[1] + 1 - 2*x[4])^2 + "
                       "x[2]^2 + x[3]^2);\n  -- edited\n}\n");
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(window->findChild<QCheckBox*>("x4Projected")->isChecked());
  QVERIFY(window->coordinatePanel()->setProjected("X4", false));
  QVERIFY(wait_until_settled(*window, kSettleMs));
  QVERIFY(std::abs(enclosedVolume(window->sectionView()->section()) - ball) < 0.03 * ball);
}

#include "TestFRepStudio.moc"
