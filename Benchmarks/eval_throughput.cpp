// Evaluation throughput (points per second) of every benchmark model, 10^6 points drawn
// uniformly from the model's box: the batch evaluator on 1 and 2 threads, the point evaluator
// (the naive reference), the reference interpreter (on the first 20000 points: it is the
// original's speed class), and the cost of specialisation (AST -> tape).
//
//   build/bin/frep_eval_throughput [--benchmark_filter=...]
#include "benchmark_models.h"

#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Semantics/interpreter.h"
#include "Eval/point_evaluator.h"
#include "Language/parser.h"

#include <benchmark/benchmark.h>

#include <iostream>
#include <cstdlib>
#include <random>

namespace
{

constexpr std::size_t kPoints = 1'000'000;
constexpr std::size_t kInterpreterPoints = 20'000;

struct Prepared
{
  frep::bench::BenchModel model;
  std::shared_ptr<const frep::ast::Program> program;
  int object = 0;
  std::shared_ptr<const frep::Model> compiled;
  std::shared_ptr<const frep::Tape> tape;
  std::vector<std::vector<double>> points; // SoA: points[k][i]
};

std::vector<Prepared>& prepared_models()
{
  static std::vector<Prepared> models;
  return models;
}

void prepare(const std::string& shared_dir)
{
  for (frep::bench::BenchModel& model : frep::bench::benchmark_models(shared_dir))
  {
    Prepared p;
    frep::ParseResult parsed = frep::parse_program(model.text, model.name);
    if (!parsed.ok())
    {
      std::cerr << frep::format_diagnostics(parsed.diagnostics);
      continue;
    }
    p.program = parsed.program;
    p.object = frep::ast::select_object(*p.program, model.object);
    frep::Model::CompileResult compiled = frep::Model::compile(p.program, p.object);
    if (!compiled.model)
    {
      std::cerr << model.name << ": " << frep::format_diagnostics(compiled.diagnostics);
      continue;
    }
    p.compiled = compiled.model;
    p.tape = p.compiled->tape();
    std::mt19937_64 random(42);
    p.points.resize(3);
    for (int k = 0; k < 3; ++k)
    {
      std::uniform_real_distribution<double> u(model.lo[k], model.hi[k]);
      p.points[k].resize(kPoints);
      for (double& v : p.points[k])
      {
        v = u(random);
      }
    }
    p.model = std::move(model);
    prepared_models().push_back(std::move(p));
  }
}

void batch(benchmark::State& state, const Prepared* p, int threads)
{
  frep::BatchOptions options;
  options.threads = threads;
  // FREP_BLOCK_SIZE=N measures another block size (lanes per block; the default is 256).
  if (const char* block = std::getenv("FREP_BLOCK_SIZE"))
  {
    options.block_size = std::max(1, std::atoi(block));
  }
  // FREP_JIT=0 measures the interpreter where the tape would be compiled to machine code.
  if (const char* jit = std::getenv("FREP_JIT"))
  {
    options.jit = std::atoi(jit) != 0;
  }
  frep::BatchEvaluator evaluator(p->tape, options);
  state.counters["compiled"] = evaluator.compiled() ? 1 : 0;
  std::vector<const double*> inputs;
  for (const auto& column : p->points)
  {
    inputs.push_back(column.data());
  }
  std::vector<double> values(kPoints);
  for (auto _ : state)
  {
    evaluator.evaluate(inputs, kPoints, values.data());
    benchmark::DoNotOptimize(values.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kPoints));
}

void point(benchmark::State& state, const Prepared* p)
{
  frep::PointEvaluator evaluator(p->tape);
  double x[3];
  for (auto _ : state)
  {
    double sum = 0;
    for (std::size_t i = 0; i < kPoints; ++i)
    {
      x[0] = p->points[0][i];
      x[1] = p->points[1][i];
      x[2] = p->points[2][i];
      sum += evaluator.value(x);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kPoints));
}

void interpreter(benchmark::State& state, const Prepared* p)
{
  frep::Interpreter reference(p->program, p->object);
  double x[3];
  for (auto _ : state)
  {
    double sum = 0;
    for (std::size_t i = 0; i < kInterpreterPoints; ++i)
    {
      x[0] = p->points[0][i];
      x[1] = p->points[1][i];
      x[2] = p->points[2][i];
      sum += reference.evaluate(x).value;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kInterpreterPoints));
}

void specialise(benchmark::State& state, const Prepared* p)
{
  const frep::Specialisation all_free; // every coordinate free, a[] = 0: the full lowering
  for (auto _ : state)
  {
    auto tape = p->compiled->specialise(all_free);
    benchmark::DoNotOptimize(tape.get());
  }
  state.counters["instructions"] = static_cast<double>(p->tape->code.size());
}

void parse(benchmark::State& state, const Prepared* p)
{
  for (auto _ : state)
  {
    frep::ParseResult parsed = frep::parse_program(p->model.text, p->model.name);
    benchmark::DoNotOptimize(parsed.program.get());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * p->model.text.size()));
}

} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  prepare(FREPKIT_SHARED_DIR);
  for (const Prepared& p : prepared_models())
  {
    const std::string& name = p.model.name;
    for (int threads : { 1, 2 })
    {
      benchmark::RegisterBenchmark(
        ("Batch/" + name + "/threads:" + std::to_string(threads)).c_str(), batch, &p, threads)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(1.0);
    }
    benchmark::RegisterBenchmark(("Point/" + name).c_str(), point, &p)
      ->Unit(benchmark::kMillisecond)
      ->MinTime(1.0);
    benchmark::RegisterBenchmark(("Interpreter/" + name).c_str(), interpreter, &p)
      ->Unit(benchmark::kMillisecond)
      ->MinTime(1.0);
    benchmark::RegisterBenchmark(("Specialise/" + name).c_str(), specialise, &p)
      ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Parse/" + name).c_str(), parse, &p)
      ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
