// FRepKit's side of the peer benchmark, and the harness's shared chores:
//
//   frepkit_driver workloads SHARED_DIR OUTDIR
//       writes the generated W4/W5 models (Benchmarks/benchmark_models.cpp) into OUTDIR and
//       prints the workload table "id<TAB>label<TAB>model<TAB>object<TAB>box" (box x0,..,z1: the
//       box FRepKit's own benchmarks use: the grid of the model's reference values);
//   frepkit_driver points BOX COUNT SEED OUT.bin      the shared random points (points.h)
//   frepkit_driver eval MODEL OBJECT POINTS VALUES [THREADS=2] [REPEAT=3]
//       BatchEvaluator, f64, median of REPEAT passes over all points;
//   frepkit_driver mesh MODEL OBJECT BOX SAMPLES [THREADS=2]
//       frep::mesh::extract_surface (defaults: culling, simplification, caps, normals), timed
//       from reading the file to the finished mesh;
//   frepkit_driver slice MODEL N [THREADS=2]
//       frep::sample_grid (frepkit slice's sampler) at the N x N pixel centres of [-1,1]^2,
//       inside count;
//   frepkit_driver compare REF VALUES [COUNT]
//       max |a - b|, max |a - b| / max(1, |a|), bit-identical and sign-disagreeing points.
//
// Prints one line "RESULT key=value ..." for run_peers.sh.
#include "../benchmark_models.h"
#include "frepkit_model.h"
#include "points.h"

#include "Eval/batch_evaluator.h"
#include "Mesh/surface.h"
#include "Sample/grid_sampler.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{

std::string box_text(const std::array<double, 3>& lo, const std::array<double, 3>& hi)
{
  char text[256];
  std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", lo[0], lo[1], lo[2],
    hi[0], hi[1], hi[2]);
  return text;
}

int workloads(int argc, char** argv)
{
  if (argc < 4)
  {
    throw std::runtime_error("usage: frepkit_driver workloads SHARED_DIR OUTDIR");
  }
  namespace fs = std::filesystem;
  const fs::path shared = argv[2];
  const fs::path out = argv[3];
  fs::create_directories(out);
  const auto models = frep::bench::benchmark_models(shared.string());
  auto box_of = [&](const std::string& name) {
    for (const auto& m : models)
    {
      if (m.name == name)
      {
        return box_text(m.lo, m.hi);
      }
    }
    throw std::runtime_error("no benchmark model " + name + " under " + shared.string());
  };
  struct Row
  {
    const char* id;
    const char* label;
    std::string file;
    const char* bench_name;
  };
  const fs::path m = shared / "hyperfun" / "models";
  std::vector<Row> rows = {
    { "W1", "W1 sphere (tut_start_example1)", (m / "web__f-rep.org/tut_start_example1.hf").string(),
      "tut_start_example1" },
    { "W2", "W2 csg (pmur002 csg.hf)", (m / "pmur002__hyperfun-report/csg.hf").string(), "csg" },
    { "W3", "W3 soft objects (HF_sample)", (m / "web__paulbourke.net/HF_sample.hf").string(),
      "HF_sample" },
    { "W4c", "W4 200-sphere R-union, chain", (out / "w4_union200_chain.hf").string(),
      "union200_chain" },
    { "W4b", "W4 200-sphere R-union, balanced", (out / "w4_union200_balanced.hf").string(),
      "union200_balanced" },
    { "W5", "W5 the same spheres by max", (out / "w5_max200_chain.hf").string(), "max200_chain" },
  };
  const std::pair<const char*, std::string> generated[] = {
    { "w4_union200_chain.hf", frep::bench::sphere_union_model(200, false) },
    { "w4_union200_balanced.hf", frep::bench::sphere_union_model(200, true) },
    { "w5_max200_chain.hf", frep::bench::sphere_union_model(200, false, true) },
  };
  for (const auto& [name, text] : generated)
  {
    std::ofstream file(out / name, std::ios::binary);
    file << text;
    if (!file)
    {
      throw std::runtime_error("cannot write " + (out / name).string());
    }
  }
  for (const Row& row : rows)
  {
    if (!fs::exists(row.file))
    {
      throw std::runtime_error("no model file " + row.file);
    }
    std::printf("%s\t%s\t%s\tmy_model\t%s\n", row.id, row.label, row.file.c_str(),
      box_of(row.bench_name).c_str());
  }
  return 0;
}

