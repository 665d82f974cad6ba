// The interactive timings of FRepStudio: moves the x4 slider of Meta5D and measures, from the
// move, when the coarse (32^3) and the refined (128^3) section are on screen (the view's
// frameSwapped). The refined time includes the rest delay (StudioMainWindow::kRefineRestMs)
// the application waits before refining. Run under xvfb-run with QT_QPA_PLATFORM=xcb:
//   xvfb-run -a env QT_QPA_PLATFORM=xcb build/bin/frepstudio_timing [MOVES]
#include "CoordinatePanel.h"
#include "ScreenshotCapture.h"
#include "StudioMainWindow.h"

#include "Eval/thread_pool.h"
#include "Language/parser.h"
#include "Mesh/surface.h"

#include <QApplication>
#include <QFile>
#include <QElapsedTimer>
#include <QSlider>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <cstdio>
#include <vector>

using frepstudio::StudioMainWindow;
using Clock = std::chrono::steady_clock;

namespace
{
double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n == 0 ? 0 : (n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2);
}
}

int main(int argc, char* argv[])
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("FRepKit");
  QApplication::setApplicationName("FRepStudioTiming");
  const int moves = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20;

  // The engine alone, for the breakdown: specialising Meta5D at (x4, x5) and meshing it.
  {
    QFile in(StudioMainWindow::examples()[4].second);
    in.open(QIODevice::ReadOnly);
    const auto parsed = frep::parse_program(in.readAll().toStdString(), "meta5d.hf");
    const auto model = frep::Model::compile(parsed.program,
      frep::ast::select_object(*parsed.program, "my_model")).model;
    auto pool = std::make_shared<frep::ThreadPool>(0);
    std::vector<double> specialise_ms, coarse_ms, refined_ms;
    for (int i = 0; i < moves; ++i)
    {
      frep::Specialisation specialisation;
      specialisation.fixed = { std::nullopt, std::nullopt, std::nullopt,
        ((i * 379 + 100) % 1001) / 1000.0, 0.0 };
      const auto t0 = Clock::now();
      const auto tape = model->specialise(specialisation);
      const auto t1 = Clock::now();
      frep::mesh::ExtractOptions options;
      options.pool = pool;
      frep::GridSpec grid{ { { -10, 10, 32 }, { -10, 10, 32 }, { -10, 10, 32 } } };
      frep::mesh::extract_surface(tape, grid, options);
      const auto t2 = Clock::now();
      for (frep::GridAxis& axis : grid.axes)
        axis.samples = 128;
      frep::mesh::extract_surface(tape, grid, options);
      const auto t3 = Clock::now();
      auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
      specialise_ms.push_back(ms(t0, t1));
      coarse_ms.push_back(ms(t1, t2));
      refined_ms.push_back(ms(t2, t3));
    }
    std::printf("engine only (%zu threads), medians: specialise %.1f ms, mesh 32^3 %.1f ms, "
                "mesh 128^3 %.1f ms\n", static_cast<std::size_t>(pool->size()),
      median(specialise_ms), median(coarse_ms), median(refined_ms));
  }

  StudioMainWindow window;
  window.resize(1280, 800);
  window.show();
  window.loadFile(StudioMainWindow::examples()[4].second); // Meta5D
  if (!frepstudio::wait_until_settled(window, 120000))
    return 1;
  QSlider* x4 = window.coordinatePanel()->slider(3);
  if (!x4)
    return 1;

  QElapsedTimer clock;
  double coarse_ms = -1, refined_ms = -1;
  long long refined_cells = 0;
  QObject::connect(&window, &StudioMainWindow::sectionShown,
    [&](int resolution, long long cells, double) {
      if (resolution == StudioMainWindow::kCoarseResolution && coarse_ms < 0)
        coarse_ms = clock.nsecsElapsed() / 1e6;
      if (resolution == StudioMainWindow::kRefinedResolution)
      {
        refined_ms = clock.nsecsElapsed() / 1e6;
        refined_cells = cells;
      }
    });

  std::vector<double> coarse, refined;
  std::printf("move  x4     coarse_ms  refined_ms  refined_triangles\n");
  for (int i = 0; i < moves; ++i)
  {
    coarse_ms = refined_ms = -1;
    const int step = (i * 379 + 100) % 1001; // spread over [0, 1], never the same twice in a row
    clock.start();
    x4->setValue(step);
    if (!frepstudio::wait_until_settled(window, 120000) || coarse_ms < 0 || refined_ms < 0)
    {
      std::fprintf(stderr, "move %d: no section shown\n", i);
      return 1;
    }
    coarse.push_back(coarse_ms);
    refined.push_back(refined_ms);
    std::printf("%4d  %.3f  %9.1f  %10.1f  %lld\n", i, step / 1000.0, coarse_ms, refined_ms,
      refined_cells);
  }
  std::printf("median: coarse %.1f ms, refined %.1f ms (rest delay %d ms included); max: coarse "
              "%.1f ms, refined %.1f ms\n",
    median(coarse), median(refined), StudioMainWindow::kRefineRestMs,
    *std::max_element(coarse.begin(), coarse.end()),
    *std::max_element(refined.begin(), refined.end()));
  return 0;
}
