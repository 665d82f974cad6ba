// libfive's side of the peer benchmark. The model is compiled by FRepKit to its tape and the tape
// translated into a libfive::Tree (tape_to_libfive.h); libfive then does everything itself:
//
//   libfive_driver eval MODEL OBJECT POINTS VALUES [THREADS=2] [REPEAT=3]
//       libfive::ArrayEvaluator (f32, 256-point batches), one evaluator per thread, each thread
//       a contiguous share of the points; median of REPEAT passes;
//   libfive_driver mesh MODEL OBJECT BOX SAMPLES [WORKERS=2]
//       libfive::Mesh::render (dual contouring, its defaults) over BOX with min_feature such
//       that the octree has SAMPLES-1 cells per axis (a power of two: 255 -> 256 cells);
//   libfive_driver slice MODEL N [WORKERS=2]
//       the N x N sign image over [-1,1]^2 two ways: libfive::Heightmap::render (its own
//       interval-pruned renderer, a one-voxel-deep volume) and the array evaluator brute force;
//
// libfive's sign convention (inside < 0) is used for meshing and images: the tree is -F there.
// Prints "RESULT key=value ..." (or "RESULT cannot_translate=...") for run_peers.sh.
#include "frepkit_model.h"
#include "points.h"
#include "tape_to_libfive.h"

#include <libfive/eval/eval_array.hpp>
#include <libfive/render/brep/mesh.hpp>
#include <libfive/render/brep/region.hpp>
#include <libfive/render/brep/settings.hpp>
#include <libfive/render/discrete/heightmap.hpp>
#include <libfive/render/discrete/voxels.hpp>
#include <libfive/tree/operations.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace
{

constexpr std::size_t kBatch = LIBFIVE_EVAL_ARRAY_SIZE; // 256

/// The model as a libfive tree; false (after printing the RESULT line) when it cannot be.
bool translate(const std::string& path, const std::string& object, libfive::Tree& tree,
  double& seconds)
{
  const auto start = std::chrono::steady_clock::now();
  const peers::LoadedModel model = peers::load_model(path, object);
  const peers::LibfiveTranslation t = peers::tape_to_libfive(*model.tape);
  seconds = peers::seconds_since(start);
  if (!t.unsupported.empty())
  {
    std::printf("RESULT cannot_translate=\"%s\"\n", t.unsupported.c_str());
    return false;
  }
  std::fprintf(stderr, "libfive_driver: %s: %zu tape instructions, %zu checks dropped, %zu by formula\n",
    path.c_str(), model.tape->code.size(), t.dropped_checks, t.approximated);
  tree = t.tree;
  return true;
}

/// Evaluates points [begin, end) of `xyz` into out[] with one evaluator.
void evaluate_range(libfive::ArrayEvaluator& e, const std::vector<double>& xyz, std::size_t begin,
  std::size_t end, float* out)
{
  for (std::size_t first = begin; first < end; first += kBatch)
  {
    const std::size_t count = std::min(kBatch, end - first);
    for (std::size_t j = 0; j < count; ++j)
    {
      const double* p = &xyz[3 * (first + j)];
      e.set(Eigen::Vector3f(float(p[0]), float(p[1]), float(p[2])), j);
    }
    const auto values = e.values(count);
    for (std::size_t j = 0; j < count; ++j)
    {
      out[first + j] = values(j);
    }
  }
}

/// Each of `threads` evaluators takes a contiguous share of the points (whole batches).
double evaluate_all(std::vector<std::unique_ptr<libfive::ArrayEvaluator>>& evaluators,
  const std::vector<double>& xyz, std::size_t n, float* out)
{
  const std::size_t threads = evaluators.size();
  const std::size_t batches = (n + kBatch - 1) / kBatch;
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < threads; ++t)
  {
    const std::size_t begin = std::min(n, batches * t / threads * kBatch);
    const std::size_t end = std::min(n, batches * (t + 1) / threads * kBatch);
    pool.emplace_back([&, t, begin, end] { evaluate_range(*evaluators[t], xyz, begin, end, out); });
  }
  for (std::thread& th : pool)
  {
    th.join();
  }
  return peers::seconds_since(start);
}

std::vector<std::unique_ptr<libfive::ArrayEvaluator>> make_evaluators(const libfive::Tree& tree,
  int threads)
{
  // One deck (libfive's compiled tape), shared by the evaluators as libfive's own renderers do.
  auto deck = std::make_shared<libfive::Deck>(tree);
  std::vector<std::unique_ptr<libfive::ArrayEvaluator>> evaluators;
  for (int t = 0; t < threads; ++t)
  {
    evaluators.push_back(std::make_unique<libfive::ArrayEvaluator>(deck));
  }
  return evaluators;
}