int points(int argc, char** argv)
{
  if (argc < 6)
  {
    throw std::runtime_error("usage: frepkit_driver points BOX COUNT SEED OUT");
  }
  double lo[3], hi[3];
  peers::parse_box(argv[2], lo, hi);
  peers::write_points(argv[5], peers::random_points(std::stoul(argv[3]), lo, hi, std::stoul(argv[4])));
  return 0;
}

int eval(int argc, char** argv)
{
  if (argc < 6)
  {
    throw std::runtime_error("usage: frepkit_driver eval MODEL OBJECT POINTS VALUES [THREADS] [REPEAT]");
  }
  const int threads = argc > 6 ? std::stoi(argv[6]) : 2;
  const int repeat = argc > 7 ? std::max(1, std::stoi(argv[7])) : 3;
  const auto build_start = std::chrono::steady_clock::now();
  const peers::LoadedModel model = peers::load_model(argv[2], argv[3]);
  const double build = peers::seconds_since(build_start);
  const peers::Points p = peers::read_points(argv[4]);
  const std::size_t n = p.count();
  std::vector<double> columns[3];
  for (int k = 0; k < 3; ++k)
  {
    columns[k].resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      columns[k][i] = p.xyz[3 * i + k];
    }
  }
  const double* inputs[3] = { columns[0].data(), columns[1].data(), columns[2].data() };
  frep::BatchOptions options;
  options.threads = threads;
  frep::BatchEvaluator evaluator(model.tape, options);
  std::vector<double> values(n);
  std::vector<double> times;
  std::size_t failed = 0;
  // At least `repeat` passes and at least half a second in all (short passes are noisy).
  const auto all_start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeat || peers::seconds_since(all_start) < 0.5; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    failed = evaluator.evaluate(std::span<const double* const>(inputs, model.tape->input_count), n,
      values.data());
    times.push_back(peers::seconds_since(start));
  }
  std::sort(times.begin(), times.end());
  const double t = times[times.size() / 2];
  peers::write_values(argv[5], values);
  std::printf("RESULT points=%zu seconds=%.6g mpps=%.4g instructions=%zu failed=%zu build_seconds=%.4g\n",
    n, t, n / t / 1e6, model.tape->code.size(), failed, build);
  return 0;
}

int mesh(int argc, char** argv)
{
  if (argc < 6)
  {
    throw std::runtime_error("usage: frepkit_driver mesh MODEL OBJECT BOX SAMPLES [THREADS]");
  }
  double lo[3], hi[3];
  peers::parse_box(argv[4], lo, hi);
  const std::int64_t samples = std::stoll(argv[5]);
  const auto start = std::chrono::steady_clock::now();
  const peers::LoadedModel model = peers::load_model(argv[2], argv[3]);
  const frep::GridSpec grid{
    { { lo[0], hi[0], samples }, { lo[1], hi[1], samples }, { lo[2], hi[2], samples } }
  };
  frep::mesh::ExtractOptions options;
  options.threads = argc > 6 ? std::stoi(argv[6]) : 2;
  const frep::mesh::ExtractResult r = frep::mesh::extract_surface(model.tape, grid, options);
  const double t = peers::seconds_since(start);
  if (!r.ok())
  {
    throw std::runtime_error("extract_surface: " + r.error);
  }
  std::printf("RESULT samples=%lld seconds=%.6g triangles=%zu\n", static_cast<long long>(samples), t,
    r.surface.cell_count());
  return 0;
}

