// FRepStudio: the HyperFun editor with a live 3-D view of n-D models' cross-sections.
//   FRepStudio [MODEL.hf]
//   FRepStudio --screenshot OUT.png MODEL.hf [--set x4=0.3]... [--object NAME] [--size 1280x800]
//              [--spreadsheet] [--mapping FILE.json] [--high-quality] [--raycast-cells]
// The screenshot mode shows the window once, waits for the refined section, writes OUT.png and
// exits (0 ok, 1 error): for tests and the documentation, under xvfb-run on a headless machine.
#include "ErrorListWidget.h"
#include "MappingEditor.h"
#include "ScreenshotCapture.h"
#include "SpreadsheetPanel.h"
#include "StudioMainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <cstdio>

int main(int argc, char* argv[])
{
  // VTK's widget needs its OpenGL format before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("FRepKit");
  QApplication::setApplicationName("FRepStudio");
  QApplication::setApplicationVersion(FREPSTUDIO_VERSION);

  QCommandLineParser parser;
  parser.setApplicationDescription("FRepStudio: HyperFun modelling in n dimensions");
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption screenshot("screenshot", "Render once, write FILE (PNG) and exit.",
    "FILE");
  const QCommandLineOption set("set", "Set a coordinate or parameter, e.g. x4=0.3 or a1=2.",
    "NAME=VALUE");
  const QCommandLineOption object("object", "The object to show (default my_model, else the "
                                            "first).", "NAME");
  const QCommandLineOption size("size", "Window size for the screenshot (default 1280x800).",
    "WxH", "1280x800");
  const QCommandLineOption timeout("timeout", "Seconds to wait for the refined section.", "S",
    "120");
  const QCommandLineOption spreadsheet("spreadsheet",
    "Show the spreadsheet of cross-sections (the screenshot waits for all its cells).");
  const QCommandLineOption high_quality("high-quality",
    "View > High Quality: the resting section ray-cast instead of meshed.");
  const QCommandLineOption raycast_cells("raycast-cells",
    "The spreadsheet's cells ray-cast instead of meshed (its Ray-cast box).");
  const QCommandLineOption mapping("mapping", "Open a mapping file (JSON) in the Mapping tab.",
    "FILE");
  const QCommandLineOption library("library",
    "A user library (frepkit_user.h) whose functions models may call; repeatable.", "FILE");
  const QCommandLineOption shape("shape",
    "A mesh (.stl, .obj, .ply, .vtp: signed distance, >= 0 inside) or a volume (.vti[:ISO]) "
    "that models call as name(x); repeatable.", "NAME=FILE");
  const QCommandLineOption unsigned_distance("unsigned-distance",
    "Accept open or non-manifold meshes for --shape: their F is minus the unsigned distance.");
  parser.addOptions({ screenshot, set, object, size, timeout, spreadsheet, high_quality,
    raycast_cells, mapping, library, shape, unsigned_distance });
  parser.addPositionalArgument("model", "The HyperFun file to open.", "[MODEL.hf]");
  parser.process(app);

  frepstudio::StudioMainWindow window;
  QString inputs_error;
  const frepstudio::UserInputs inputs{ parser.values(library), parser.values(shape),
    parser.isSet(unsigned_distance) };
  if (!window.setUserInputs(inputs, &inputs_error))
  {
    std::fprintf(stderr, "FRepStudio: %s\n", qPrintable(inputs_error));
    return 1;
  }
  const QStringList sizes = parser.value(size).split('x');
  if (sizes.size() != 2 || sizes[0].toInt() <= 0 || sizes[1].toInt() <= 0)
  {
    std::fprintf(stderr, "FRepStudio: --size wants WIDTHxHEIGHT, got %s\n",
      qPrintable(parser.value(size)));
    return 1;
  }
  window.resize(sizes[0].toInt(), sizes[1].toInt());
  for (const QString& assignment : parser.values(set))
  {
    const int equals = assignment.indexOf('=');
    bool number = false;
    const double value = equals > 0 ? assignment.mid(equals + 1).toDouble(&number) : 0;
    if (!number || !window.setValue(assignment.left(equals).trimmed(), value))
    {
      std::fprintf(stderr, "FRepStudio: --set wants NAME=VALUE (x4=0.3, a1=2), got %s\n",
        qPrintable(assignment));
      return 1;
    }
  }
  if (parser.isSet(object))
    window.selectObject(parser.value(object));

  const QStringList models = parser.positionalArguments();
  if (parser.isSet(screenshot) && models.size() != 1)
  {
    std::fprintf(stderr, "FRepStudio: --screenshot needs one model file\n");
    return 1;
  }
  window.show();
  window.setHighQuality(parser.isSet(high_quality));
  window.spreadsheetPanel()->setRaycast(parser.isSet(raycast_cells));
  if (parser.isSet(spreadsheet))
    window.showSpreadsheet(true);
  if (parser.isSet(mapping) && !window.showMapping(parser.value(mapping)))
  {
    std::fprintf(stderr, "FRepStudio: cannot read the mapping %s:\n%s\n",
      qPrintable(parser.value(mapping)),
      qPrintable(window.mappingEditor()->errors().join('\n')));
    return 1;
  }
  if (!models.isEmpty() && !window.loadFile(models.front()))
  {
    std::fprintf(stderr, "FRepStudio: cannot open %s\n", qPrintable(models.front()));
    if (parser.isSet(screenshot))
      return 1;
  }
  if (models.isEmpty())
    window.loadFile(frepstudio::StudioMainWindow::examples()[4].second); // Meta5D

  if (parser.isSet(screenshot))
  {
    const QString error = frepstudio::write_screenshot(
      window, parser.value(screenshot), parser.value(timeout).toInt() * 1000);
    if (!error.isEmpty())
    {
      std::fprintf(stderr, "FRepStudio: screenshot failed: %s\n", qPrintable(error));
      return 1;
    }
    if (window.analysis() == nullptr || !window.errorList()->messages().isEmpty())
      std::fprintf(stderr, "FRepStudio: note: the model has errors (see the picture)\n");
    return 0;
  }
  return app.exec();
}