int eval(int argc, char** argv)
{
  if (argc < 6)
  {
    throw std::runtime_error("usage: libfive_driver eval MODEL OBJECT POINTS VALUES [THREADS] [REPEAT]");
  }
  const int threads = argc > 6 ? std::stoi(argv[6]) : 2;
  const int repeat = argc > 7 ? std::max(1, std::stoi(argv[7])) : 3;
  libfive::Tree tree = libfive::Tree::invalid();
  double translate_seconds = 0;
  if (!translate(argv[2], argv[3], tree, translate_seconds))
  {
    return 0;
  }
  const auto build_start = std::chrono::steady_clock::now();
  auto evaluators = make_evaluators(tree, threads);
  const double build = peers::seconds_since(build_start);
  const peers::Points p = peers::read_points(argv[4]);
  const std::size_t n = p.count();
  std::vector<float> out(n);
  std::vector<double> times;
  // At least `repeat` passes and at least half a second in all (short passes are noisy).
  const auto all_start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeat || peers::seconds_since(all_start) < 0.5; ++r)
  {
    times.push_back(evaluate_all(evaluators, p.xyz, n, out.data()));
  }
  std::sort(times.begin(), times.end());
  const double t = times[times.size() / 2];
  peers::write_values(argv[5], std::vector<double>(out.begin(), out.end()));
  std::printf("RESULT points=%zu seconds=%.6g mpps=%.4g translate_seconds=%.4g build_seconds=%.4g\n",
    n, t, n / t / 1e6, translate_seconds, build);
  return 0;
}

int mesh(int argc, char** argv)
{
  if (argc < 6)
  {
    throw std::runtime_error("usage: libfive_driver mesh MODEL OBJECT BOX SAMPLES [WORKERS]");
  }
  double lo[3], hi[3];
  peers::parse_box(argv[4], lo, hi);
  const int cells = std::stoi(argv[5]) - 1;
  const auto start = std::chrono::steady_clock::now();
  libfive::Tree tree = libfive::Tree::invalid();
  double translate_seconds = 0;
  if (!translate(argv[2], argv[3], tree, translate_seconds))
  {
    return 0;
  }
  // libfive splits a region in halves on every axis until it is no larger than min_feature:
  // the largest axis over min_feature, rounded up to a power of two, cells per axis.
  const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  int octree_cells = 1;
  while (octree_cells < cells)
  {
    octree_cells *= 2;
  }
  libfive::BRepSettings settings;
  settings.min_feature = extent / octree_cells * 1.0001;
  settings.workers = argc > 6 ? std::stoi(argv[6]) : 2;
  const libfive::Region<3> region({ lo[0], lo[1], lo[2] }, { hi[0], hi[1], hi[2] });
  const auto mesh = libfive::Mesh::render(-tree, region, settings);
  const double t = peers::seconds_since(start);
  if (!mesh)
  {
    throw std::runtime_error("Mesh::render returned nothing");
  }
  std::printf("RESULT cells=%d seconds=%.6g triangles=%zu translate_seconds=%.4g\n", octree_cells, t,
    mesh->branes.size(), translate_seconds);
  return 0;
}

int slice(int argc, char** argv)
{
  if (argc < 4)
  {
    throw std::runtime_error("usage: libfive_driver slice MODEL N [WORKERS]");
  }
  const int n = std::stoi(argv[3]);
  const int workers = argc > 4 ? std::stoi(argv[4]) : 2;
  libfive::Tree tree = libfive::Tree::invalid();
  double translate_seconds = 0;
  if (!translate(argv[2], "", tree, translate_seconds))
  {
    return 0;
  }
  const libfive::Tree inside_negative = -tree;

  // 1. libfive's renderer: a heightmap of a one-voxel-deep volume at z = 0 (pixel centres at
  //    -1 + (i + 0.5) * 2 / n), interval arithmetic on regions and tape pushing.
  std::atomic_bool abort(false);
  const libfive::Voxels voxels({ -1, -1, 0 }, { 1, 1, 0 }, n / 2.0f);
  auto start = std::chrono::steady_clock::now();
  const auto heightmap = libfive::Heightmap::render(inside_negative, voxels, abort, workers);
  const double render_seconds = peers::seconds_since(start);
  std::size_t render_inside = 0;
  for (int r = 0; r < heightmap->depth.rows(); ++r)
  {
    for (int c = 0; c < heightmap->depth.cols(); ++c)
    {
      render_inside += std::isinf(heightmap->depth(r, c)) ? 0 : 1;
    }
  }

  // 2. Brute force: every pixel centre through the array evaluator, 256 at a time.
  std::vector<double> xyz(3 * std::size_t(n) * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      double* p = &xyz[3 * (std::size_t(j) * n + i)];
      p[0] = -1 + (i + 0.5) * 2.0 / n;
      p[1] = -1 + (j + 0.5) * 2.0 / n;
      p[2] = 0;
    }
  }
  auto evaluators = make_evaluators(inside_negative, workers);
  std::vector<float> values(std::size_t(n) * n);
  const double brute_seconds = evaluate_all(evaluators, xyz, values.size(), values.data());
  std::size_t brute_inside = 0;
  for (float v : values)
  {
    brute_inside += v < 0 ? 1 : 0;
  }
  std::printf("RESULT pixels=%d render_seconds=%.6g render_inside=%zu brute_seconds=%.6g "
              "brute_inside=%zu translate_seconds=%.4g\n",
    n * n, render_seconds, render_inside, brute_seconds, brute_inside, translate_seconds);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "eval") return eval(argc, argv);
    if (command == "mesh") return mesh(argc, argv);
    if (command == "slice") return slice(argc, argv);
    std::fprintf(stderr, "usage: libfive_driver eval|mesh|slice ... (see the source)\n");
    return 2;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "libfive_driver: %s\n", e.what());
    return 1;
  }
}
