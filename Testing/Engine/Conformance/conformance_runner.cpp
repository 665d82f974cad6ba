#include "conformance_runner.h"

#include "Compiler/detail/library_call.h"
#include "Compiler/model.h"
#include "Eval/point_evaluator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <sstream>

namespace frep::conformance
{
namespace
{

class InterpreterSession final : public EvaluationSession
{
public:
  InterpreterSession(std::shared_ptr<const ast::Program> program, int object_index)
    : interpreter_(std::move(program), object_index)
  {
  }
  void set_parameters(std::span<const double> a) override { interpreter_.set_parameters(a); }
  void reset_attributes() override { interpreter_.reset_attributes(); }
  Outcome evaluate(std::span<const double> x) override
  {
    PointResult r = interpreter_.evaluate(x);
    Outcome o;
    o.value = r.value;
    o.error = std::move(r.error);
    const auto s = interpreter_.attributes();
    const auto a = interpreter_.parameters();
    o.s.assign(s.begin(), s.end());
    o.a.assign(a.begin(), a.end());
    return o;
  }

private:
  Interpreter interpreter_;
};

class CompiledSession final : public EvaluationSession
{
public:
  explicit CompiledSession(std::shared_ptr<const Model> model)
    : model_(std::move(model))
  {
    set_parameters({});
  }
  void set_parameters(std::span<const double> a) override
  {
    parameters_.assign(a.begin(), a.end());
    evaluator_.emplace(model_->tape(parameters_));
  }
  void reset_attributes() override {}
  Outcome evaluate(std::span<const double> x) override
  {
    const Tape& tape = evaluator_->tape();
    std::vector<double> outputs(tape.outputs.size());
    const int error = evaluator_->evaluate(x, outputs);
    Outcome o;
    o.a = parameters_;
    o.a.resize(static_cast<std::size_t>(model_->a_dim()), 0.0);
    if (error != 0)
    {
      const TapeError& e = tape.errors.at(static_cast<std::size_t>(error - 1));
      const auto aborts = compiler::library_abort_messages();
      const bool abort = std::find(aborts.begin(), aborts.end(), e.message) != aborts.end();
      o.error = RuntimeError{ e.message, e.location, abort };
      return o;
    }
    o.value = outputs.empty() ? 0.0 : outputs[0];
    o.s.assign(outputs.begin() + (outputs.empty() ? 0 : 1), outputs.end());
    o.s.resize(static_cast<std::size_t>(model_->s_dim()), 0.0);
    return o;
  }

private:
  std::shared_ptr<const Model> model_;
  std::vector<double> parameters_;
  std::optional<PointEvaluator> evaluator_;
};

std::string describe(const RuntimeError& e)
{
  std::ostringstream out;
  out << (e.abort ? "abort " : "error ") << e.location.line << " " << e.location.column << " "
      << e.message;
  return out.str();
}

std::string describe_numbers(const std::vector<double>& values)
{
  std::string out;
  for (double v : values)
  {
    out += ' ';
    out += format_double(v);
  }
  return out;
}

enum class Grade
{
  Exact,
  Close,
  Wrong
};

Grade worse(Grade a, Grade b)
{
  return static_cast<int>(a) > static_cast<int>(b) ? a : b;
}

Grade grade(double expected, double actual)
{
  if (same_double(expected, actual))
  {
    return Grade::Exact;
  }
  return close_double(expected, actual) ? Grade::Close : Grade::Wrong;
}

Grade grade(const std::vector<double>& expected, const std::vector<double>& actual)
{
  if (expected.size() != actual.size())
  {
    return Grade::Wrong;
  }
  Grade g = Grade::Exact;
  for (std::size_t i = 0; i < expected.size(); ++i)
  {
    g = worse(g, grade(expected[i], actual[i]));
  }
  return g;
}

} // namespace

Tally& Tally::operator+=(const Tally& o)
{
  cases += o.cases;
  points += o.points;
  exact += o.exact;
  close += o.close;
  wrong += o.wrong;
  errors += o.errors;
  errors_matched += o.errors_matched;
  unsupported += o.unsupported;
  parse_cases += o.parse_cases;
  parse_outcome_ok += o.parse_outcome_ok;
  parse_column_ok += o.parse_column_ok;
  parse_message_ok += o.parse_message_ok;
  return *this;
}

std::unique_ptr<EvaluationSession> InterpreterEvaluator::start(
  std::shared_ptr<const ast::Program> program,
  int object_index,
  std::string&) const
{
  return std::make_unique<InterpreterSession>(std::move(program), object_index);
}

std::unique_ptr<EvaluationSession> CompiledEvaluator::start(
  std::shared_ptr<const ast::Program> program,
  int object_index,
  std::string& why_not) const
{
  Model::CompileResult compiled = Model::compile(std::move(program), object_index);
  if (!compiled.model)
  {
    why_not =
      compiled.diagnostics.empty() ? "compilation failed" : compiled.diagnostics.front().message;
    return nullptr;
  }
  return std::make_unique<CompiledSession>(std::move(compiled.model));
}

bool same_double(double expected, double actual)
{
  if (std::isnan(expected) || std::isnan(actual))
  {
    return std::isnan(expected) && std::isnan(actual);
  }
  // Bit comparison: keeps the sign of zero.
  return std::memcmp(&expected, &actual, sizeof(double)) == 0;
}

bool close_double(double expected, double actual)
{
  if (same_double(expected, actual))
  {
    return true;
  }
  if (!std::isfinite(expected) || !std::isfinite(actual))
  {
    return false;
  }
  return std::fabs(expected - actual) <= 1e-12 * std::max(1.0, std::fabs(expected));
}

std::string format_double(double v)
{
  if (std::isnan(v))
  {
    return "nan";
  }
  if (std::isinf(v))
  {
    return v > 0 ? "inf" : "-inf";
  }
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

ParseResult parse_case(const ConformanceCase& c)
{
  ParseOptions options;
  options.accept_carriage_return = false;
  return parse_program(c.source, c.program_path.filename().string(), options);
}

CaseRun check_parse(const ConformanceCase& c, const ParseResult& parsed)
{
  CaseRun run;
  run.tally.parse_cases = 1;
  auto mismatch = [&](const std::string& what) { run.mismatches.push_back({ c.id(), -1, what }); };
  const ParseExpectation& want = c.parse;
  switch (want.outcome)
  {
    case ParseOutcome::Ok:
    {
      if (!parsed.ok())
      {
        mismatch("expected parse ok, got: " + format_diagnostics(parsed.diagnostics));
        return run;
      }
      const int index = ast::select_object(*parsed.program, c.object, ast::NameMatch::Exact);
      if (index < 0)
      {
        mismatch("expected parse ok " + want.selected + ", got no object");
        return run;
      }
      const ast::Object& o = parsed.program->objects[index];
      if ((!want.selected.empty() && o.name != want.selected) ||
          (want.x_dim >= 0 && o.x_dim != want.x_dim) ||
          (want.a_dim >= 0 && o.a_dim != want.a_dim) || (want.s_dim >= 0 && o.s_dim != want.s_dim))
      {
        mismatch("expected object " + want.selected + " " + std::to_string(want.x_dim) + " " +
                 std::to_string(want.a_dim) + " " + std::to_string(want.s_dim) + ", got " + o.name +
                 " " + std::to_string(o.x_dim) + " " + std::to_string(o.a_dim) + " " +
                 std::to_string(o.s_dim));
        return run;
      }
      run.tally.parse_outcome_ok = run.tally.parse_column_ok = run.tally.parse_message_ok = 1;
      return run;
    }
    case ParseOutcome::None:
      if (!parsed.ok() || !parsed.program->objects.empty())
      {
        mismatch(parsed.ok()
                   ? "expected parse none, got objects"
                   : "expected parse none, got: " + format_diagnostics(parsed.diagnostics));
        return run;
      }
      run.tally.parse_outcome_ok = run.tally.parse_column_ok = run.tally.parse_message_ok = 1;
      return run;
    case ParseOutcome::Error:
    {
      const std::string expected = "parse error " + std::to_string(want.line) + " " +
                                   std::to_string(want.column) + " " + want.message;
      if (parsed.ok() || parsed.diagnostics.empty())
      {
        mismatch("expected " + expected + ", got parse ok");
        return run;
      }
      const Diagnostic& d = parsed.diagnostics.front();
      const std::string got =
        std::to_string(d.location.line) + " " + std::to_string(d.location.column) + " " + d.message;
      if (d.location.line != want.line)
      {
        mismatch("expected " + expected + ", got " + got);
        return run;
      }
      run.tally.parse_outcome_ok = 1;
      run.tally.parse_column_ok = d.location.column == want.column ? 1 : 0;
      // Our messages may add what was found after the original's text: "TEXT (found ...)".
      const bool same_message =
        d.message == want.message || d.message.rfind(want.message + " (", 0) == 0;
      run.tally.parse_message_ok = same_message ? 1 : 0;
      if (!run.tally.parse_column_ok || !run.tally.parse_message_ok)
      {
        mismatch("expected " + expected + ", got " + got);
      }
      return run;
    }
  }
  return run;
}

CaseRun run_points(const ConformanceCase& c,
  const ParseResult& parsed,
  const CaseEvaluator& evaluator)
{
  CaseRun run;
  run.tally.cases = 1;
  run.tally.points = static_cast<int>(c.points.size());
  for (const CasePoint& p : c.points)
  {
    if (p.expected.kind == ResultKind::Value)
    {
      continue;
    }
    ++run.tally.errors;
  }
  if (c.points.empty())
  {
    return run;
  }
  auto all_wrong = [&](const std::string& why)
  {
    run.tally.wrong += run.tally.points - run.tally.errors;
    run.mismatches.push_back({ c.id(), -1, why });
    return run;
  };
  if (!parsed.ok())
  {
    return all_wrong("program did not parse: " + format_diagnostics(parsed.diagnostics));
  }
  const int index = ast::select_object(*parsed.program, c.object, ast::NameMatch::Exact);
  if (index < 0)
  {
    return all_wrong("no object to evaluate");
  }
  std::unique_ptr<EvaluationSession> session;
  std::string why_not;
  try
  {
    session = evaluator.start(parsed.program, index, why_not);
  }
  catch (const std::exception& e)
  {
    return all_wrong(std::string("evaluator refused the program: ") + e.what());
  }
  if (!session)
  {
    // Counted apart (the summary's "unsup" column) and reported: a model that no longer
    // compiles must fail the suite, not shrink it.
    run.tally.unsupported = run.tally.points;
    run.tally.errors = 0;
    run.mismatches.push_back({ c.id(),
      kDeclinedCase,
      "the " + evaluator.name() + " evaluator declined the case: " +
        (why_not.empty() ? std::string("no reason given") : why_not) });
    return run;
  }
  const bool exact_required = evaluator.requires_exact(c.category);
  if (c.mode == Mode::Sequence)
  {
    session->set_parameters(c.points.front().a);
    session->reset_attributes();
  }
  for (std::size_t k = 0; k < c.points.size(); ++k)
  {
    const CasePoint& p = c.points[k];
    if (c.mode == Mode::Fresh)
    {
      session->set_parameters(p.a);
      session->reset_attributes();
    }
    const Outcome got = session->evaluate(p.x);
    const ExpectedResult& want = p.expected;
    auto mismatch = [&](const std::string& what)
    {
      run.mismatches.push_back(
        { c.id(), static_cast<int>(k), "line " + std::to_string(p.file_line) + ": " + what });
    };
    switch (want.kind)
    {
      case ResultKind::Value:
      {
        if (got.error)
        {
          ++run.tally.wrong;
          mismatch("expected value " + format_double(want.value) + ", got " + describe(*got.error));
          break;
        }
        Grade g = grade(want.value, got.value);
        if (!want.s.empty())
        {
          g = worse(g, grade(want.s, got.s));
        }
        if (want.a)
        {
          g = worse(g, grade(*want.a, got.a));
        }
        (g == Grade::Exact    ? run.tally.exact
          : g == Grade::Close ? run.tally.close
                              : run.tally.wrong)++;
        if (g == Grade::Wrong || (g == Grade::Close && exact_required))
        {
          std::string what = "expected value " + format_double(want.value) + " s" +
                             describe_numbers(want.s) +
                             (want.a ? " a" + describe_numbers(*want.a) : "") + ", got value " +
                             format_double(got.value) + " s" + describe_numbers(got.s) +
                             (want.a ? " a" + describe_numbers(got.a) : "");
          mismatch(what);
        }
        break;
      }
      case ResultKind::Error:
        if (got.error && !got.error->abort && got.error->message == want.message &&
            got.error->location.line == want.line && got.error->location.column == want.column)
        {
          ++run.tally.errors_matched;
        }
        else
        {
          mismatch("expected error " + std::to_string(want.line) + " " +
                   std::to_string(want.column) + " " + want.message + ", got " +
                   (got.error ? describe(*got.error) : "value " + format_double(got.value)));
        }
        break;
      case ResultKind::Abort:
        if (got.error && got.error->abort && got.error->message == want.message)
        {
          ++run.tally.errors_matched;
        }
        else
        {
          mismatch("expected abort " + want.message + ", got " +
                   (got.error ? describe(*got.error) : "value " + format_double(got.value)));
        }
        break;
      case ResultKind::AnyError:
        if (got.error)
        {
          ++run.tally.errors_matched;
        }
        else
        {
          mismatch("expected a run-time error, got value " + format_double(got.value));
        }
        break;
    }
  }
  return run;
}

std::string format_eval_summary(const std::string& title, const std::map<std::string, Tally>& rows)
{
  std::ostringstream out;
  char line[256];
  out << title << "\n";
  std::snprintf(line,
    sizeof line,
    "%-14s %6s %7s %7s %7s %7s %11s %6s\n",
    "category",
    "cases",
    "points",
    "exact",
    "1e-12",
    "wrong",
    "errors ok",
    "unsup");
  out << line;
  Tally total;
  auto row = [&](const std::string& name, const Tally& t)
  {
    char errors[32];
    std::snprintf(errors, sizeof errors, "%d/%d", t.errors_matched, t.errors);
    std::snprintf(line,
      sizeof line,
      "%-14s %6d %7d %7d %7d %7d %11s %6d\n",
      name.c_str(),
      t.cases,
      t.points,
      t.exact,
      t.close,
      t.wrong,
      errors,
      t.unsupported);
    out << line;
  };
  for (const auto& [name, t] : rows)
  {
    row(name, t);
    total += t;
  }
  row("TOTAL", total);
  return out.str();
}

std::string format_parse_summary(const std::string& title, const std::map<std::string, Tally>& rows)
{
  std::ostringstream out;
  char line[256];
  out << title << "\n";
  std::snprintf(line,
    sizeof line,
    "%-14s %6s %14s %7s %8s\n",
    "category",
    "cases",
    "outcome+line",
    "column",
    "message");
  out << line;
  Tally total;
  auto row = [&](const std::string& name, const Tally& t)
  {
    std::snprintf(line,
      sizeof line,
      "%-14s %6d %14d %7d %8d\n",
      name.c_str(),
      t.parse_cases,
      t.parse_outcome_ok,
      t.parse_column_ok,
      t.parse_message_ok);
    out << line;
  };
  for (const auto& [name, t] : rows)
  {
    row(name, t);
    total += t;
  }
  row("TOTAL", total);
  return out.str();
}

} // namespace frep::conformance