int slice(int argc, char** argv)
{
  if (argc < 4)
  {
    throw std::runtime_error("usage: frepkit_driver slice MODEL N [THREADS]");
  }
  const std::int64_t n = std::stoll(argv[3]);
  const auto load_start = std::chrono::steady_clock::now();
  const peers::LoadedModel model = peers::load_model(argv[2], "");
  const double load = peers::seconds_since(load_start);
  if (model.tape->input_count != 2)
  {
    throw std::runtime_error(std::string(argv[2]) + ": not a 2-D model");
  }
  frep::GridSpec grid;
  // Pixel centres -1 + (i + 0.5) * 2 / n, as libfive's renderer samples (libfive_driver slice).
  const double half = 1.0 / static_cast<double>(n);
  grid.axes = { { -1.0 + half, 1.0 - half, n }, { -1.0 + half, 1.0 - half, n } };
  frep::SampleOptions options;
  options.threads = argc > 4 ? std::stoi(argv[4]) : 2;
  std::size_t inside = 0;
  const auto start = std::chrono::steady_clock::now();
  const frep::SampleResult r = frep::sample_grid(model.tape, grid, options,
    [&](const frep::SampleBlock& b) {
      for (std::size_t i = 0; i < b.count; ++i)
      {
        inside += b.values[i] >= 0.0 ? 1 : 0;
      }
    });
  const double t = peers::seconds_since(start);
  if (!r.ok())
  {
    throw std::runtime_error("sample_grid: " + r.error);
  }
  std::printf("RESULT pixels=%lld seconds=%.6g inside=%zu load_seconds=%.4g instructions=%zu\n",
    static_cast<long long>(n * n), t, inside, load, model.tape->code.size());
  return 0;
}

int compare(int argc, char** argv)
{
  if (argc < 4)
  {
    throw std::runtime_error("usage: frepkit_driver compare REF VALUES [COUNT]");
  }
  const std::vector<double> a = peers::read_values(argv[2]);
  const std::vector<double> b = peers::read_values(argv[3]);
  std::size_t n = std::min(a.size(), b.size());
  if (argc > 4)
  {
    n = std::min<std::size_t>(n, std::stoul(argv[4]));
  }
  double max_abs = 0, max_rel = 0;
  std::size_t identical = 0, compared = 0, skipped = 0, sign = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!std::isfinite(a[i]) || !std::isfinite(b[i]))
    {
      skipped += 1; // a run-time error (FRepKit: NaN) or an infinity on either side
      identical += std::memcmp(&a[i], &b[i], sizeof(double)) == 0 ? 1 : 0;
      continue;
    }
    compared += 1;
    identical += std::memcmp(&a[i], &b[i], sizeof(double)) == 0 ? 1 : 0;
    const double d = std::fabs(a[i] - b[i]);
    max_abs = std::max(max_abs, d);
    max_rel = std::max(max_rel, d / std::max(1.0, std::fabs(a[i])));
    sign += (a[i] >= 0) != (b[i] >= 0) ? 1 : 0;
  }
  std::printf("RESULT points=%zu compared=%zu identical=%zu max_abs=%.3g max_rel=%.3g "
              "sign_differs=%zu not_finite=%zu\n",
    n, compared, identical, max_abs, max_rel, sign, skipped);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "workloads") return workloads(argc, argv);
    if (command == "points") return points(argc, argv);
    if (command == "eval") return eval(argc, argv);
    if (command == "mesh") return mesh(argc, argv);
    if (command == "slice") return slice(argc, argv);
    if (command == "compare") return compare(argc, argv);
    std::fprintf(stderr, "usage: frepkit_driver workloads|points|eval|mesh|slice|compare ... (see the source)\n");
    return 2;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "frepkit_driver: %s\n", e.what());
    return 1;
  }
}
