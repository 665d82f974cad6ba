#include "conformance_case.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace frep::conformance
{
namespace fs = std::filesystem;

namespace
{

std::string read_bytes(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw std::runtime_error("cannot read " + path.string());
  }
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

std::vector<std::string> split_words(const std::string& line)
{
  std::vector<std::string> words;
  std::istringstream in(line);
  std::string word;
  while (in >> word)
  {
    words.push_back(word);
  }
  return words;
}

std::vector<std::string> split_lines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    lines.push_back(line);
  }
  return lines;
}

[[noreturn]] void malformed(const fs::path& path, int line, const std::string& what)
{
  throw std::runtime_error(path.string() + ":" + std::to_string(line) + ": " + what);
}

int parse_int(const std::string& text, const fs::path& path, int line)
{
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (end == text.c_str() || *end != '\0' || errno != 0)
  {
    malformed(path, line, "not an integer: " + text);
  }
  return static_cast<int>(v);
}

std::string join_from(const std::vector<std::string>& words, std::size_t first)
{
  std::string out;
  for (std::size_t i = first; i < words.size(); ++i)
  {
    if (!out.empty())
    {
      out += ' ';
    }
    out += words[i];
  }
  return out;
}

/// Numbers of `words` from `i` up to (not including) the word `stop` (or the end).
std::vector<double> take_numbers(const std::vector<std::string>& words,
  std::size_t& i,
  const std::string& stop)
{
  std::vector<double> out;
  while (i < words.size() && words[i] != stop)
  {
    out.push_back(parse_number(words[i]));
    ++i;
  }
  return out;
}

ExpectedResult parse_result(const std::vector<std::string>& words,
  std::size_t i,
  const fs::path& path,
  int line)
{
  ExpectedResult r;
  if (i >= words.size())
  {
    malformed(path, line, "missing result");
  }
  const std::string& kind = words[i++];
  if (kind == "value")
  {
    r.kind = ResultKind::Value;
    if (i >= words.size())
    {
      malformed(path, line, "missing value");
    }
    r.value = parse_number(words[i++]);
    if (i >= words.size() || words[i] != "s")
    {
      malformed(path, line, "missing s");
    }
    ++i;
    r.s = take_numbers(words, i, "a");
    if (i < words.size())
    {
      ++i; // "a"
      r.a = take_numbers(words, i, "");
    }
  }
  else if (kind == "error")
  {
    r.kind = ResultKind::Error;
    if (i + 2 > words.size())
    {
      malformed(path, line, "short error record");
    }
    r.line = parse_int(words[i], path, line);
    r.column = parse_int(words[i + 1], path, line);
    r.message = join_from(words, i + 2);
  }
  else if (kind == "abort")
  {
    r.kind = ResultKind::Abort;
    r.message = join_from(words, i);
  }
  else
  {
    malformed(path, line, "unknown result kind " + kind);
  }
  return r;
}

std::string lower(std::string text)
{
  std::transform(text.begin(),
    text.end(),
    text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

} // namespace

double parse_number(const std::string& text)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0')
  {
    throw std::runtime_error("not a number: '" + text + "'");
  }
  return v;
}

ConformanceCase load_case(const std::string& category,
  const fs::path& hf_path,
  const fs::path& expected_path)
{
  ConformanceCase c;
  c.category = category;
  c.name = hf_path.stem().string();
  c.program_path = hf_path;
  c.expected_path = expected_path;
  c.source = read_bytes(hf_path);
  bool have_object = false, have_mode = false, have_parse = false;
  int line_no = 0;
  for (const std::string& line : split_lines(read_bytes(expected_path)))
  {
    ++line_no;
    if (line.empty() || line[0] == '#')
    {
      continue;
    }
    const std::vector<std::string> words = split_words(line);
    if (words.empty())
    {
      continue;
    }
    if (words[0] == "object" && words.size() == 2)
    {
      c.object = words[1];
      have_object = true;
    }
    else if (words[0] == "mode" && words.size() == 2)
    {
      if (words[1] != "fresh" && words[1] != "sequence")
      {
        malformed(expected_path, line_no, "unknown mode");
      }
      c.mode = words[1] == "fresh" ? Mode::Fresh : Mode::Sequence;
      have_mode = true;
    }
    else if (words[0] == "parse" && words.size() >= 2)
    {
      have_parse = true;
      if (words[1] == "ok" && words.size() == 6)
      {
        c.parse.outcome = ParseOutcome::Ok;
        c.parse.selected = words[2];
        c.parse.x_dim = parse_int(words[3], expected_path, line_no);
        c.parse.a_dim = parse_int(words[4], expected_path, line_no);
        c.parse.s_dim = parse_int(words[5], expected_path, line_no);
      }
      else if (words[1] == "error" && words.size() >= 5)
      {
        c.parse.outcome = ParseOutcome::Error;
        c.parse.line = parse_int(words[2], expected_path, line_no);
        c.parse.column = parse_int(words[3], expected_path, line_no);
        c.parse.message = join_from(words, 4);
      }
      else if (words[1] == "none" && words.size() == 2)
      {
        c.parse.outcome = ParseOutcome::None;
      }
      else
      {
        malformed(expected_path, line_no, "bad parse record");
      }
    }
    else if (words[0] == "eval")
    {
      if (!have_parse || c.parse.outcome != ParseOutcome::Ok)
      {
        malformed(expected_path, line_no, "eval without parse ok");
      }
      CasePoint p;
      p.file_line = line_no;
      std::size_t i = 1;
      if (i >= words.size() || words[i] != "x")
      {
        malformed(expected_path, line_no, "eval without x");
      }
      ++i;
      p.x = take_numbers(words, i, "a");
      if (i >= words.size())
      {
        malformed(expected_path, line_no, "eval without a");
      }
      ++i;
      p.a = take_numbers(words, i, "=>");
      if (i >= words.size())
      {
        malformed(expected_path, line_no, "eval without =>");
      }
      ++i;
      p.expected = parse_result(words, i, expected_path, line_no);
      if (static_cast<int>(p.x.size()) != c.parse.x_dim ||
          static_cast<int>(p.a.size()) != c.parse.a_dim)
      {
        malformed(expected_path, line_no, "x/a count differs from the parse record");
      }
      c.points.push_back(std::move(p));
    }
    else
    {
      malformed(expected_path, line_no, "unknown record: " + line);
    }
  }
  if (!have_object || !have_mode || !have_parse)
  {
    malformed(expected_path, line_no, "missing object, mode or parse record");
  }
  return c;
}

