// Fuzz harness (b): compile a HyperFun text and evaluate its tapes at deterministic points
// (fuzz_points.h), checking the evaluators against each other. Properties, each a documented
// promise of FRep/Eval or FRep/Compiler:
// - BatchEvaluator == PointEvaluator bit for bit: F, s[] and the error id of every point
//   (NaN compared as NaN: both evaluators return NaN for an error point);
// - the tape == a fresh Interpreter at the same point (F bit for bit, an error on both or on
//   neither): tapes evaluate every point from a fresh state, as a new interpreter does;
// - IntervalEvaluator encloses: for a box containing a point, the point's F lies in the
//   enclosure; a point that raised an error has may_fail set; a NaN F (no error, e.g. an
//   unguarded sqrt of a negative) has the whole line, which stands for "possibly NaN";
// - GradientEvaluator returns F bit for bit as PointEvaluator, and an all-NaN gradient exactly
//   where the point raised an error. (A finite F does not imply a finite gradient: d/dx sqrt(x)
//   is +inf at 0, so that is not checked.)
// Texts with a loop that runs more than kLoopBudget iterations at a point are skipped: a tape
// that falls back to the interpreter would run up to its 1e8-iteration cap per point.
#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Eval/gradient_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Language/parser.h"
#include "Semantics/interpreter.h"
#include "fuzz_check.h"
#include "fuzz_points.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace
{

constexpr std::size_t kPoints = 16;
constexpr std::size_t kBoxes = 6;
constexpr int kObjects = 3;
constexpr std::int64_t kLoopBudget = 20'000;

bool same(double a, double b)
{
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<std::uint64_t>(a) ==
    std::bit_cast<std::uint64_t>(b);
}

using Point = std::vector<double>;

/// What a failed oracle was looking at (printed before it aborts).
void print_point(const char* what, const Point& x)
{
  std::fprintf(stderr, "%s x =", what);
  for (const double v : x)
  {
    std::fprintf(stderr, " %.17g", v);
  }
  std::fprintf(stderr, "\n");
}

/// The interpreter at `x` (all coordinates of the object), fresh state. False when a loop ran
/// past the budget (the text is then skipped).
bool interpret(const std::shared_ptr<const frep::ast::Program>& program, int object,
  const Point& x, frep::PointResult& result)
{
  frep::InterpreterOptions options;
  options.max_loop_iterations = kLoopBudget;
  frep::Interpreter interpreter(program, object, options);
  result = interpreter.evaluate(x);
  return !(result.error && result.error->message == frep::kLoopLimitMessage);
}

void check_object(const std::shared_ptr<const frep::ast::Program>& program, int object,
  frep_fuzz::PointSource& source)
{
  frep::CompileOptions compile_options;
  compile_options.max_unrolled_iterations = 20'000;
  compile_options.max_nodes = 200'000;
  const frep::Model::CompileResult compiled =
    frep::Model::compile(program, object, compile_options);
  if (!compiled.model)
  {
    FUZZ_CHECK(!compiled.diagnostics.empty(), "a failed compilation says why");
    return;
  }
  const frep::Model& model = *compiled.model;
  const std::size_t dimension = static_cast<std::size_t>(model.x_dim());
  std::vector<Point> points(kPoints, Point(dimension));
  for (Point& p : points)
  {
    std::generate(p.begin(), p.end(), [&] { return source.coordinate(); });
  }
  std::vector<frep::PointResult> reference(kPoints);
  for (std::size_t i = 0; i < kPoints; ++i)
  {
    if (!interpret(program, object, points[i], reference[i]))
    {
      return;
    }
  }

  const auto tape = model.tape();
  FUZZ_CHECK(tape->input_count == dimension, "every coordinate is a tape input");
  const std::size_t outputs = tape->outputs.size();
  frep::PointEvaluator point(tape);
  std::vector<std::vector<double>> point_outputs(kPoints, std::vector<double>(outputs));
  std::vector<int> point_errors(kPoints);
  for (std::size_t i = 0; i < kPoints; ++i)
  {
    point_errors[i] = point.evaluate(points[i], point_outputs[i]);
    const bool interpreter_failed = reference[i].error.has_value();
    if ((point_errors[i] != 0) != interpreter_failed ||
      (!interpreter_failed && outputs > 0 && !same(point_outputs[i][0], reference[i].value)))
    {
      print_point("at", points[i]);
      std::fprintf(stderr, "tape: F %.17g error %d; interpreter: F %.17g error %s\n",
        outputs > 0 ? point_outputs[i][0] : 0.0, point_errors[i], reference[i].value,
        interpreter_failed ? reference[i].error->message.c_str() : "none");
    }
    FUZZ_CHECK((point_errors[i] != 0) == interpreter_failed,
      "tape and interpreter agree on whether the point fails");
    if (!interpreter_failed && outputs > 0)
    {
      FUZZ_CHECK(same(point_outputs[i][0], reference[i].value), "tape F == interpreter F");
    }
  }

  // Batch, structure of arrays, on the caller's thread.
  std::vector<std::vector<double>> columns(dimension, std::vector<double>(kPoints));
  std::vector<const double*> inputs(dimension);
  for (std::size_t k = 0; k < dimension; ++k)
  {
    for (std::size_t i = 0; i < kPoints; ++i)
    {
      columns[k][i] = points[i][k];
    }
    inputs[k] = columns[k].data();
  }
  std::vector<double> values(kPoints);
  std::vector<std::uint32_t> errors(kPoints);
  std::vector<std::vector<double>> attributes(outputs > 0 ? outputs - 1 : 0,
    std::vector<double>(kPoints));
  std::vector<double*> attribute_columns;
  for (auto& a : attributes)
  {
    attribute_columns.push_back(a.data());
  }
  frep::BatchOptions batch_options;
  batch_options.threads = 1;
  batch_options.jit = false; // the interpreter; the compiled kernel is compared with it below
  frep::BatchEvaluator batch(tape, batch_options);
  const std::size_t failed =
    batch.evaluate(inputs, kPoints, values.data(), errors.data(), attribute_columns);
  FUZZ_CHECK(failed == static_cast<std::size_t>(std::count_if(point_errors.begin(),
                         point_errors.end(), [](int e) { return e != 0; })),
    "batch and point count the same failing points");
  for (std::size_t i = 0; i < kPoints; ++i)
  {
    FUZZ_CHECK(static_cast<int>(errors[i]) == point_errors[i], "batch error id == point error id");
    if (outputs > 0)
    {
      FUZZ_CHECK(same(values[i], point_outputs[i][0]), "batch F == point F bit for bit");
    }
    for (std::size_t j = 0; j + 1 < outputs; ++j)
    {
      FUZZ_CHECK(same(attributes[j][i], point_outputs[i][j + 1]), "batch s[] == point s[]");
    }
  }
  // The compiled kernel (made now; else only from 1024 samples) == the interpreter above.
  batch_options.jit = true;
  frep::BatchEvaluator machine_code(tape, batch_options);
  if (machine_code.compiled())
  {
    std::vector<double> compiled_values(kPoints);
    std::vector<std::uint32_t> compiled_errors(kPoints);
    machine_code.evaluate(inputs, kPoints, compiled_values.data(), compiled_errors.data());
    for (std::size_t i = 0; i < kPoints; ++i)
    {
      FUZZ_CHECK(compiled_errors[i] == errors[i], "compiled error id == interpreted error id");
      FUZZ_CHECK(same(compiled_values[i], values[i]), "compiled F == interpreted F bit for bit");
    }
  }
  if (outputs == 0)
  {
    return;
  }

  frep::GradientEvaluator gradient(tape);
  std::vector<double> g(dimension);
  for (std::size_t i = 0; i < kPoints; ++i)
  {
    const double f = gradient.evaluate(points[i], g);
    FUZZ_CHECK(same(f, point_outputs[i][0]), "gradient evaluator's F == point F bit for bit");
    if (point_errors[i] != 0)
    {
      FUZZ_CHECK(std::all_of(g.begin(), g.end(), [](double d) { return std::isnan(d); }),
        "the gradient at an error point is NaN");
    }
  }

  // Boxes spanned by two of the points; checked at both corners and at a mixed point inside.
  frep::IntervalEvaluator interval(tape);
  std::vector<frep::Interval> box(dimension);
  for (std::size_t b = 0; b < kBoxes; ++b)
  {
    const Point& p = points[source.next() % kPoints];
    const Point& q = points[source.next() % kPoints];
    Point mixed(dimension);
    for (std::size_t k = 0; k < dimension; ++k)
    {
      box[k] = { std::min(p[k], q[k]), std::max(p[k], q[k]) };
      mixed[k] = (source.next() & 1) ? p[k] : q[k];
    }
    const frep::IntervalResult enclosure = interval.evaluate(box);
    std::vector<double> out(outputs);
    const Point* const checked[] = { &p, &q, &mixed };
    for (const Point* x : checked)
    {
      const int error = point.evaluate(*x, out);
      if (error != 0)
      {
        FUZZ_CHECK(enclosure.may_fail, "a box with an error point may fail");
      }
      else if (std::isnan(out[0]))
      {
        FUZZ_CHECK(enclosure.value.lo == -INFINITY && enclosure.value.hi == INFINITY,
          "a box with a NaN point is enclosed by the whole line");
      }
      else
      {
        FUZZ_CHECK(enclosure.value.contains(out[0]), "the box's enclosure contains F");
      }
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const frep::ParseResult parsed = frep::parse_program(text, "fuzz.hf");
  if (!parsed.ok())
  {
    return 0;
  }
  frep_fuzz::PointSource source(text);
  const int objects = std::min<int>(kObjects, static_cast<int>(parsed.program->objects.size()));
  for (int object = 0; object < objects; ++object)
  {
    check_object(parsed.program, object, source);
  }
  return 0;
}
