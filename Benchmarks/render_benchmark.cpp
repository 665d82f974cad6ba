// Timing of the mesh renderer (not a test): a ~300k-triangle rippled sphere at 1280 x 720 with
// 2 x 2 supersampling, 1 thread and all threads. Usage: frep_render_benchmark [repeats] [out.ppm]
#include "Imaging/camera.h"
#include "Render/mesh_renderer.h"
#include "test_meshes.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace frep::render;
namespace imaging = frep::imaging;

int main(int argc, char** argv)
{
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  // 548 x 274 cells: 2 * 548 * 273 = 299 208 triangles.
  const test::TestMesh mesh = test::uv_sphere(548, 274, 1.0, 0, 0, 0, 0.1, false);
  MeshInput in;
  in.points = mesh.points;
  in.triangles = mesh.triangles;
  in.colours = mesh.colours;
  const imaging::Camera camera =
    imaging::fit_box({ -1.1, -1.1, -1.1 }, { 1.1, 1.1, 1.1 }, 1280.0 / 720.0, 30, 20);
  std::printf("%zu triangles, %zu points, 1280 x 720, supersample 2\n",
    mesh.triangles.size() / 3,
    mesh.points.size() / 3);
  for (const int threads : { 1, 0 })
  {
    imaging::RenderStyle style;
    style.threads = threads;
    double best = 1e30, total = 0;
    imaging::Image image;
    for (int r = 0; r < repeats; ++r)
    {
      image = imaging::Image(1280, 720, { 1, 1, 1, 1 });
      const auto t0 = std::chrono::steady_clock::now();
      const RenderReport report = render_mesh(image, camera, in, style);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!report.ok())
      {
        std::fprintf(stderr, "%s\n", report.error.c_str());
        return 1;
      }
      best = std::min(best, s);
      total += s;
    }
    std::printf("threads %-3s best %.1f ms, mean %.1f ms over %d runs\n",
      threads == 0 ? "all" : "1",
      best * 1e3,
      total / repeats * 1e3,
      repeats);
    if (argc > 2 && threads == 0)
    {
      const std::string error = imaging::write_ppm(image, argv[2]);
      if (!error.empty())
      {
        std::fprintf(stderr, "%s\n", error.c_str());
      }
    }
  }
  return 0;
}
