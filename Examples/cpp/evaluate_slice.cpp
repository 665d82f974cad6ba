// Using the engine from C++: parse a 5-D HyperFun model, compile it, cut the 3-D slice
// x4 = 0.5, x5 = 0.25 (a smaller tape), and evaluate it at many points on all cores, with
// interval culling of a box and the gradient (surface normal) at one point.
//
//   build/bin/frep_example_evaluate_slice Examples/homotopy5d.hf
#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Compiler/load_model.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " MODEL.hf\n";
    return 1;
  }
  // 1. Load: read, parse, choose the object (my_model, else the first) and compile it
  //    (immutable, shareable between threads); every problem comes back as file:line:col.
  const frep::LoadedModel compiled = frep::load_model(frep::ModelSource::file(argv[1]));
  if (!compiled.ok())
  {
    std::cerr << compiled.message();
    return 1;
  }
  const frep::Model& model = *compiled.model;

  // 2. Specialise: fix x4 and x5; x1..x3 stay free and become the tape's inputs 0..2.
  frep::Specialisation slice;
  slice.fixed = { std::nullopt, std::nullopt, std::nullopt, 0.5, 0.25 };
  const std::shared_ptr<const frep::Tape> tape = model.specialise(slice);
  std::printf("%s: %d-D, slice tape %zu instructions (all free: %zu)\n", model.name().c_str(),
    model.x_dim(), tape->code.size(), model.tape()->code.size());

  // 3. Batch evaluation on a 64^3 grid, structure of arrays, all cores.
  const int n = 64;
  std::vector<double> xs, ys, zs;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        xs.push_back(-5 + 10.0 * i / (n - 1));
        ys.push_back(-5 + 10.0 * j / (n - 1));
        zs.push_back(-5 + 10.0 * k / (n - 1));
      }
  const double* inputs[] = { xs.data(), ys.data(), zs.data() };
  std::vector<double> values(xs.size());
  frep::BatchEvaluator batch(tape);
  const std::size_t failed = batch.evaluate(inputs, xs.size(), values.data());
  std::size_t inside = 0;
  for (double v : values)
  {
    inside += v >= 0 ? 1 : 0;
  }
  std::printf("grid %d^3: %zu points inside, %zu run-time errors, %d threads\n", n, inside,
    failed, batch.threads());

  // 4. Interval evaluation: is a box certainly outside (F < 0 everywhere)?
  frep::IntervalEvaluator interval(tape);
  const frep::Interval box[] = { { 4, 5 }, { 4, 5 }, { 4, 5 } };
  const frep::IntervalResult r = interval.evaluate(box);
  std::printf("box [4,5]^3: F in [%g, %g] -> %s\n", r.value.lo, r.value.hi,
    r.value.hi < 0 ? "certainly outside" : (r.value.lo >= 0 ? "certainly inside" : "unknown"));

  // 5. Gradient: the outward normal is -grad F (F grows inwards).
  frep::GradientEvaluator gradient(tape);
  const double p[] = { 1.0, 0.5, 0.25 };
  double g[3];
  const double f = gradient.evaluate(p, g);
  std::printf("F(1, 0.5, 0.25) = %.6g, grad = (%.6g, %.6g, %.6g)\n", f, g[0], g[1], g[2]);
  return 0;
}