std::vector<ConformanceCase> load_conformance_suite(const fs::path& conformance_dir)
{
  std::vector<ConformanceCase> cases;
  for (const fs::directory_entry& dir : fs::directory_iterator(conformance_dir))
  {
    if (!dir.is_directory())
    {
      continue;
    }
    const std::string category = dir.path().filename().string();
    for (const fs::directory_entry& file : fs::directory_iterator(dir.path()))
    {
      if (file.path().extension() != ".hf")
      {
        continue;
      }
      fs::path expected = file.path();
      expected.replace_extension(".expected");
      if (!fs::exists(expected))
      {
        throw std::runtime_error("no .expected for " + file.path().string());
      }
      cases.push_back(load_case(category, file.path(), expected));
    }
  }
  std::sort(cases.begin(),
    cases.end(),
    [](const ConformanceCase& a, const ConformanceCase& b) { return a.id() < b.id(); });
  return cases;
}

std::vector<ConformanceCase> load_model_cases(const fs::path& models_dir)
{
  static const std::regex object_rule(
    R"(([A-Za-z0-9_.-]+)\.expected\.txt holds the values of object ([A-Za-z_][A-Za-z0-9_]*))");
  std::vector<ConformanceCase> cases;
  for (const fs::directory_entry& dir : fs::directory_iterator(models_dir))
  {
    if (!dir.is_directory())
    {
      continue;
    }
    std::string sources;
    if (fs::exists(dir.path() / "SOURCES.txt"))
    {
      sources = read_bytes(dir.path() / "SOURCES.txt");
    }
    for (const fs::directory_entry& file : fs::directory_iterator(dir.path()))
    {
      const std::string file_name = file.path().filename().string();
      const std::string suffix = ".expected.txt";
      if (file_name.size() <= suffix.size() ||
          file_name.compare(file_name.size() - suffix.size(), suffix.size(), suffix) != 0)
      {
        continue;
      }
      const std::string stem = file_name.substr(0, file_name.size() - suffix.size());
      ConformanceCase c;
      c.category = "models";
      c.name = dir.path().filename().string() + "/" + stem;
      c.program_path = dir.path() / (stem + ".hf");
      c.expected_path = file.path();
      c.source = read_bytes(c.program_path);
      // hfp compares -o with the lower-cased stored names: SOURCES.txt gives the object as
      // written in the program, the selection uses its lower-case form.
      for (std::sregex_iterator it(sources.begin(), sources.end(), object_rule), end; it != end;
           ++it)
      {
        if ((*it)[1] == stem)
        {
          c.object = lower((*it)[2]);
        }
      }
      c.parse.outcome = ParseOutcome::Ok; // selected name and sizes not recorded
      int line_no = 0;
      for (const std::string& line : split_lines(read_bytes(file.path())))
      {
        ++line_no;
        const std::vector<std::string> words = split_words(line);
        if (words.empty() || words[0][0] == '#')
        {
          continue;
        }
        if (words.size() != 4)
        {
          malformed(file.path(), line_no, "expected 'x1 x2 x3 value'");
        }
        CasePoint p;
        p.file_line = line_no;
        for (int k = 0; k < 3; ++k)
        {
          p.x.push_back(parse_number(words[k]));
        }
        if (words[3] == "error")
        {
          p.expected.kind = ResultKind::AnyError;
        }
        else
        {
          p.expected.kind = ResultKind::Value;
          p.expected.value = parse_number(words[3]);
        }
        c.points.push_back(std::move(p));
      }
      cases.push_back(std::move(c));
    }
  }
  std::sort(cases.begin(),
    cases.end(),
    [](const ConformanceCase& a, const ConformanceCase& b) { return a.id() < b.id(); });
  return cases;
}

} // namespace frep::conformance
