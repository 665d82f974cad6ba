// Running conformance cases through an evaluator and comparing with the original's results.
// An evaluator is plugged in through CaseEvaluator (the reference interpreter is one; a compiled
// tape evaluator can be another): the runner owns parsing, object selection, fresh/sequence
// state handling and the comparison rules, so every evaluator is judged the same way.
#pragma once

#include "conformance_case.h"

#include "Language/ast.h"
#include "Language/parser.h"
#include "Semantics/interpreter.h"

#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace frep::conformance
{

/// What one evaluation produced.
struct Outcome
{
  double value = 0;
  std::vector<double> s; ///< final s[] (on success)
  std::vector<double> a; ///< a[] after the evaluation
  std::optional<RuntimeError> error;
};

/// One evaluator bound to one object, with the persistent a[]/s[] state of hfp.
class EvaluationSession
{
public:
  virtual ~EvaluationSession() = default;
  virtual void set_parameters(std::span<const double> a) = 0;
  virtual void reset_attributes() = 0;
  virtual Outcome evaluate(std::span<const double> x) = 0;
};

/// An evaluation strategy under test.
class CaseEvaluator
{
public:
  virtual ~CaseEvaluator() = default;
  virtual std::string name() const = 0;
  /// Whether values must be bit-exact in `category` (else within 1e-12 relative).
  virtual bool requires_exact(const std::string& category) const = 0;
  /// A session for program->objects[object_index], or nullptr with `why_not` set when this
  /// evaluator does not handle the program: its points count as unsupported and run_points
  /// reports a kDeclinedCase mismatch, which fails a test unless the test expects it.
  virtual std::unique_ptr<EvaluationSession> start(std::shared_ptr<const ast::Program> program,
    int object_index,
    std::string& why_not) const = 0;
};

/// The reference interpreter as a CaseEvaluator: exact everywhere.
class InterpreterEvaluator final : public CaseEvaluator
{
public:
  std::string name() const override { return "interpreter"; }
  bool requires_exact(const std::string&) const override { return true; }
  std::unique_ptr<EvaluationSession> start(std::shared_ptr<const ast::Program> program,
    int object_index,
    std::string& why_not) const override;
};

/// The compiled tapes as a CaseEvaluator: Model::compile, a tape per a[] vector
/// (Model::tape(a)), PointEvaluator. Exact everywhere. Tapes evaluate every point from a fresh
/// state (Documentation/compatibility.md): a[] comes back as given and s[] starts at 0, so cases
/// that rely on hfp's persistence between points differ by design (known exceptions). A run-time
/// error is the tape's own error entry (message and position), never the interpreter's.
class CompiledEvaluator final : public CaseEvaluator
{
public:
  std::string name() const override { return "compiled"; }
  bool requires_exact(const std::string&) const override { return true; }
  std::unique_ptr<EvaluationSession> start(std::shared_ptr<const ast::Program> program,
    int object_index,
    std::string& why_not) const override;
};

/// Mismatch::point when the evaluator declined the whole case (CaseEvaluator::start returned
/// null, e.g. the model did not compile): a failure unless the test names it as expected.
constexpr int kDeclinedCase = -2;

/// One difference from the original.
struct Mismatch
{
  std::string case_id;
  int point = -1; ///< index in ConformanceCase::points; -1 for the parse check; kDeclinedCase
  std::string what;
};

/// Counts for a summary row.
struct Tally
{
  int cases = 0;
  int points = 0;
  int exact = 0;          ///< value points bit-exact (value, s[], a[])
  int close = 0;          ///< not exact but within 1e-12
  int wrong = 0;          ///< value points off (or an error where a value was expected)
  int errors = 0;         ///< error/abort points expected
  int errors_matched = 0; ///< ... reproduced with message, line and column
  int unsupported = 0;    ///< points of cases the evaluator declined (each also a mismatch)
  // Parse checks (evaluator independent).
  int parse_cases = 0;
  int parse_outcome_ok = 0; ///< ok/none/error and, for errors, the line agree
  int parse_column_ok = 0;  ///< ... and the column (errors only; ok/none count as agreeing)
  int parse_message_ok = 0; ///< ... and the message (errors only)

  Tally& operator+=(const Tally& other);
};

struct CaseRun
{
  Tally tally;
  std::vector<Mismatch> mismatches; ///< every difference from the original
};

/// Parses the case's program exactly as the original would (CR rejected).
ParseResult parse_case(const ConformanceCase& c);

/// Checks the parse outcome: ok/none/error, the selected object and its sizes, and for an error
/// the line, column and message of our first diagnostic (which may append " (found ...)" to the
/// original's text). The tally separates outcome+line, column and message agreement.
CaseRun check_parse(const ConformanceCase& c, const ParseResult& parsed);

/// Evaluates every point of a case that parsed as expected and compares the results.
CaseRun run_points(const ConformanceCase& c,
  const ParseResult& parsed,
  const CaseEvaluator& evaluator);

/// Exact double equality as the suite means it: bit-identical, except that any two NaNs match.
bool same_double(double expected, double actual);
/// Within 1e-12 relative (absolute when |expected| < 1).
bool close_double(double expected, double actual);

/// "%.17g" with nan/inf spelled as in the suite.
std::string format_double(double v);

/// Tables of tallies by category, with a total row: evaluation (exact / within 1e-12 / wrong /
/// errors reproduced / unsupported) and parsing (outcome+line / column / message agreeing).
std::string format_eval_summary(const std::string& title, const std::map<std::string, Tally>& rows);
std::string format_parse_summary(const std::string& title,
  const std::map<std::string, Tally>& rows);

} // namespace frep::conformance
