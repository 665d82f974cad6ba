// FRepStudio: the HyperFun editor with a live 3-D view of n-D models' cross-sections.
//   FRepStudio [MODEL.hf]
//   FRepStudio --screenshot OUT.png MODEL.hf [--set x4=0.3]... [--object NAME] [--size 1280x800]
//              [--spreadsheet] [--mapping FILE.json] [--high-quality] [--raycast-cells]
// The screenshot mode shows the window once, waits for the refined section, writes OUT.png and
// exits (0 ok, 1 error): for tests and the documentation. Without a display (DISPLAY and
// WAYLAND_DISPLAY unset) --help and --version answer through Qt's offscreen platform, and
// --screenshot starts itself again under `xvfb-run -a` (the packaged VTK draws through GLX).
#include "ErrorListWidget.h"
#include "MappingEditor.h"
#include "ScreenshotCapture.h"
#include "SpreadsheetPanel.h"
#include "StudioMainWindow.h"

#include "picture_size.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{

bool set_in_environment(const char* name)
{
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0';
}

/// Whether the command line has one of `names` (also as --name=VALUE).
bool has_argument(int argc, char* argv[], std::initializer_list<const char*> names)
{
  for (int i = 1; i < argc; ++i)
  {
    for (const char* name : names)
    {
      const std::size_t length = std::strlen(name);
      if (std::strncmp(argv[i], name, length) == 0 &&
          (argv[i][length] == '\0' || argv[i][length] == '='))
      {
        return true;
      }
    }
  }
  return false;
}

/// --screenshot without a display: this program again under `xvfb-run -a`. Returns only when
/// that is impossible, with the exit code.
int run_under_xvfb(int argc, char* argv[])
{
  const char* const kGuard = "FREPSTUDIO_UNDER_XVFB_RUN";
  const bool again = set_in_environment(kGuard); // xvfb-run started us and gave no display
  std::vector<char> self(4096);
  const ssize_t length = ::readlink("/proc/self/exe", self.data(), self.size() - 1);
  if (!again && length > 0)
  {
    self[static_cast<std::size_t>(length)] = '\0';
    std::vector<char*> command{ const_cast<char*>("xvfb-run"), const_cast<char*>("-a"),
      self.data() };
    command.insert(command.end(), argv + 1, argv + argc);
    command.push_back(nullptr);
    ::setenv(kGuard, "1", 1);
    ::execvp(command[0], command.data());
  }
  std::fprintf(stderr,
    "FRepStudio: --screenshot needs an X display: DISPLAY is unset and xvfb-run %s; run it "
    "under an X server (e.g. xvfb-run -a FRepStudio --screenshot ...)\n",
    again ? "gave none" : "cannot be started (is the xvfb package installed?)");
  return 1;
}

/// Qt's platform when there is no display: offscreen for --help and --version (they draw
/// nothing), xvfb-run for --screenshot, a message otherwise (Qt would abort). Returns an exit
/// code when the program must stop here. A platform the user chose (QT_QPA_PLATFORM) is kept.
std::optional<int> choose_platform(int argc, char* argv[])
{
  if (set_in_environment("DISPLAY") || set_in_environment("WAYLAND_DISPLAY") ||
      set_in_environment("QT_QPA_PLATFORM"))
  {
    return std::nullopt;
  }
  if (has_argument(argc, argv, { "-h", "-?", "--help", "--help-all", "-v", "--version" }))
  {
    ::setenv("QT_QPA_PLATFORM", "offscreen", 1);
    return std::nullopt;
  }
  if (has_argument(argc, argv, { "--screenshot" }))
  {
    return run_under_xvfb(argc, argv);
  }
  std::fprintf(stderr,
    "FRepStudio: no display (DISPLAY and WAYLAND_DISPLAY are unset): start it in a desktop "
    "session; --help, --version and --screenshot work without one\n");
  return 1;
}

} // namespace

int main(int argc, char* argv[])
{
  if (const std::optional<int> code = choose_platform(argc, argv))
  {
    return *code;
  }
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
  const QCommandLineOption size("size",
    "Window size, WIDTHxHEIGHT or WIDTH,HEIGHT (default 1280x800).", "WxH", "1280x800");
  const QCommandLineOption timeout("timeout",
    "Seconds the screenshot waits for the refined section (default 120).", "S", "120");
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
  std::string size_error;
  const std::optional<frepkit::PictureSize> window_size =
    frepkit::parse_picture_size(parser.value(size).toStdString(), &size_error);
  if (!window_size)
  {
    std::fprintf(stderr, "FRepStudio: --size: %s\n", size_error.c_str());
    return 1;
  }
  window.resize(window_size->width, window_size->height);
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
    if (window.analysis() == nullptr || window.errorList()->errorCount() > 0)
      std::fprintf(stderr, "FRepStudio: note: the model has errors (see the picture)\n");
    if (!window.errorList()->warning().isEmpty())
      std::fprintf(stderr, "FRepStudio: %s\n", qPrintable(window.errorList()->warning()));
    return 0;
  }
  return app.exec();
}
