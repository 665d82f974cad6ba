#include "eval_command.h"

#include "Compiler/model.h"
#include "Eval/batch_evaluator.h"
#include "Semantics/interpreter.h"
#include "Durable/atomic_output.h"
#include "Durable/interrupt_guard.h"
#include "model_loading.h"
#include "number_format.h"
#include "points_reader.h"
#include "user_error.h"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <limits>

namespace frepkit
{
namespace
{

/// Points are read, evaluated and written in chunks so that any input size streams.
constexpr std::size_t kChunkPoints = 1 << 16;

std::string format_error(const std::string& file, const frep::RuntimeError& error)
{
  std::string text = "error: " + file;
  if (error.location.valid())
  {
    text += ":" + std::to_string(error.location.line) + ":" + std::to_string(error.location.column);
  }
  text += ": " + error.message;
  if (error.abort)
  {
    text += " (the original interpreter aborts here)";
  }
  return text;
}

/// What is printed for one point, and what --hfp-errors carries to the next failing point.
struct PointOutput
{
  double value = 0;
  std::vector<double> attributes;
};

class EvalRun
{
public:
  EvalRun(const EvalOptions& options, const frep::LoadedProgram& loaded, int object_index)
    : options_(options)
    , loaded_(loaded)
    , object_(loaded.program->objects[static_cast<std::size_t>(object_index)])
    , interpreter_(loaded.program, object_index)
  {
    interpreter_.set_parameters(options.parameters);
    if (!options.sequence && !options.interpreter)
    {
      frep::Model::CompileResult compiled = frep::Model::compile(loaded.program, object_index);
      if (!compiled.model)
      {
        throw UserError(frep::format_diagnostics(compiled.diagnostics));
      }
      frep::BatchOptions batch;
      batch.threads = options.threads;
      batch_ = std::make_unique<frep::BatchEvaluator>(
        compiled.model->tape(options.parameters), batch);
    }
    previous_.attributes.assign(static_cast<std::size_t>(object_.s_dim), 0.0);
  }

  void evaluate_chunk(const std::vector<std::vector<double>>& columns, std::size_t count,
    std::ostream& out)
  {
    if (batch_)
    {
      evaluate_compiled(columns, count, out);
    }
    else
    {
      std::vector<double> x(columns.size());
      for (std::size_t i = 0; i < count; ++i)
      {
        for (std::size_t k = 0; k < columns.size(); ++k)
        {
          x[k] = columns[k][i];
        }
        if (!options_.sequence)
        {
          interpreter_.set_parameters(options_.parameters);
          interpreter_.reset_attributes();
        }
        write_interpreted(interpreter_.evaluate(x), out);
      }
    }
  }

private:
  void evaluate_compiled(
    const std::vector<std::vector<double>>& columns, std::size_t count, std::ostream& out)
  {
    std::vector<const double*> inputs;
    for (const auto& column : columns)
    {
      inputs.push_back(column.data());
    }
    values_.resize(count);
    errors_.resize(count);
    const std::size_t s_dim = static_cast<std::size_t>(object_.s_dim);
    attribute_storage_.resize(s_dim);
    std::vector<double*> attribute_columns;
    if (options_.attributes)
    {
      for (auto& column : attribute_storage_)
      {
        column.resize(count);
        attribute_columns.push_back(column.data());
      }
    }
    batch_->evaluate(inputs, count, values_.data(), errors_.data(), attribute_columns);
    std::vector<double> x(columns.size());
    for (std::size_t i = 0; i < count; ++i)
    {
      if (errors_[i] != 0)
      {
        // The tape knows that the point failed; the reference interpreter says exactly how,
        // with the original's message and position.
        for (std::size_t k = 0; k < columns.size(); ++k)
        {
          x[k] = columns[k][i];
        }
        interpreter_.set_parameters(options_.parameters);
        interpreter_.reset_attributes();
        write_interpreted(interpreter_.evaluate(x), out);
        continue;
      }
      PointOutput point;
      point.value = values_[i];
      if (options_.attributes)
      {
        for (std::size_t j = 0; j < s_dim; ++j)
        {
          point.attributes.push_back(attribute_storage_[j][i]);
        }
      }
      write_value(point, out);
    }
  }

