#include "test_support.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

namespace frep::test
{

std::filesystem::path conformance_dir()
{
  if (const char* env = std::getenv("FREPKIT_SHARED_DIR"))
  {
    return std::filesystem::path(env) / "hyperfun" / "conformance";
  }
  return std::filesystem::path(FREPKIT_SHARED_DIR) / "hyperfun" / "conformance";
}

std::string read_file(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::vector<ConformanceCase> conformance_cases()
{
  const std::filesystem::path root = conformance_dir();
  std::istringstream index(read_file(root / "INDEX.tsv"));
  std::vector<ConformanceCase> cases;
  std::string line;
  bool header = true;
  while (std::getline(index, line))
  {
    if (header)
    {
      header = false;
      continue;
    }
    const std::size_t tab1 = line.find('\t');
    const std::size_t tab2 = tab1 == std::string::npos ? tab1 : line.find('\t', tab1 + 1);
    if (tab2 == std::string::npos)
    {
      continue;
    }
    ConformanceCase c;
    c.category = line.substr(0, tab1);
    c.name = line.substr(tab1 + 1, tab2 - tab1 - 1);
    c.hf = root / c.category / (c.name + ".hf");
    c.expected = root / c.category / (c.name + ".expected");
    cases.push_back(std::move(c));
  }
  return cases;
}

} // namespace frep::test
