// Fuzz harness: the .vm tape reader (Language/vm_reader.h) on arbitrary text, and tape
// simplification (Eval/tape_simplifier.h) on the min/max-heavy programs it makes. Properties:
// nothing crashes; a refused text has exactly one diagnostic, with a message and a line and
// column inside the text; an accepted program is one object that compiles; its batch values equal
// its point values bit for bit; and on a box around the probe points the tape simplified for that
// box gives the full tape's values and error ids bit for bit at every probe point.
#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Eval/interval_evaluator.h"
#include "Eval/point_evaluator.h"
#include "Eval/tape_simplifier.h"
#include "Language/vm_reader.h"
#include "fuzz_check.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace
{

bool same_bits(double a, double b)
{
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const frep::ParseResult parsed = frep::parse_vm(text, "fuzz.vm");
  if (!parsed.ok())
  {
    FUZZ_CHECK(parsed.diagnostics.size() == 1, "a refused .vm has one diagnostic");
    const frep::Diagnostic& d = parsed.diagnostics.front();
    const int lines = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    FUZZ_CHECK(!d.message.empty(), "the diagnostic has a message");
    FUZZ_CHECK(d.location.line >= 1 && d.location.line <= lines, "its line is inside the text");
    FUZZ_CHECK(d.location.column >= 1, "its column is positive");
    return 0;
  }
  FUZZ_CHECK(parsed.program->objects.size() == 1, "a .vm is one object");
  const frep::Model::CompileResult compiled = frep::Model::compile(parsed.program, 0);
  FUZZ_CHECK(compiled.model != nullptr, "an accepted .vm compiles");
  const std::shared_ptr<const frep::Tape> tape = compiled.model->tape();
  const std::size_t n = tape->input_count;

  // Probe points on a small grid around the origin, and the box that holds them.
  constexpr int per_axis = 5;
  std::size_t count = 1;
  for (std::size_t k = 0; k < n; ++k)
  {
    count *= per_axis;
  }
  std::vector<std::vector<double>> columns(n, std::vector<double>(count));
  for (std::size_t p = 0; p < count; ++p)
  {
    std::size_t q = p;
    for (std::size_t k = 0; k < n; ++k)
    {
      columns[k][p] = -1.0 + 0.5 * static_cast<double>(q % per_axis) + 0.125 * static_cast<double>(k);
      q /= per_axis;
    }
  }
  std::vector<const double*> inputs;
  std::vector<frep::Interval> box;
  for (const auto& c : columns)
  {
    inputs.push_back(c.data());
    const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
    box.push_back({ *lo, *hi });
  }

  frep::PointEvaluator point(tape);
  frep::BatchOptions one;
  one.threads = 1;
  frep::BatchEvaluator batch(tape, one);
  batch.compiled(); // compile now (else only from 1024 samples): the machine code is checked too
  std::vector<double> batch_values(count);
  std::vector<std::uint32_t> batch_errors(count);
  batch.evaluate(inputs, count, batch_values.data(), batch_errors.data());

  frep::IntervalEvaluator interval(tape);
  std::vector<frep::Choice> choices(tape->code.size());
  interval.evaluate(box, choices);
  frep::TapeSimplifier simplifier;
  const std::shared_ptr<const frep::Tape> simplified = simplifier.simplify(*tape, choices);
  std::unique_ptr<frep::PointEvaluator> simple;
  if (simplified)
  {
    simple = std::make_unique<frep::PointEvaluator>(simplified);
  }

  std::vector<double> x(n), out(tape->outputs.size()), simple_out(tape->outputs.size());
  for (std::size_t p = 0; p < count; ++p)
  {
    for (std::size_t k = 0; k < n; ++k)
    {
      x[k] = columns[k][p];
    }
    const int error = point.evaluate(x, out);
    FUZZ_CHECK(static_cast<std::uint32_t>(error) == batch_errors[p], "batch error id == point");
    FUZZ_CHECK(same_bits(batch_values[p], error ? std::nan("") : out[0]), "batch F == point F");
    if (simple)
    {
      const int simple_error = simple->evaluate(x, simple_out);
      FUZZ_CHECK(simple_error == error, "the simplified tape raises the same error");
      for (std::size_t o = 0; o < out.size(); ++o)
      {
        FUZZ_CHECK(same_bits(simple_out[o], out[o]), "the simplified tape's outputs == the full tape's");
      }
    }
  }
  return 0;
}