  void write_interpreted(const frep::PointResult& result, std::ostream& out)
  {
    if (result.error)
    {
      if (options_.hfp_errors)
      {
        write_value(previous_, out); // hfp: a failing point keeps the previous point's value
        return;
      }
      out << format_error(loaded_.file, *result.error) << '\n';
      return;
    }
    PointOutput point;
    point.value = result.value;
    const auto s = interpreter_.attributes();
    point.attributes.assign(s.begin(), s.end());
    write_value(point, out);
  }

  void write_value(const PointOutput& point, std::ostream& out)
  {
    out << format_double(point.value);
    if (options_.attributes)
    {
      for (double s : point.attributes)
      {
        out << ' ' << format_double(s);
      }
    }
    out << '\n';
    previous_ = point;
  }

  const EvalOptions& options_;
  const frep::LoadedProgram& loaded_;
  const frep::ast::Object& object_;
  frep::Interpreter interpreter_;
  std::unique_ptr<frep::BatchEvaluator> batch_;
  std::vector<double> values_;
  std::vector<std::uint32_t> errors_;
  std::vector<std::vector<double>> attribute_storage_;
  PointOutput previous_;
};

} // namespace

CLI::App* add_eval_command(CLI::App& app, EvalOptions& options)
{
  CLI::App* eval = app.add_subcommand("eval",
    "Evaluate a HyperFun model at points: one point per input line (coordinates x1..xn "
    "separated by spaces), one output line per point: the value as %.17g, or 'error: "
    "FILE:LINE:COL: MESSAGE' for a point where the model raises a run-time error.");
  eval->add_option("model", options.model, "HyperFun model file (.hf)")->required();
  eval->add_option("-o,--object", options.object,
    "Object to evaluate (case-insensitive); default: my_model, else the first object");
  eval->add_option("-a,--parameters", options.parameters,
       "Values of a[1], a[2], ... separated by commas (missing ones are 0)")
    ->delimiter(',');
  eval->add_option("-p,--points", options.points, "Points file ('-' = standard input)")
    ->capture_default_str();
  eval->add_option("--output", options.output,
    "Write the results to this file (written under a temporary name, renamed when complete; "
    "'-' = standard output)")->capture_default_str();
  eval->add_flag("--attributes", options.attributes, "Also print s[1..m] after each value");
  eval->add_flag("--hfp-errors", options.hfp_errors,
    "Reproduce hfp: a point with a run-time error repeats the previous point's output "
    "(0 at the first point) instead of reporting the error");
  eval->add_flag("--sequence", options.sequence,
    "Reproduce hfp's state: a[] and s[] keep what the model wrote at the previous point "
    "(evaluates with the reference interpreter, in input order)");
  eval->add_flag("--interpreter", options.interpreter,
    "Evaluate with the reference interpreter instead of the compiled tape (for checking)");
  eval->add_option("-j,--threads", options.threads,
    "Worker threads for compiled evaluation (0 = all cores)")->capture_default_str()
    ->check(CLI::Range(0, 1024));
  add_user_input_options(eval, options.user);
  return eval;
}

int run_eval(const EvalOptions& options)
{
  const frep::LoadedProgram loaded = load_program(options.model, options.user);
  require_parsed(loaded);
  const int object_index = choose_object(loaded, options.object);
  const frep::ast::Object& object = loaded.program->objects[static_cast<std::size_t>(object_index)];
  warn_extra_parameters(object, options.parameters.size());

  std::ifstream file;
  std::istream* in = &std::cin;
  if (options.points != "-")
  {
    file.open(options.points, std::ios::binary);
    if (!file)
    {
      throw UserError(options.points + ": cannot open the points file");
    }
    in = &file;
  }
  PointsReader reader(*in, options.points == "-" ? "<stdin>" : options.points, object.x_dim);
  EvalRun run(options, loaded, object_index);
  frep::durable::AtomicOutput output(options.output);
  std::vector<std::vector<double>> columns;
  while (const std::size_t count = reader.read(kChunkPoints, columns))
  {
    // A long points file stops between chunks.
    frep::durable::InterruptGuard::throw_if_interrupted();
    run.evaluate_chunk(columns, count, output.stream());
  }
  output.commit();
  return 0;
}

} // namespace frepkit
