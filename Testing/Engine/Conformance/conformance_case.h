// Loading the conformance material: the cases of hyperfun/conformance (<category>/<case>.hf +
// .expected, format in its README) and the external models of hyperfun/models (<name>.hf +
// <name>.expected.txt grid files, object named in SOURCES.txt). Both become ConformanceCases, so
// one runner checks every evaluator against both.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace frep::conformance
{

enum class Mode
{
  Fresh,   ///< every point from a fresh state (a[] set, s[] zeroed)
  Sequence ///< one evaluator for all points, a[] set once, a[]/s[] persist (hfp's behaviour)
};

enum class ParseOutcome
{
  Ok,
  Error,
  None ///< parsed, but the file holds no object
};

struct ParseExpectation
{
  ParseOutcome outcome = ParseOutcome::Ok;
  std::string selected; ///< Ok: lower-case name of the object chosen ("" = not recorded)
  int x_dim = -1, a_dim = -1, s_dim = -1; ///< Ok: sizes (-1 = not recorded)
  int line = 0, column = 0;               ///< Error
  std::string message;                    ///< Error
};

enum class ResultKind
{
  Value,   ///< value (and s[], and a[] in sequence mode)
  Error,   ///< run-time error with line, column, message
  Abort,   ///< library error(): message
  AnyError ///< models: "error" without details
};

struct ExpectedResult
{
  ResultKind kind = ResultKind::Value;
  double value = 0;
  std::vector<double> s;                ///< empty when not recorded (models)
  std::optional<std::vector<double>> a; ///< sequence mode: a[] after the evaluation
  int line = 0, column = 0;
  std::string message;
};

struct CasePoint
{
  std::vector<double> x;
  std::vector<double> a;
  ExpectedResult expected;
  int file_line = 0; ///< line in the expected file, for messages
};

struct ConformanceCase
{
  std::string category; ///< conformance folder, or "models"
  std::string name;     ///< case base name (models: "<folder>/<stem>")
  std::filesystem::path program_path;
  std::filesystem::path expected_path;
  std::string source; ///< exact bytes of the program
  std::string object = "my_model";
  Mode mode = Mode::Fresh;
  ParseExpectation parse;
  std::vector<CasePoint> points;

  std::string id() const { return category + "/" + name; }
};

/// Reads one conformance case. Throws std::runtime_error on a malformed file.
ConformanceCase load_case(const std::string& category,
  const std::filesystem::path& hf_path,
  const std::filesystem::path& expected_path);

/// Every case under `conformance_dir` (one folder per category), sorted by id.
std::vector<ConformanceCase> load_conformance_suite(const std::filesystem::path& conformance_dir);

/// Every <folder>/<stem>.expected.txt under `models_dir` with its <stem>.hf, as category
/// "models": a[] all zeros, grid lines "x1 x2 x3 value|error", object from SOURCES.txt
/// ("<stem>.expected.txt holds the values of object NAME"), else my_model.
std::vector<ConformanceCase> load_model_cases(const std::filesystem::path& models_dir);

/// Strict decimal parsing as the suite writes numbers (strtod: "nan", "inf", "-0").
double parse_number(const std::string& text);

} // namespace frep::conformance
